// Metric remeshing: fewer, better triangles; every region still closed and oriented; labels and
// junctions kept; the Hausdorff bound holds when measured independently.
#include "amAnalyticDistance.h"
#include "amCurvatureMetric.h"
#include "amLabelSurface.h"
#include "amMetricRemeshing.h"
#include "amSurfaceDistance.h"
#include "amSurfaceSmoothing.h"
#include "amSurfaceTestUtilities.h"
#include "amSurfaceTopology.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <set>

namespace
{
/// The phantom at 'spacing' mm through label surface, smoothing, isotropic curvature metric
/// (MinimumSize one voxel) and remeshing at tolerance eps, run.
struct PhantomChain
{
  vtkNew<amThoraxPhantomSource> Source;
  vtkNew<amLabelSurface> Surface;
  vtkNew<amSurfaceSmoothing> Smooth;
  vtkNew<amCurvatureMetric> Metric;
  vtkNew<amMetricRemeshing> Remesh;
  PhantomChain(double spacing, double eps, bool preserveVolumes = true)
  {
    this->Source->SetSpacing(spacing, spacing, spacing);
    this->Surface->SetInputConnection(this->Source->GetOutputPort(1));
    this->Surface->SetComputeTopology(false);
    this->Smooth->SetInputConnection(this->Surface->GetOutputPort());
    this->Metric->SetInputConnection(this->Smooth->GetOutputPort());
    this->Metric->SetTolerance(eps);
    this->Metric->SetMinimumSize(spacing);
    this->Metric->SetAnisotropic(false);
    this->Remesh->SetInputConnection(this->Metric->GetOutputPort());
    this->Remesh->SetTolerance(eps);
    this->Remesh->SetPreserveVolumes(preserveVolumes);
    this->Remesh->Update();
  }
};

void ExpectClosedRegions(vtkPolyData* pd)
{
  std::vector<amSurfaceTopology::Region> regions;
  std::string why;
  ASSERT_TRUE(amSurfaceTopology::Analyse(pd, regions, why)) << why;
  for (const auto& r : regions)
  {
    EXPECT_EQ(r.BoundaryEdges, 0) << r.Label;
    EXPECT_EQ(r.NonManifoldEdges, 0) << r.Label;
    EXPECT_EQ(r.MisorientedEdges, 0) << r.Label;
    EXPECT_EQ(r.NonManifoldVertices, 0) << r.Label;
  }
}
}

