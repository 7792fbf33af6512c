#include "amTetraMeshOptimizer.h"

#include "amMeshQuality.h"
#include "amTetraFaces.h"
#include "amTetraImproveMesh.h"
#include "amTetraInterfaceUpdate.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

using namespace amTetraImprove;

amTetraMeshOptimizer::Report amTetraMeshOptimizer::Optimize(std::vector<double>& points,
  std::vector<std::array<int, 4>>& tets, std::vector<int>& regions, const std::vector<std::array<int, 3>>& fixedFaces,
  const Options& options, const std::function<void(double)>& progress)
{
  Report report;
  Mesh m(points);
  m.Inc.resize(points.size() / 3);
  m.FixedVertex.assign(points.size() / 3, 0);
  m.Dirty.assign(points.size() / 3, 1);
  m.T.reserve(tets.size() * 2);
  // The objectives on the threads, the rest in order.
  std::vector<double> q(tets.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(tets.size()), [&](vtkIdType t0, vtkIdType t1) {
    for (vtkIdType t = t0; t < t1; ++t)
      q[t] = m.Quality(tets[t][0], tets[t][1], tets[t][2], tets[t][3]);
  });
  for (size_t t = 0; t < tets.size(); ++t)
    m.Add(tets[t], regions[t], q[t]);
  auto statistics = [&](double& worst, double& mean) {
    // Each element's Q on the threads; the worst and the sum in order (the same sum whatever the
    // thread count).
    q.assign(m.T.size(), -1.0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(m.T.size()), [&](vtkIdType t0, vtkIdType t1) {
      for (vtkIdType t = t0; t < t1; ++t)
        if (m.Alive[t])
        {
          double minDihedral, maxDihedral, radiusRatio, volume;
          amMeshQuality::TetraQuality(m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]), q[t], minDihedral,
            maxDihedral, radiusRatio, volume);
        }
    });
    worst = 0;
    double sum = 0;
    size_t n = 0;
    for (size_t t = 0; t < m.T.size(); ++t)
      if (m.Alive[t])
      {
        worst = std::max(worst, q[t]);
        sum += q[t];
        ++n;
      }
    mean = n ? sum / static_cast<double>(n) : 0;
  };
  statistics(report.WorstBefore, report.MeanBefore);

  // Fixed: the given faces and the mesh's own boundary (faces of one tetrahedron only).
  for (const Tri& f : fixedFaces)
    m.FixedFaces.insert(Sorted(f[0], f[1], f[2]));
  for (const Tri& f : amTetraFaces::Boundary(tets))
    m.FixedFaces.insert(f);
  auto fixEdges = [&m]() { m.FixEdgesOfFixedFaces(); };
  fixEdges();

  const double bad = 1.0 / options.FlipQuality, poor = 1.0 / options.SearchQuality, split = 1.0 / options.SplitQuality;
  const int maxRing = std::min(options.MaxRing, 15);
  const int rounds = options.MaximumSurfaceDeviation > 0 ? std::max(0, options.SliverRounds) : 0;
  auto improve = [&](int round) {
    const int passes = round == 0 ? options.Passes : std::min(options.Passes, 2);
    for (int pass = 0; pass < passes; ++pass)
    {
      long changes = 0;
      // Topology: the bad tetrahedra's edges, then faces.
      changes += TopologyPass(m, bad, split, maxRing, report);
      // Geometry: smoothing of every free vertex, then a local search around the bad elements
      // (in the sliver rounds, only where something changed since the last pass).
      const size_t nv = m.Inc.size();
      const std::vector<char> changed = m.Dirty;
      const long smoothed = SmoothAll(m, nv);
      report.Moves += smoothed;
      changes += smoothed;
      std::vector<char> climb(nv, 0);
      for (size_t t = 0; t < m.T.size(); ++t)
        if (m.Alive[t] && m.Objectives[t] < poor)
          for (int w : m.T[t])
            climb[w] = !m.FixedVertex[w] && (round == 0 || changed[w]);
      for (size_t v = 0; v < nv; ++v)
        if (climb[v] && Climb(m, static_cast<int>(v)))
        {
          ++report.Moves;
          ++changes;
        }
      if (progress)
        progress((round + static_cast<double>(pass + 1) / passes) / (rounds + 1));
      if (changes == 0)
        break;
    }
  };
  if (!options.TargetVolumes.empty() && options.MaximumVolumeOffset > 0)
  {
    // Only what the moves disturb is smoothed between the rounds; the passes then start anew.
    std::fill(m.Dirty.begin(), m.Dirty.end(), 0);
    report.VolumeMoves = PreserveVolumes(m, options.TargetVolumes, options.MaximumVolumeOffset,
      1.0 / options.SearchQuality, options.VolumeRounds, report.VolumeDisplacement);
    std::fill(m.Dirty.begin(), m.Dirty.end(), 1);
  }
  improve(0);
  if (rounds > 0)
  {
    // The sliver rounds improve only around what they change.
    std::fill(m.Dirty.begin(), m.Dirty.end(), 0);
    std::fill(m.Tried.begin(), m.Tried.end(), 1);
    FreeSlivers(m, options, report, improve, fixEdges);
  }
  report.Slivers = CountSlivers(m, options);

  tets.clear();
  regions.clear();
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
    {
      tets.push_back(m.T[t]);
      regions.push_back(m.R[t]);
    }
  statistics(report.WorstAfter, report.MeanAfter);
  return report;
}

