#include "amTetGenParts.h"

#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amTetraGeometry.h"
#include "amTetraRegions.h"
#include "amTriangleLocator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>

namespace
{
using Vec = amTetraGeometry::Vec;
using G = amTetraGeometry;

/// Per label: its boundary's triangles and edge lengths, and its volume (from the triangles'
/// signed volumes: the normal points out of Labels[0] into Labels[1]).
struct LabelFigures
{
  double Triangles = 0, EdgeLength = 0, Volume = 0;
};

std::map<int, LabelFigures> Figures(const amSurfaceMesh& mesh, int background)
{
  std::map<int, LabelFigures> figures;
  for (vtkIdType t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const auto& tri = mesh.Triangles[t];
    const double* a = mesh.Points[tri[0]].data();
    const double* b = mesh.Points[tri[1]].data();
    const double* c = mesh.Points[tri[2]].data();
    const double volume =
      G::Dot(Vec{ a[0], a[1], a[2] }, G::Cross(Vec{ b[0], b[1], b[2] }, Vec{ c[0], c[1], c[2] })) / 6;
    const double edges = G::Norm(G::Sub(b, a)) + G::Norm(G::Sub(c, b)) + G::Norm(G::Sub(a, c));
    for (int side = 0; side < 2; ++side)
    {
      const int label = mesh.Labels[t][side];
      if (label == background)
        continue;
      LabelFigures& f = figures[label];
      f.Triangles += 1;
      f.EdgeLength += edges / 3;
      f.Volume += side == 0 ? volume : -volume;
    }
  }
  return figures;
}

struct Find
{
  std::vector<size_t> Parent;
  explicit Find(size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  size_t Root(size_t i)
  {
    while (this->Parent[i] != i)
      i = this->Parent[i] = this->Parent[this->Parent[i]];
    return i;
  }
  void Join(size_t a, size_t b)
  {
    a = this->Root(a);
    b = this->Root(b);
    if (a != b)
      this->Parent[std::max(a, b)] = std::min(a, b);
  }
};

/// One group's surface: the triangles with a region of the group on a side (the other groups'
/// labels made the background), its points numbered in the whole surface's order, and a hole
/// point in each part of the other groups' regions it bounds.
struct Part
{
  amSurfaceMesh Mesh;
  std::vector<vtkIdType> Triangle; // part triangle -> the surface's
  std::vector<vtkIdType> Point;    // part point -> the surface's
  std::vector<std::array<double, 3>> Holes;
};

/// The point a hundredth of the inradius off triangle t's centroid, on its 'side' (1: along its
/// normal), when t is the surface's triangle nearest to it: then no other triangle lies between
/// them, and the point is in the region on that side of t.
bool ClearHolePoint(const amSurfaceMesh& mesh, const amTriangleLocator& locator, vtkIdType t, int side, double inradius,
  std::array<double, 3>& hole)
{
  const auto& tri = mesh.Triangles[t];
  const double* a = mesh.Points[tri[0]].data();
  const double* b = mesh.Points[tri[1]].data();
  const double* d = mesh.Points[tri[2]].data();
  const Vec n = G::Cross(G::Sub(b, a), G::Sub(d, a));
  const double step = (side == 1 ? 0.01 : -0.01) * inradius / G::Norm(n);
  for (int k = 0; k < 3; ++k)
    hole[k] = (a[k] + b[k] + d[k]) / 3 + step * n[k];
  double closest[3];
  vtkIdType nearest = -1;
  locator.ClosestPoint(hole.data(), closest, nearest);
  return nearest == t;
}

void MakePart(const amSurfaceMesh& mesh, const amTriangleLocator& locator, const std::vector<int>& labels,
  int background, Part& part)
{
  auto inGroup = [&labels](int label) { return std::binary_search(labels.begin(), labels.end(), label); };
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  std::vector<vtkIdType> local(static_cast<size_t>(np), -1);
  for (vtkIdType t = 0; t < nt; ++t)
    if (inGroup(mesh.Labels[t][0]) || inGroup(mesh.Labels[t][1]))
    {
      part.Triangle.push_back(t);
      for (vtkIdType v : mesh.Triangles[t])
        local[v] = 0;
    }
  for (vtkIdType v = 0; v < np; ++v)
    if (local[v] == 0)
    {
      local[v] = static_cast<vtkIdType>(part.Point.size());
      part.Point.push_back(v);
      part.Mesh.Points.push_back(mesh.Points[v]);
    }
  // The hole candidates: triangles with another group's region (not the background) on one
  // side; those of one label joined through their edges, one hole point for each such patch.
  struct Side
  {
    uint64_t Edge;
    int Label;
    size_t Candidate;
    bool operator<(const Side& o) const
    {
      return std::tie(this->Edge, this->Label, this->Candidate) < std::tie(o.Edge, o.Label, o.Candidate);
    }
  };
  std::vector<std::pair<vtkIdType, int>> candidates; // triangle, side of the other group
  std::vector<Side> sides;
  for (vtkIdType t : part.Triangle)
  {
    const auto& tri = mesh.Triangles[t];
    std::array<int, 2> l = mesh.Labels[t];
    part.Mesh.Triangles.push_back({ local[tri[0]], local[tri[1]], local[tri[2]] });
    for (int s = 0; s < 2; ++s)
      if (!inGroup(l[s]))
        l[s] = background;
    part.Mesh.Labels.push_back(l);
    for (int s = 0; s < 2; ++s)
      if (!inGroup(mesh.Labels[t][s]) && mesh.Labels[t][s] != background)
      {
        for (int k = 0; k < 3; ++k)
        {
          const uint64_t a = static_cast<uint64_t>(std::min(tri[k], tri[(k + 1) % 3])),
                         b = static_cast<uint64_t>(std::max(tri[k], tri[(k + 1) % 3]));
          sides.push_back({ (a << 32) | b, mesh.Labels[t][s], candidates.size() });
        }
        candidates.emplace_back(t, s);
      }
  }
  std::sort(sides.begin(), sides.end());
  Find patches(candidates.size());
  for (size_t i = 1; i < sides.size(); ++i)
    if (sides[i].Edge == sides[i - 1].Edge && sides[i].Label == sides[i - 1].Label)
      patches.Join(sides[i].Candidate, sides[i - 1].Candidate);
  // Each patch's hole point: off the centroid of its roundest triangle, into the other group's
  // region, by a hundredth of its inradius, where that triangle is the surface's nearest to the
  // point. Where two interfaces nearly touch (a layer of the other region thinner than the
  // offset), the point could lie beyond the next triangle, in a region of this group, whose
  // tetrahedra TetGen would then carve away: the next roundest is tried. A patch without such a
  // triangle gets no hole: TetGen meshes that region too, and its tetrahedra, of the background
  // here, are left out when merging.
  std::map<size_t, std::vector<std::pair<double, size_t>>> byPatch; // patch -> (inradius, candidate)
  for (size_t c = 0; c < candidates.size(); ++c)
  {
    const auto& tri = mesh.Triangles[candidates[c].first];
    const double* a = mesh.Points[tri[0]].data();
    const double* b = mesh.Points[tri[1]].data();
    const double* d = mesh.Points[tri[2]].data();
    const double area2 = G::Norm(G::Cross(G::Sub(b, a), G::Sub(d, a)));
    const double perimeter = G::Norm(G::Sub(b, a)) + G::Norm(G::Sub(d, b)) + G::Norm(G::Sub(a, d));
    const double inradius = perimeter > 0 ? area2 / perimeter : 0;
    if (inradius > 0)
      byPatch[patches.Root(c)].push_back({ inradius, c });
  }
  for (auto& [patch, list] : byPatch)
  {
    // Roundest first; among equals, the first candidate (the order of the triangles).
    std::sort(list.begin(), list.end(), [](const std::pair<double, size_t>& x, const std::pair<double, size_t>& y) {
      return x.first > y.first || (x.first == y.first && x.second < y.second);
    });
    for (const auto& [inradius, c] : list)
    {
      const auto& [t, side] = candidates[c];
      std::array<double, 3> hole;
      if (ClearHolePoint(mesh, locator, t, side, inradius, hole))
      {
        part.Holes.push_back(hole);
        break;
      }
    }
  }
}

/// The groups' results as one run's: false when a group's tetrahedra do not fill its regions.
bool Merge(const amSurfaceMesh& mesh, int background, const std::vector<Part>& parts,
  const std::vector<amTetGenRun::Result>& results, const std::map<int, LabelFigures>& figures,
  amTetGenRun::Result& merged)
{
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  merged = amTetGenRun::Result();
  merged.Points.resize(3 * static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
    std::copy(mesh.Points[v].begin(), mesh.Points[v].end(), &merged.Points[3 * v]);
  std::vector<std::array<int, 3>> face(static_cast<size_t>(nt), { -1, -1, -1 });
  std::map<int, double> volume;
  double total = 0;
  for (size_t g = 0; g < parts.size(); ++g)
  {
    const Part& part = parts[g];
    const amTetGenRun::Result& out = results[g];
    amTetraRegions regions;
    std::string why;
    if (!regions.Assign(part.Mesh, out, background, why))
      return false;
    const vtkIdType localPoints = part.Mesh.NumberOfPoints();
    // The part's points first and unchanged, as TetGen keeps its input's: TetGen drops those a
    // hole carved every tetrahedron away from, and then the group is not trusted.
    if (out.NumberOfPoints < localPoints)
      return false;
    for (vtkIdType v = 0; v < localPoints; ++v)
      for (int d = 0; d < 3; ++d)
        if (out.Points[3 * v + d] != part.Mesh.Points[v][d])
          return false;
    // Points: the part's surface points are the surface's; its Steiner points used by its
    // regions' tetrahedra come next, in its order.
    std::vector<int> point(static_cast<size_t>(out.NumberOfPoints), -1);
    for (vtkIdType v = 0; v < localPoints; ++v)
      point[v] = static_cast<int>(part.Point[v]);
    std::vector<int> tet(static_cast<size_t>(out.NumberOfTetrahedra), -1);
    const int firstTet = static_cast<int>(merged.Tetrahedra.size() / 4);
    int kept = 0;
    for (vtkIdType t = 0; t < out.NumberOfTetrahedra; ++t)
      if (regions.Label[t] != background)
        tet[t] = firstTet + kept++;
    std::vector<char> used(static_cast<size_t>(out.NumberOfPoints), 0);
    for (vtkIdType t = 0; t < out.NumberOfTetrahedra; ++t)
      if (tet[t] >= 0)
        for (int k = 0; k < 4; ++k)
          used[out.Tetrahedra[4 * t + k]] = 1;
    for (vtkIdType v = localPoints; v < out.NumberOfPoints; ++v)
      if (used[v])
      {
        point[v] = static_cast<int>(merged.Points.size() / 3);
        merged.Points.insert(merged.Points.end(), &out.Points[3 * v], &out.Points[3 * v] + 3);
      }
    for (vtkIdType t = 0; t < out.NumberOfTetrahedra; ++t)
    {
      if (tet[t] < 0)
        continue;
      const double* x[4];
      for (int k = 0; k < 4; ++k)
      {
        merged.Tetrahedra.push_back(point[out.Tetrahedra[4 * t + k]]);
        const int n = out.Neighbors[4 * t + k];
        merged.Neighbors.push_back(n >= 0 ? tet[n] : -1);
        x[k] = &out.Points[3 * out.Tetrahedra[4 * t + k]];
      }
      const double v = std::fabs(G::SignedVolume(x[0], x[1], x[2], x[3]));
      volume[regions.Label[t]] += v;
      total += v;
    }
    for (vtkIdType s = 0; s < out.NumberOfFaces; ++s)
    {
      const vtkIdType source = part.Triangle[amTetraRegions::SourceOf(out, s)];
      if (face[source][0] < 0)
        for (int k = 0; k < 3; ++k)
          face[source][k] = point[out.Faces[3 * s + k]];
    }
  }
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (face[t][0] < 0)
      return false; // a triangle no group kept as a face
    merged.Faces.insert(merged.Faces.end(), face[t].begin(), face[t].end());
    merged.FaceMarkers.push_back(static_cast<int>(t + 1));
  }
  // Each region filled, as the surface encloses it (to rounding).
  for (const auto& [label, f] : figures)
  {
    const auto it = volume.find(label);
    if (it == volume.end() || std::fabs(it->second - f.Volume) > 1e-6 * std::max(total, std::fabs(f.Volume)))
      return false;
  }
  merged.NumberOfPoints = static_cast<vtkIdType>(merged.Points.size() / 3);
  merged.NumberOfTetrahedra = static_cast<vtkIdType>(merged.Tetrahedra.size() / 4);
  merged.NumberOfFaces = nt;
  return true;
}

/// The labels in two groups by their figures (see amTetGenParts::Groups).
std::vector<std::vector<int>> GroupsOf(const std::map<int, LabelFigures>& figures)
{
  // Expected work: the boundary's triangles, and the volume in tetrahedra of the boundary's mean
  // edge length (interiors grade to larger ones). The largest first into the lighter group.
  std::vector<std::pair<double, int>> work;
  for (const auto& [label, f] : figures)
  {
    const double h = f.Triangles > 0 ? f.EdgeLength / f.Triangles : 0;
    work.emplace_back(f.Triangles + (h > 0 ? std::fabs(f.Volume) / (4 * h * h * h) : 0), label);
  }
  std::sort(work.begin(), work.end(),
    [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  std::vector<std::vector<int>> groups(std::min<size_t>(2, work.size()));
  std::vector<double> load(groups.size(), 0);
  for (const auto& [w, label] : work)
  {
    const size_t g = static_cast<size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    groups[g].push_back(label);
    load[g] += w;
  }
  for (auto& g : groups)
    std::sort(g.begin(), g.end());
  return groups;
}
}

std::vector<std::vector<int>> amTetGenParts::Groups(const amSurfaceMesh& mesh, int background)
{
  return GroupsOf(Figures(mesh, background));
}

std::string amTetGenParts::Run(const amSurfaceMesh& mesh, const amGradedSizeField& field, const std::string& switches,
  int background, bool preserved, amTetGenRun::Result& result, int* groups)
{
  if (groups)
    *groups = 1;
  const std::map<int, LabelFigures> figures =
    preserved && !mesh.Labels.empty() ? Figures(mesh, background) : std::map<int, LabelFigures>();
  const std::vector<std::vector<int>> labels = GroupsOf(figures);
  if (labels.size() >= 2)
  {
    std::vector<Part> parts(labels.size());
    std::vector<amTetGenRun::Input> inputs;
    amTriangleLocator locator;
    locator.Build(mesh.Points, mesh.Triangles);
    for (size_t g = 0; g < labels.size(); ++g)
    {
      MakePart(mesh, locator, labels[g], background, parts[g]);
      inputs.push_back({ &parts[g].Mesh, parts[g].Holes });
    }
    std::vector<amTetGenRun::Result> results;
    // A group's run sees only its own triangles: a triangle of one group crossing one of the
    // other (which one run refuses) is looked for while the groups are meshed.
    bool crossing = false;
    const std::vector<std::string> failures = amTetGenRun::RunEach(inputs, field, switches, results,
      [&]() { crossing = !amSelfIntersection::AllTriangles(mesh, mesh.Points).empty(); });
    const bool ran = std::all_of(failures.begin(), failures.end(), [](const std::string& f) { return f.empty(); });
    if (ran && !crossing && Merge(mesh, background, parts, results, figures, result))
    {
      if (groups)
        *groups = static_cast<int>(labels.size());
      return "";
    }
    // A group TetGen refused or did not fill, or a crossing: the whole surface in one run says
    // what is wrong, or meshes it.
  }
  return amTetGenRun::Run(mesh, field, switches, result);
}