TEST(MetricRemeshing, TwoMaterialBallUniformSize)
{
  // A ball of radius 12 voxels split into labels 1 (x < 0) and 2: a junction circle.
  const double origin[3] = { -15.5, -15.5, -15.5 };
  auto img = amTest::LabelMap(32, 32, 32, 1.0, origin,
    [](double x, double y, double z) { return x * x + y * y + z * z < 144 ? (x < 0 ? 1 : 2) : 0; });
  vtkNew<amLabelSurface> ls;
  ls->SetInputData(img);
  vtkNew<amSurfaceSmoothing> sm;
  sm->SetInputConnection(ls->GetOutputPort());
  vtkNew<amMetricRemeshing> rm;
  rm->SetInputConnection(sm->GetOutputPort());
  rm->SetTargetSize(3.0);
  rm->SetTolerance(0.3);
  rm->Update();
  vtkPolyData* out = rm->GetOutput();
  sm->Update();
  const vtkIdType before = sm->GetOutput()->GetNumberOfCells(), after = out->GetNumberOfCells();
  EXPECT_LT(after * 5, before);
  ExpectClosedRegions(out);
  EXPECT_LE(rm->GetHausdorff(), 0.3);
  // Measured independently with denser sampling: within the reported upper bound.
  vtkNew<amSurfaceDistance> d;
  d->SetInputConnection(0, rm->GetOutputPort());
  d->SetInputConnection(1, sm->GetOutputPort());
  d->SetSamplingDistance(0.05);
  d->Update();
  EXPECT_LE(d->GetHausdorff(), rm->GetHausdorffUpperBound() + 1e-9);
  EXPECT_LE(d->GetHausdorff(), 0.3 + 0.05);
  EXPECT_GT(amTest::AngleFraction(out, 20), 0.95);
  // Labels kept: exactly the pairs of the input, and the field data says what was achieved.
  std::set<std::pair<int, int>> pairs;
  vtkDataArray* labels = out->GetCellData()->GetArray("Labels");
  ASSERT_NE(labels, nullptr);
  for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
    pairs.insert({ static_cast<int>(labels->GetComponent(t, 0)), static_cast<int>(labels->GetComponent(t, 1)) });
  EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{ { 1, 0 }, { 2, 0 }, { 2, 1 } }));
  ASSERT_NE(out->GetFieldData()->GetArray("Hausdorff"), nullptr);
  EXPECT_NEAR(out->GetFieldData()->GetArray("Hausdorff")->GetComponent(0, 0), rm->GetHausdorff(), 1e-12);

  // Where the distance is: per triangle, its largest is the Hausdorff distance; per interface,
  // the largest of its triangles; every vertex's independently measured distance is within the
  // largest of its triangles' (a vertex is one of their samples).
  vtkDataArray* local = out->GetCellData()->GetArray("HausdorffDistance");
  ASSERT_NE(local, nullptr);
  std::map<std::pair<int, int>, double> perPair;
  double largest = 0;
  for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
  {
    const double v = local->GetTuple1(t);
    EXPECT_GE(v, 0.0);
    largest = std::max(largest, v);
    const int a = static_cast<int>(labels->GetComponent(t, 0)), b = static_cast<int>(labels->GetComponent(t, 1));
    double& w = perPair[std::minmax(a, b)];
    w = std::max(w, v);
  }
  EXPECT_NEAR(largest, rm->GetHausdorff(), 1e-12);
  vtkDataArray* interfaces = out->GetFieldData()->GetArray("InterfaceHausdorff");
  ASSERT_NE(interfaces, nullptr);
  ASSERT_EQ(interfaces->GetNumberOfComponents(), 3);
  ASSERT_EQ(interfaces->GetNumberOfTuples(), 3);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    const std::pair<int, int> key(
      static_cast<int>(interfaces->GetComponent(i, 0)), static_cast<int>(interfaces->GetComponent(i, 1)));
    ASSERT_EQ(perPair.count(key), 1u) << key.first << "|" << key.second;
    EXPECT_EQ(interfaces->GetComponent(i, 2), perPair[key]);
    EXPECT_GT(perPair[key], 0.0);
  }
  EXPECT_EQ(rm->GetInterfacesAboveTolerance(), 0);
  vtkPolyData* measured = d->GetOutput();
  vtkDataArray* vertexDistance = measured->GetPointData()->GetArray("Distance");
  ASSERT_NE(vertexDistance, nullptr);
  std::vector<double> vertexBound(static_cast<size_t>(out->GetNumberOfPoints()), 0.0);
  auto it = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
      vertexBound[ids[k]] = std::max(vertexBound[ids[k]], local->GetTuple1(it->GetCurrentCellId()));
  }
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
    EXPECT_LE(vertexDistance->GetTuple1(v), vertexBound[v] + 1e-9) << v;
}

TEST(MetricRemeshing, PhantomWithCurvatureMetric)
{
  PhantomChain chain(2, 0.5);
  amMetricRemeshing* rm = chain.Remesh;
  amSurfaceSmoothing* sm = chain.Smooth;
  vtkPolyData* out = rm->GetOutput();
  EXPECT_LT(out->GetNumberOfCells() * 5, sm->GetOutput()->GetNumberOfCells());
  // The bound holds, junction curves included (junction edges split along the input curve).
  EXPECT_LE(rm->GetHausdorff(), 0.5);
  ExpectClosedRegions(out);
  EXPECT_GT(amTest::AngleFraction(out, 20), 0.95);
  // Every region is still there.
  std::vector<amSurfaceTopology::Region> regions;
  std::string why;
  ASSERT_TRUE(amSurfaceTopology::Analyse(out, regions, why));
  EXPECT_EQ(regions.size(), 10u);
  // The per-triangle distances are the output's (the cleanups restore some states): their largest
  // is the Hausdorff distance, and each interface's row is above the tolerance only if the
  // filter counts it.
  vtkDataArray* local = out->GetCellData()->GetArray("HausdorffDistance");
  ASSERT_NE(local, nullptr);
  EXPECT_NEAR(local->GetRange()[1], rm->GetHausdorff(), 1e-12);
  vtkDataArray* interfaces = out->GetFieldData()->GetArray("InterfaceHausdorff");
  ASSERT_NE(interfaces, nullptr);
  int above = 0;
  double largest = 0;
  for (vtkIdType i = 0; i < interfaces->GetNumberOfTuples(); ++i)
  {
    above += interfaces->GetComponent(i, 2) > 0.5;
    largest = std::max(largest, interfaces->GetComponent(i, 2));
  }
  EXPECT_EQ(above, rm->GetInterfacesAboveTolerance());
  EXPECT_NEAR(largest, rm->GetHausdorff(), 1e-12);
  EXPECT_GE(interfaces->GetNumberOfTuples(), 15);

  // Both surfaces stay within about one voxel (2 mm) of the phantom's analytic interfaces: every
  // analytic interface point has the surface within 2 mm; the surface is within 2 mm of its
  // interface except at a few thin places (ribs a voxel or two across, the aorta's cut ends).
  for (vtkPolyData* surface : { sm->GetOutput(), out })
  {
    const amTest::AnalyticDistance d = amTest::DistanceToPhantom(surface);
    std::printf("%s: distance to the analytic phantom: surface -> truth max %.3f mean %.3f mm, %.3f %% within "
                "2 mm; truth -> surface max %.3f mm (%lld interface samples)\n",
      surface == out ? "remeshed" : "smoothed", d.SurfaceToTruth, d.MeanSurfaceToTruth, 100 * d.FractionWithin(2.0),
      d.TruthToSurface, d.TruthSamples);
    EXPECT_GT(d.TruthSamples, 10000);
    EXPECT_LE(d.TruthToSurface, 2.0);
    EXPECT_LT(d.MeanSurfaceToTruth, 0.5);
    EXPECT_GT(d.FractionWithin(2.0), 0.98);
  }
}