bool amTetraMeshOptimizer::ImproveGrid(vtkUnstructuredGrid* grid, vtkPolyData* surface, const Options& options,
  Report& report, std::string& why, const std::function<void(double)>& progress)
{
  vtkPoints* gridPoints = grid->GetPoints();
  vtkDataArray* regionArray = grid->GetCellData()->GetArray("Region");
  vtkDataArray* labels = surface->GetCellData()->GetArray("Labels");
  const vtkIdType np = grid->GetNumberOfPoints(), ne = grid->GetNumberOfCells();
  vtkIdType ns = surface->GetNumberOfCells();
  if (!gridPoints || !regionArray || !labels || labels->GetNumberOfComponents() != 2 ||
    surface->GetPoints() != gridPoints)
  {
    why = "the grid needs a Region array and the surface a 2-component Labels array on the grid's points";
    return false;
  }
  std::vector<double> points(3 * static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
    gridPoints->GetPoint(v, &points[3 * v]);
  std::vector<Tet> tets(static_cast<size_t>(ne));
  std::vector<int> regions(static_cast<size_t>(ne));
  for (vtkIdType c = 0; c < ne; ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    if (n != 4)
    {
      why = "cell " + std::to_string(c) + " is not a tetrahedron";
      return false;
    }
    for (int k = 0; k < 4; ++k)
      tets[c][k] = static_cast<int>(ids[k]);
    if (amTetraGeometry::SignedVolume(
          &points[3 * ids[0]], &points[3 * ids[1]], &points[3 * ids[2]], &points[3 * ids[3]]) < 0)
      std::swap(tets[c][0], tets[c][1]);
    regions[c] = static_cast<int>(regionArray->GetComponent(c, 0));
  }
  std::vector<Tri> fixed(static_cast<size_t>(ns));
  for (vtkIdType s = 0; s < ns; ++s)
  {
    vtkIdType n;
    const vtkIdType* ids;
    surface->GetCellPoints(s, n, ids);
    if (n != 3)
    {
      why = "surface cell " + std::to_string(s) + " is not a triangle";
      return false;
    }
    fixed[s] = { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) };
  }
  const int background = amTetraInterfaceUpdate::Background(surface, regions);
  report = Optimize(points, tets, regions, fixed, options, progress);

  // Back into the grid: moved and new points (-1 in every point array: they lie inside, on no
  // surface), new cells, their regions.
  for (vtkIdType v = 0; v < np; ++v)
    gridPoints->SetPoint(v, &points[3 * v]);
  const vtkIdType nAll = static_cast<vtkIdType>(points.size() / 3);
  for (vtkIdType v = np; v < nAll; ++v)
    gridPoints->InsertNextPoint(&points[3 * v]);
  vtkPointData* pd = grid->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    if (vtkDataArray* array = pd->GetArray(a))
      for (vtkIdType v = np; v < nAll; ++v)
        for (int c = 0; c < array->GetNumberOfComponents(); ++c)
          array->InsertComponent(v, c, -1.0);
  gridPoints->Modified();
  const vtkIdType nt = static_cast<vtkIdType>(tets.size());
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(nt + 1);
  connectivity->SetNumberOfTuples(4 * nt);
  vtkNew<vtkIntArray> region;
  region->SetName(regionArray->GetName());
  region->SetNumberOfTuples(nt);
  for (vtkIdType c = 0; c < nt; ++c)
  {
    offsets->SetValue(c, 4 * c);
    for (int k = 0; k < 4; ++k)
      connectivity->SetValue(4 * c + k, tets[c][k]);
    region->SetValue(c, regions[c]);
  }
  offsets->SetValue(nt, 4 * nt);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(VTK_TETRA, cells);
  grid->GetCellData()->Initialize(); // per-cell data of the old cells no longer applies
  grid->GetCellData()->AddArray(region);
  grid->GetCellData()->SetActiveScalars(region->GetName());

  // Slivers that changed region, or surface edges split or collapsed near them, changed the
  // surface's triangles: they are the mesh's faces anew.
  if (report.Relabels + report.SurfaceSplits + report.SurfaceCollapses > 0)
  {
    fixed = amTetraInterfaceUpdate::Rebuild(surface, points, tets, regions, background);
    ns = static_cast<vtkIdType>(fixed.size());
  }

  // The surface's "Tetra": the tetrahedron on the Labels[0] and on the Labels[1] side of each
  // triangle (the normal points into the Labels[1] side).
  vtkNew<vtkIntArray> adjacent;
  adjacent->SetName("Tetra");
  adjacent->SetNumberOfComponents(2);
  adjacent->SetNumberOfTuples(ns);
  adjacent->Fill(-1);
  std::unordered_map<Tri, int, TriHash> faceOf;
  faceOf.reserve(static_cast<size_t>(ns) * 2);
  std::vector<char> onSurface(points.size() / 3, 0); // a face with another vertex is none of them
  for (vtkIdType s = 0; s < ns; ++s)
  {
    faceOf[Sorted(fixed[s][0], fixed[s][1], fixed[s][2])] = static_cast<int>(s);
    for (int v : fixed[s])
      onSurface[v] = 1;
  }
  for (vtkIdType c = 0; c < nt; ++c)
    for (int i = 0; i < 4; ++i)
    {
      const Tet& t = tets[c];
      if (!onSurface[t[(i + 1) % 4]] || !onSurface[t[(i + 2) % 4]] || !onSurface[t[(i + 3) % 4]])
        continue;
      const auto it = faceOf.find(Sorted(t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4]));
      if (it == faceOf.end())
        continue;
      const Tri& f = fixed[it->second];
      const int side =
        amTetraGeometry::SignedVolume(&points[3 * static_cast<size_t>(f[0])], &points[3 * static_cast<size_t>(f[1])],
          &points[3 * static_cast<size_t>(f[2])], &points[3 * static_cast<size_t>(t[i])]) > 0
        ? 1
        : 0;
      adjacent->SetComponent(it->second, side, static_cast<double>(c));
    }
  surface->GetCellData()->RemoveArray("Tetra");
  surface->GetCellData()->AddArray(adjacent);
  grid->Modified();
  surface->Modified();
  return true;
}