TEST(MetricRemeshing, PhantomAtOneMillimetreMeetsTheIssueTargets)
{
  // The issue's case: the whole ten-organ phantom at 1 mm, curvature metric and remeshing at
  // eps = 0.2 mm. Measured: 1.785 M -> 160.7 k triangles (11.1x; 18.6x against
  // vtkDiscreteMarchingCubes, which makes every interface twice), Hausdorff 0.200 per interface,
  // 99.54 % of the triangles with angles >= 20 degrees (9.7x before collapses into the middle of
  // an edge). Before, junction
  // edges split at the curve vertex nearest their midpoint folded a curve back on itself (0.533 mm)
  // and short closed junction loops smoothed into edges of 0.004 mm.
  PhantomChain chain(1, 0.2);
  amMetricRemeshing* rm = chain.Remesh;
  vtkPolyData* out = rm->GetOutput();
  const vtkIdType before = chain.Smooth->GetOutput()->GetNumberOfCells(), after = out->GetNumberOfCells();
  std::printf("1 mm phantom: %lld -> %lld triangles (%.2fx), Hausdorff %.4f, %.2f %% >= 20 degrees\n",
    static_cast<long long>(before), static_cast<long long>(after), static_cast<double>(before) / after,
    rm->GetHausdorff(), 100 * amTest::AngleFraction(out, 20));
  EXPECT_LE(rm->GetHausdorff(), 0.2);
  EXPECT_GE(amTest::AngleFraction(out, 20), 0.99);
  EXPECT_GT(static_cast<double>(before) / after, 10.0);
  double shortest = std::numeric_limits<double>::infinity();
  const vtkIdType* ids;
  vtkIdType n;
  auto cells = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      double a[3], b[3];
      out->GetPoint(ids[k], a);
      out->GetPoint(ids[(k + 1) % n], b);
      shortest = std::min(shortest, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
    }
  }
  EXPECT_GT(shortest, 0.05);
  ExpectClosedRegions(out);
  std::vector<amSurfaceTopology::Region> regions;
  std::string why;
  ASSERT_TRUE(amSurfaceTopology::Analyse(out, regions, why));
  EXPECT_EQ(regions.size(), 10u);
}

namespace
{
/// Each label's enclosed volume (mm^3): Labels[0] is the side a triangle's normal leaves.
std::map<int, double> EnclosedVolumes(vtkPolyData* pd)
{
  std::map<int, double> v;
  vtkDataArray* labels = pd->GetCellData()->GetArray("Labels");
  auto it = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  vtkIdType c = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    double a[3], b[3], d[3];
    pd->GetPoint(ids[0], a);
    pd->GetPoint(ids[1], b);
    pd->GetPoint(ids[2], d);
    double bxd[3];
    vtkMath::Cross(b, d, bxd);
    const double six = vtkMath::Dot(a, bxd);
    v[static_cast<int>(labels->GetComponent(c, 0))] += six / 6.0;
    v[static_cast<int>(labels->GetComponent(c, 1))] -= six / 6.0;
  }
  return v;
}
}

// The chords of a coarser triangulation lie inside a convex part: the 2 mm phantom's ribs (a
// voxel or two across) lose several per cent of their volume in remeshing at 0.5 mm. With
// PreserveVolumes every region keeps its input volume within 0.2 %, the bound
// still holds, and the junction curves stay where they were.
TEST(MetricRemeshing, RegionsKeepTheirInputVolumes)
{
  PhantomChain chain(2, 0.5);
  const std::map<int, double> input = EnclosedVolumes(chain.Smooth->GetOutput());
  const std::map<int, double> kept = EnclosedVolumes(chain.Remesh->GetOutput());
  EXPECT_LE(chain.Remesh->GetHausdorff(), 0.5);
  EXPECT_TRUE(chain.Remesh->GetPreserveVolumes());
  ExpectClosedRegions(chain.Remesh->GetOutput());
  vtkNew<amMetricRemeshing> lossy;
  lossy->SetInputConnection(chain.Metric->GetOutputPort());
  lossy->SetTolerance(0.5);
  lossy->SetPreserveVolumes(false);
  lossy->Update();
  const std::map<int, double> lost = EnclosedVolumes(lossy->GetOutput());
  double worstKept = 0, worstLost = 0;
  for (const auto& kv : input)
  {
    if (kv.first == 0)
      continue;
    const double k = (kept.at(kv.first) - kv.second) / kv.second, l = (lost.at(kv.first) - kv.second) / kv.second;
    std::printf("label %d: input %.1f cm3, remeshed %+.2f %% (%+.2f %% without PreserveVolumes)\n", kv.first,
      kv.second / 1000, 100 * k, 100 * l);
    EXPECT_LT(std::fabs(k), 0.002) << "label " << kv.first;
    worstKept = std::max(worstKept, std::fabs(k));
    worstLost = std::max(worstLost, std::fabs(l));
  }
  EXPECT_GT(worstLost, 0.03) << "the ribs lose volume without the correction";
  EXPECT_LT(worstKept, 0.1 * worstLost);
}

TEST(MetricRemeshing, AnisotropicTubeStretchesAlongTheAxis)
{
  // A voxelised tube (radius 7 mm, 64 mm long): curved across, straight along. The anisotropic
  // metric asks for long edges along the axis, so the remeshed tube needs far fewer triangles for
  // the same bound. (Before gradation graded each principal size on its own, the anisotropic
  // metric was isotropic in effect and both runs gave the same mesh.)
  const double origin[3] = { -39.5, -11.5, -11.5 };
  auto img = amTest::LabelMap(80, 24, 24, 1.0, origin,
    [](double x, double y, double z) { return y * y + z * z < 49 && std::fabs(x) < 32 ? 1 : 0; });
  vtkNew<amLabelSurface> ls;
  ls->SetInputData(img);
  vtkNew<amSurfaceSmoothing> sm;
  sm->SetInputConnection(ls->GetOutputPort());
  sm->Update();
  struct Result
  {
    vtkIdType Triangles;
    double Hausdorff, Along, Across;
  };
  auto run = [&](bool anisotropic) {
    vtkNew<amCurvatureMetric> cm;
    cm->SetInputConnection(sm->GetOutputPort());
    cm->SetTolerance(0.1);
    cm->SetAnisotropic(anisotropic);
    vtkNew<amMetricRemeshing> rm;
    rm->SetInputConnection(cm->GetOutputPort());
    rm->SetTolerance(0.1);
    rm->Update();
    vtkPolyData* out = rm->GetOutput();
    ExpectClosedRegions(out);
    vtkNew<amSurfaceDistance> d; // measured independently of the remesher
    d->SetInputData(0, out);
    d->SetInputData(1, sm->GetOutput());
    d->Update();
    EXPECT_LE(d->GetHausdorff(), rm->GetHausdorffUpperBound() + 1e-9);
    // Mean length of the side wall's edges along the axis and across it.
    double along = 0, across = 0;
    int nAlong = 0, nAcross = 0;
    vtkIdType npts;
    const vtkIdType* ids;
    for (out->GetPolys()->InitTraversal(); out->GetPolys()->GetNextCell(npts, ids);)
      for (int k = 0; k < 3; ++k)
      {
        double a[3], b[3], e[3];
        out->GetPoint(ids[k], a);
        out->GetPoint(ids[(k + 1) % 3], b);
        vtkMath::Subtract(b, a, e);
        const double length = vtkMath::Norm(e);
        if (std::fabs(a[0] + b[0]) > 50 || length == 0)
          continue; // the caps and their rims
        if (std::fabs(e[0]) > 0.9 * length)
          along += length, ++nAlong;
        else if (std::fabs(e[0]) < 0.3 * length)
          across += length, ++nAcross;
      }
    return Result{ out->GetNumberOfCells(), rm->GetHausdorff(), nAlong ? along / nAlong : 0.0,
      nAcross ? across / nAcross : 0.0 };
  };
  const Result iso = run(false), aniso = run(true);
  std::printf(
    "isotropic: %lld triangles, Hausdorff %.3f, along %.2f across %.2f mm; anisotropic: %lld, %.3f, %.2f, %.2f\n",
    static_cast<long long>(iso.Triangles), iso.Hausdorff, iso.Along, iso.Across,
    static_cast<long long>(aniso.Triangles), aniso.Hausdorff, aniso.Along, aniso.Across);
  // Measured: isotropic 4 042 triangles (edges 1.3 and 1.4 mm), anisotropic 1 782 (3.9 along, 2.0
  // across), both at Hausdorff 0.100.
  EXPECT_LE(iso.Hausdorff, 0.1 + 1e-9);
  EXPECT_LE(aniso.Hausdorff, 0.1 + 1e-9);
  EXPECT_LT(aniso.Triangles, 0.6 * iso.Triangles);
  EXPECT_GT(aniso.Along, 1.5 * aniso.Across);
  EXPECT_LT(iso.Along, 1.2 * iso.Across);
}

TEST(MetricRemeshing, SameMeshWhateverTheThreads)
{
  // Collapses, flips and relaxation run on two workers, one on each side of a plane: the mesh
  // must not depend on the number of threads or on their timing (3 mm phantom, all labels).
  PhantomChain chain(3, 0.5);
  auto run = [&chain]() {
    vtkNew<amMetricRemeshing> remesh;
    remesh->SetInputConnection(chain.Metric->GetOutputPort());
    remesh->SetTolerance(0.5);
    remesh->Update();
    vtkPolyData* out = remesh->GetOutput();
    std::vector<double> points(static_cast<size_t>(3 * out->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      out->GetPoint(i, &points[static_cast<size_t>(3 * i)]);
    std::vector<vtkIdType> cells;
    auto it = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      cells.insert(cells.end(), ids, ids + n);
    }
    return std::make_pair(points, cells);
  };
  const auto two = run();
  vtkSMPTools::Initialize(1);
  const auto one = run();
  const std::string backend = vtkSMPTools::GetBackend();
  vtkSMPTools::SetBackend("Sequential");
  const auto sequential = run();
  vtkSMPTools::SetBackend(backend.c_str());
  vtkSMPTools::Initialize(2);
  const auto again = run();
  ASSERT_GT(two.second.size(), 3000u);
  EXPECT_TRUE(two == one) << "one thread gave another mesh";
  EXPECT_TRUE(two == sequential) << "the Sequential backend gave another mesh";
  EXPECT_TRUE(two == again) << "a second run with two threads gave another mesh";
}

TEST(MetricRemeshing, BadInput)
{
  vtkNew<amTest::ErrorCatcher> errors;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<amMetricRemeshing> rm;
  errors->Watch(rm);
  errors->Watch(rm->GetExecutive());
  rm->SetInputConnection(sphere->GetOutputPort());
  rm->Update();
  EXPECT_TRUE(errors->ErrorContains("no 6-component point data \"Metric\"")) << errors->AllErrors();
}

// Fragments a voxel or two across (what thin organs leave, as on the frog): coarsened with a large
// target size, none may shrink below five vertices (a tetrahedron that flat can turn inside out
// when projected onto the input) and every one stays oriented as the labels say.
TEST(MetricRemeshing, TinyFragmentsNeverBecomeTetrahedra)
{
  const double origin[3] = { 0, 0, 0 };
  auto img = amTest::LabelMap(40, 40, 12, 1.0, origin, [](double x, double y, double z) {
    const int i = static_cast<int>(x), j = static_cast<int>(y), k = static_cast<int>(z);
    if (k < 4 || k > 5 || i < 2 || j < 2 || i > 37 || j > 37)
      return 0;
    // Single voxels, 2x1 bars and 2x2 plates on a 4-voxel lattice, labels 1 and 2.
    const int ci = (i - 2) % 4, cj = (j - 2) % 4, kind = ((i - 2) / 4 + (j - 2) / 4) % 3;
    const bool in = kind == 0 ? (ci == 0 && cj == 0 && k == 4)
      : kind == 1             ? (ci < 2 && cj == 0 && k == 4)
                              : (ci < 2 && cj < 2);
    return in ? 1 + ((i - 2) / 4) % 2 : 0;
  });
  vtkNew<amLabelSurface> ls;
  ls->SetInputData(img);
  vtkNew<amMetricRemeshing> rm;
  rm->SetInputConnection(ls->GetOutputPort());
  rm->SetTargetSize(6.0);
  rm->SetTolerance(1.0);
  rm->Update();
  vtkPolyData* out = rm->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  ExpectClosedRegions(out);
  // Connected components through shared vertices: vertex count and signed volume each.
  const vtkIdType np = out->GetNumberOfPoints();
  std::vector<vtkIdType> parent(static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
    parent[i] = i;
  std::function<vtkIdType(vtkIdType)> find = [&](vtkIdType x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  vtkIdType npts;
  const vtkIdType* ids;
  for (out->GetPolys()->InitTraversal(); out->GetPolys()->GetNextCell(npts, ids);)
    for (int k = 1; k < 3; ++k)
      parent[find(ids[k])] = find(ids[0]);
  std::map<vtkIdType, std::set<vtkIdType>> vertices;
  std::map<vtkIdType, double> volume;
  for (out->GetPolys()->InitTraversal(); out->GetPolys()->GetNextCell(npts, ids);)
  {
    double p[3][3], c[3];
    for (int k = 0; k < 3; ++k)
    {
      out->GetPoint(ids[k], p[k]);
      vertices[find(ids[0])].insert(ids[k]);
    }
    vtkMath::Cross(p[1], p[2], c);
    volume[find(ids[0])] += vtkMath::Dot(p[0], c) / 6.0;
  }
  EXPECT_GE(vertices.size(), 60u);
  int positive = 0, negative = 0;
  for (const auto& entry : vertices)
  {
    EXPECT_GE(entry.second.size(), 5u) << "a fragment shrank to a tetrahedron";
    (volume[entry.first] > 0 ? positive : negative) += 1;
  }
  EXPECT_TRUE(positive == 0 || negative == 0) << positive << " fragments one way, " << negative << " the other";
}

TEST(MetricRemeshing, WhereTheBoundCannotBeKeptTheInputTrianglesAre)
{
  // The phantom at 4 mm, tolerance 2 mm, sizes up to 16 mm (the main job's settings at that
  // spacing): the first remeshing ends above the tolerance on one interface; the input's own
  // triangles are kept there and the bound holds.
  vtkNew<amThoraxPhantomSource> source;
  source->SetSpacing(4, 4, 4);
  vtkNew<amLabelSurface> surface;
  surface->SetInputConnection(source->GetOutputPort(1));
  surface->SetComputeTopology(false);
  vtkNew<amSurfaceSmoothing> smooth;
  smooth->SetInputConnection(surface->GetOutputPort());
  vtkNew<amCurvatureMetric> metric;
  metric->SetInputConnection(smooth->GetOutputPort());
  metric->SetTolerance(2.0);
  metric->SetMinimumSize(4.0);
  metric->SetMaximumSize(16.0);
  metric->SetAnisotropic(false);
  vtkNew<amMetricRemeshing> remesh;
  remesh->SetInputConnection(metric->GetOutputPort());
  remesh->SetTolerance(2.0);
  remesh->Update();
  EXPECT_GT(remesh->GetInputVerticesKept(), 0);
  EXPECT_LE(remesh->GetHausdorff(), 2.0);
  EXPECT_EQ(remesh->GetInterfacesAboveTolerance(), 0);
  ExpectClosedRegions(remesh->GetOutput());
  // Measured independently: the two-sided distance between output and input.
  vtkNew<amSurfaceDistance> distance;
  distance->SetInputConnection(0, remesh->GetOutputPort());
  distance->SetInputConnection(1, smooth->GetOutputPort());
  distance->Update();
  EXPECT_LE(distance->GetHausdorff(), remesh->GetHausdorffUpperBound() + 1e-9);
}
