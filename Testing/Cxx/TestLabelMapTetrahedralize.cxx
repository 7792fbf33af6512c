// amLabelMapTetrahedralize (CGAL Mesh_3 backend): volumes against analytic balls, interfaces that
// bound the tetrahedra exactly, the world frame (origin, direction), every phantom organ, same
// result twice, bad input.
#include "amAtlasChain.h" // amTest::DistinctValues
#include "amFigures.h"
#include "amImageReader.h"
#include "amLabelMapTetrahedralize.h"
#include "amMeshQuality.h"
#include "amSurfaceTestUtilities.h"
#include "amSyntheticAtlasSource.h"
#include "amTestUtilities.h"
#include "amTetraMeshChecks.h"
#include "amThoraxPhantomSource.h"

#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace
{
double Det(const double a[3], const double b[3], const double c[3], const double d[3])
{
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = d[k] - a[k];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Per region: volume of its tetrahedra, and the number with non-positive volume.
std::map<int, double> TetVolumes(vtkUnstructuredGrid* g, int* bad, double centroid[3], int which)
{
  std::map<int, double> v;
  *bad = 0;
  vtkDataArray* region = g->GetCellData()->GetArray("Region");
  double weight = 0;
  centroid[0] = centroid[1] = centroid[2] = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    double p[4][3];
    for (int k = 0; k < 4; ++k)
      g->GetPoint(g->GetCell(c)->GetPointId(k), p[k]);
    const double vol = Det(p[0], p[1], p[2], p[3]) / 6;
    *bad += vol <= 0;
    const int r = static_cast<int>(region->GetComponent(c, 0));
    v[r] += vol;
    if (r == which)
    {
      for (int d = 0; d < 3; ++d)
        centroid[d] += vol * (p[0][d] + p[1][d] + p[2][d] + p[3][d]) / 4;
      weight += vol;
    }
  }
  for (int d = 0; d < 3; ++d)
    centroid[d] /= weight;
  return v;
}

/// Per region: the volume its interface triangles enclose (outward = from Labels[0] to Labels[1]).
std::map<int, double> EnclosedVolumes(vtkPolyData* s)
{
  std::map<int, double> v;
  vtkDataArray* labels = s->GetCellData()->GetArray("Labels");
  const double o[3] = { 0, 0, 0 };
  for (vtkIdType t = 0; t < s->GetNumberOfCells(); ++t)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      s->GetPoint(s->GetCell(t)->GetPointId(k), p[k]);
    const double vol = Det(o, p[0], p[1], p[2]) / 6;
    v[static_cast<int>(labels->GetComponent(t, 0))] += vol;
    v[static_cast<int>(labels->GetComponent(t, 1))] -= vol;
  }
  return v;
}

struct Meshing
{
  vtkSmartPointer<vtkUnstructuredGrid> Mesh;
  vtkSmartPointer<vtkPolyData> Interfaces;
  bool Ok = false;
  std::string Errors;
};

Meshing MeshIt(vtkImageData* labels, double facetSize, double cellSize, double distance,
  const std::vector<double>& regionCellSizes = {}, bool improve = false)
{
  vtkNew<amLabelMapTetrahedralize> m;
  m->SetImproveQuality(improve);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(m);
  errors->Watch(m->GetExecutive());
  m->SetInputData(labels);
  m->SetFacetSize(facetSize);
  m->SetCellSize(cellSize);
  m->SetFacetDistance(distance);
  for (std::size_t k = 0; k + 1 < regionCellSizes.size(); k += 2)
    m->AddRegionCellSize(regionCellSizes[k], regionCellSizes[k + 1]);
  Meshing r;
  r.Ok = m->GetExecutive()->Update() != 0 && !errors->HasError();
  r.Mesh = m->GetOutput();
  r.Interfaces = vtkPolyData::SafeDownCast(m->GetOutputDataObject(1));
  r.Errors = errors->AllErrors();
  return r;
}

/// A ball of radius 10 mm (label 2) in a ball of radius 18 mm (label 1), centred at c, in a
/// rotated frame.
vtkSmartPointer<vtkImageData> NestedBalls(const double c[3], vtkMatrix3x3* direction)
{
  const double origin[3] = { 0, 0, 0 };
  auto img = amTest::LabelMap(48, 48, 48, 1.0, origin, [](double x, double y, double z) {
    const double r = std::sqrt((x - 23.5) * (x - 23.5) + (y - 23.5) * (y - 23.5) + (z - 23.5) * (z - 23.5));
    return r < 10 ? 2 : (r < 18 ? 1 : 0);
  });
  // World = origin + D * index: put the ball centre (23.5, 23.5, 23.5) in index space at c.
  double local[3] = { 23.5, 23.5, 23.5 }, rotated[3];
  direction->MultiplyPoint(local, rotated);
  img->SetOrigin(c[0] - rotated[0], c[1] - rotated[1], c[2] - rotated[2]);
  img->SetDirectionMatrix(direction);
  return img;
}
}

TEST(LabelMapTetrahedralize, NestedBallsVolumesAndInterfaces)
{
  vtkNew<vtkMatrix3x3> direction; // a rotation of 30 degrees about z
  const double a = M_PI / 6;
  direction->SetElement(0, 0, std::cos(a));
  direction->SetElement(0, 1, -std::sin(a));
  direction->SetElement(1, 0, std::sin(a));
  direction->SetElement(1, 1, std::cos(a));
  const double c[3] = { -40, 15, 120 };
  const Meshing r = MeshIt(NestedBalls(c, direction), 2.0, 3.0, 0.2);
  ASSERT_TRUE(r.Ok) << r.Errors;
  int bad = 0;
  double centroid[3];
  const auto tets = TetVolumes(r.Mesh, &bad, centroid, 2);
  EXPECT_EQ(bad, 0);
  ASSERT_EQ(tets.size(), 2u);
  const double v2 = 4.0 / 3 * M_PI * 1000, v1 = 4.0 / 3 * M_PI * (18 * 18 * 18) - v2;
  EXPECT_NEAR(tets.at(2), v2, 0.03 * v2);
  EXPECT_NEAR(tets.at(1), v1, 0.03 * v1);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(centroid[d], c[d], 0.2) << d; // the world frame is honoured
  // The interface triangles bound each region's tetrahedra exactly, oriented outwards.
  const auto enclosed = EnclosedVolumes(r.Interfaces);
  EXPECT_NEAR(enclosed.at(2), tets.at(2), 1e-9 * v2);
  EXPECT_NEAR(enclosed.at(1), tets.at(1), 1e-9 * v1);
  std::set<std::pair<int, int>> pairs;
  vtkDataArray* labels = r.Interfaces->GetCellData()->GetArray("Labels");
  for (vtkIdType t = 0; t < r.Interfaces->GetNumberOfCells(); ++t)
    pairs.insert({ static_cast<int>(labels->GetComponent(t, 0)), static_cast<int>(labels->GetComponent(t, 1)) });
  EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{ { 1, 0 }, { 2, 1 } }));
}

TEST(LabelMapTetrahedralize, ImproveQualityKeepsTheInterfaces)
{
  vtkNew<vtkMatrix3x3> identity;
  const double c[3] = { 0, 0, 0 };
  auto labels = NestedBalls(c, identity);
  const Meshing plain = MeshIt(labels, 4.0, 6.0, 0.5);
  const Meshing improved = MeshIt(labels, 4.0, 6.0, 0.5, {}, true);
  ASSERT_TRUE(plain.Ok) << plain.Errors;
  ASSERT_TRUE(improved.Ok) << improved.Errors;
  // CGAL's surface stays: the same triangles at the same places.
  ASSERT_EQ(plain.Interfaces->GetNumberOfCells(), improved.Interfaces->GetNumberOfCells());
  for (vtkIdType t = 0; t < plain.Interfaces->GetNumberOfCells(); ++t)
    for (int k = 0; k < 3; ++k)
    {
      double p[3], q[3];
      plain.Interfaces->GetPoint(plain.Interfaces->GetCell(t)->GetPointId(k), p);
      improved.Interfaces->GetPoint(improved.Interfaces->GetCell(t)->GetPointId(k), q);
      ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "triangle " << t;
    }
  // Each region is still filled exactly, and "Tetra" names a tetrahedron of the right region
  // holding the triangle on each side.
  int bad = 0;
  double centroid[3];
  const auto tets = TetVolumes(improved.Mesh, &bad, centroid, 2);
  EXPECT_EQ(bad, 0);
  // Every point in a tetrahedron, and the interfaces on the same points.
  EXPECT_EQ(amTest::InterfaceProblems(improved.Mesh, improved.Interfaces), "");
  const auto enclosed = EnclosedVolumes(improved.Interfaces);
  for (int r : { 1, 2 })
    EXPECT_NEAR(enclosed.at(r), tets.at(r), 1e-9 * tets.at(r)) << r;
  vtkDataArray* lab = improved.Interfaces->GetCellData()->GetArray("Labels");
  vtkDataArray* tetra = improved.Interfaces->GetCellData()->GetArray("Tetra");
  vtkDataArray* region = improved.Mesh->GetCellData()->GetArray("Region");
  ASSERT_TRUE(lab && tetra && region);
  for (vtkIdType t = 0; t < improved.Interfaces->GetNumberOfCells(); ++t)
    for (int side = 0; side < 2; ++side)
    {
      const int label = static_cast<int>(lab->GetComponent(t, side));
      const vtkIdType cell = static_cast<vtkIdType>(tetra->GetComponent(t, side));
      if (label == 0)
      {
        EXPECT_EQ(cell, -1);
        continue;
      }
      ASSERT_GE(cell, 0) << "triangle " << t << " side " << side;
      EXPECT_EQ(static_cast<int>(region->GetComponent(cell, 0)), label);
      std::set<vtkIdType> corners;
      for (int k = 0; k < 4; ++k)
        corners.insert(improved.Mesh->GetCell(cell)->GetPointId(k));
      for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(corners.count(improved.Interfaces->GetCell(t)->GetPointId(k)));
    }
  vtkNew<amMeshQuality> q0, q1;
  q0->SetInputData(plain.Mesh);
  q0->Update();
  q1->SetInputData(improved.Mesh);
  q1->Update();
  std::printf("CGAL: mean Q %.3f, worst %.2f; improved: mean Q %.3f, worst %.2f\n", q0->GetMeanQuality(),
    q0->GetMaximumQuality(), q1->GetMeanQuality(), q1->GetMaximumQuality());
  EXPECT_LT(q1->GetMeanQuality(), q0->GetMeanQuality() - 0.1);
  EXPECT_LE(q1->GetMaximumQuality(), q0->GetMaximumQuality());
}

namespace
{
// Mean edge length of the tetrahedra of one region.
double MeanEdge(vtkUnstructuredGrid* g, int region, vtkIdType* count)
{
  vtkDataArray* regions = g->GetCellData()->GetArray("Region");
  double sum = 0;
  vtkIdType n = 0;
  *count = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    if (regions->GetComponent(c, 0) != region)
      continue;
    ++*count;
    const vtkIdType* ids;
    vtkIdType npts;
    g->GetCellPoints(c, npts, ids);
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
      {
        double p[3], q[3];
        g->GetPoint(ids[a], p);
        g->GetPoint(ids[b], q);
        sum += std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
        ++n;
      }
  }
  return n ? sum / n : 0.0;
}

// Mean triangle area per label pair of an interface output.
std::map<std::pair<int, int>, double> MeanArea(vtkPolyData* s)
{
  vtkDataArray* labels = s->GetCellData()->GetArray("Labels");
  std::map<std::pair<int, int>, std::pair<double, int>> sums;
  for (vtkIdType t = 0; t < s->GetNumberOfCells(); ++t)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      s->GetPoint(s->GetCell(t)->GetPointId(k), p[k]);
    double u[3], v[3], n[3];
    for (int d = 0; d < 3; ++d)
    {
      u[d] = p[1][d] - p[0][d];
      v[d] = p[2][d] - p[0][d];
    }
    vtkMath::Cross(u, v, n);
    auto& sum = sums[{ static_cast<int>(labels->GetComponent(t, 0)), static_cast<int>(labels->GetComponent(t, 1)) }];
    sum.first += 0.5 * vtkMath::Norm(n);
    ++sum.second;
  }
  std::map<std::pair<int, int>, double> mean;
  for (const auto& kv : sums)
    mean[kv.first] = kv.second.first / kv.second.second;
  return mean;
}
}

TEST(LabelMapTetrahedralize, RegionCellSizes)
{
  vtkNew<vtkMatrix3x3> identity;
  const double c[3] = { 0, 0, 0 };
  auto labels = NestedBalls(c, identity);
  const Meshing uniform = MeshIt(labels, 4.0, 6.0, 0.5);
  const Meshing fine = MeshIt(labels, 4.0, 6.0, 0.5, { 2, 1.5 }); // the inner ball at 1.5 mm
  ASSERT_TRUE(uniform.Ok) << uniform.Errors;
  ASSERT_TRUE(fine.Ok) << fine.Errors;
  vtkIdType n2u, n2f, n1u, n1f;
  const double e2u = MeanEdge(uniform.Mesh, 2, &n2u), e2f = MeanEdge(fine.Mesh, 2, &n2f);
  const double e1u = MeanEdge(uniform.Mesh, 1, &n1u), e1f = MeanEdge(fine.Mesh, 1, &n1f);
  std::printf("inner ball: %lld tets, mean edge %.2f mm -> %lld tets, %.2f mm with a 1.5 mm cell size; "
              "outer shell: %lld tets, %.2f mm -> %lld tets, %.2f mm\n",
    static_cast<long long>(n2u), e2u, static_cast<long long>(n2f), e2f, static_cast<long long>(n1u), e1u,
    static_cast<long long>(n1f), e1f);
  EXPECT_LT(e2f, 0.6 * e2u); // the chosen region is finer
  EXPECT_GT(n2f, 4 * n2u);
  EXPECT_LT(e1f, e1u); // the thin outer shell gets finer near the fine interface, but
  // its outer surface (labels 1 | 0) keeps the coarse facets, the inner one (2 | 1) is finer.
  const auto ua = MeanArea(uniform.Interfaces), fa = MeanArea(fine.Interfaces);
  std::printf("interface triangles, mean area: 2|1 %.2f -> %.2f mm^2, 1|0 %.2f -> %.2f mm^2\n", ua.at({ 2, 1 }),
    fa.at({ 2, 1 }), ua.at({ 1, 0 }), fa.at({ 1, 0 }));
  EXPECT_LT(fa.at({ 2, 1 }), 0.3 * ua.at({ 2, 1 }));
  EXPECT_NEAR(fa.at({ 1, 0 }), ua.at({ 1, 0 }), 0.25 * ua.at({ 1, 0 }));
  int bad = 0;
  double centroid[3];
  const auto tets = TetVolumes(fine.Mesh, &bad, centroid, 2);
  EXPECT_EQ(bad, 0);
  const double v2 = 4.0 / 3 * M_PI * 1000;
  EXPECT_NEAR(tets.at(2), v2, 0.03 * v2);

  // Sizes for the background or non-positive sizes are errors.
  const Meshing background = MeshIt(labels, 4.0, 6.0, 0.5, { 0, 2 });
  EXPECT_FALSE(background.Ok);
  EXPECT_NE(background.Errors.find("not a meshed label"), std::string::npos) << background.Errors;
  const Meshing zero = MeshIt(labels, 4.0, 6.0, 0.5, { 2, 0 });
  EXPECT_FALSE(zero.Ok);
  EXPECT_NE(zero.Errors.find("must be > 0"), std::string::npos) << zero.Errors;
}

TEST(LabelMapTetrahedralize, EveryPhantomOrganAndTheSameMeshTwice)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(4, 4, 4);
  src->Update();
  vtkImageData* labels = vtkImageData::SafeDownCast(src->GetOutputDataObject(1));
  const Meshing a = MeshIt(labels, 8.0, 12.0, 1.5);
  ASSERT_TRUE(a.Ok) << a.Errors;
  int bad = 0;
  double centroid[3];
  const auto tets = TetVolumes(a.Mesh, &bad, centroid, 1);
  EXPECT_EQ(bad, 0);
  std::set<int> regions;
  for (const auto& kv : tets)
    regions.insert(kv.first);
  EXPECT_EQ(regions, (std::set<int>{ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 }));
  const Meshing b = MeshIt(labels, 8.0, 12.0, 1.5);
  ASSERT_TRUE(b.Ok) << b.Errors;
  ASSERT_EQ(a.Mesh->GetNumberOfPoints(), b.Mesh->GetNumberOfPoints());
  ASSERT_EQ(a.Mesh->GetNumberOfCells(), b.Mesh->GetNumberOfCells());
  for (vtkIdType p = 0; p < a.Mesh->GetNumberOfPoints(); p += 97)
    for (int d = 0; d < 3; ++d)
      ASSERT_EQ(a.Mesh->GetPoint(p)[d], b.Mesh->GetPoint(p)[d]);
}

TEST(LabelMapTetrahedralize, BadInput)
{
  const double origin[3] = { 0, 0, 0 };
  {
    vtkNew<vtkImageData> empty;
    const Meshing r = MeshIt(empty, 2, 3, 0.5);
    EXPECT_FALSE(r.Ok);
    EXPECT_NE(r.Errors.find("empty"), std::string::npos) << r.Errors;
  }
  {
    const Meshing r =
      MeshIt(amTest::LabelMap(8, 8, 8, 1.0, origin, [](double, double, double) { return 0; }), 2, 3, 0.5);
    EXPECT_FALSE(r.Ok);
    EXPECT_NE(r.Errors.find("only the background"), std::string::npos) << r.Errors;
  }
  {
    // An intensity image fed by mistake: refused, not meshed as hundreds of labels.
    vtkNew<vtkImageData> ct;
    ct->SetDimensions(8, 8, 8);
    ct->AllocateScalars(VTK_FLOAT, 1);
    for (vtkIdType i = 0; i < ct->GetNumberOfPoints(); ++i)
      ct->GetPointData()->GetScalars()->SetTuple1(i, 0.37 * static_cast<double>(i));
    const Meshing r = MeshIt(ct, 2, 3, 0.5);
    EXPECT_FALSE(r.Ok);
    EXPECT_NE(r.Errors.find("whole numbers"), std::string::npos) << r.Errors;
    EXPECT_NE(r.Errors.find("float"), std::string::npos) << r.Errors;
    EXPECT_EQ(r.Mesh->GetNumberOfCells(), 0);
  }
}

TEST(LabelMapTetrahedralize, AnyWholeNumberLabelsKeepTheirValues)
{
  // Labels far outside 0-255, negative ones and the background not 0: each region comes back with
  // its own label (CGAL meshes a compact copy).
  const double origin[3] = { 0, 0, 0 };
  auto labels = amTest::LabelMap(32, 32, 32, 1.0, origin, [](double x, double y, double z) {
    const double r = std::sqrt((x - 15.5) * (x - 15.5) + (y - 15.5) * (y - 15.5) + (z - 15.5) * (z - 15.5));
    return r > 13 ? 70000 : (r < 6 ? -5 : (x < 15.5 ? 1000 : 2000));
  });
  vtkNew<amLabelMapTetrahedralize> m;
  m->SetInputData(labels);
  m->SetBackgroundLabel(70000);
  m->SetFacetSize(2);
  m->SetCellSize(2);
  m->SetFacetDistance(0.5);
  m->AddRegionCellSize(-5, 1.0);
  m->Update();
  const std::set<int> regions = amTest::DistinctValues(m->GetOutput()->GetCellData()->GetArray("Region"));
  EXPECT_EQ(regions, (std::set<int>{ -5, 1000, 2000 }));
  const std::set<int> sides =
    amTest::DistinctValues(vtkPolyData::SafeDownCast(m->GetOutputDataObject(1))->GetCellData()->GetArray("Labels"));
  EXPECT_EQ(sides, (std::set<int>{ -5, 1000, 2000, 70000 }));
}

TEST(LabelMapTetrahedralize, MoreThan255Labels)
{
  // 300 int16 labels (Voronoi cells): the 16-bit path; every label a region.
  vtkNew<amSyntheticAtlasSource> atlas;
  atlas->SetNumberOfLabels(300);
  atlas->SetDimensions(64, 64, 64);
  atlas->Update();
  ASSERT_EQ(atlas->GetOutput()->GetScalarType(), VTK_SHORT);
  std::set<int> labels = amTest::DistinctValues(atlas->GetOutput()->GetPointData()->GetScalars());
  labels.erase(0);
  ASSERT_EQ(labels.size(), 300u);
  vtkNew<amLabelMapTetrahedralize> m;
  m->SetInputConnection(atlas->GetOutputPort());
  m->SetFacetSize(3);
  m->SetCellSize(3);
  m->SetFacetDistance(1.0);
  m->Update();
  EXPECT_EQ(amTest::DistinctValues(m->GetOutput()->GetCellData()->GetArray("Region")), labels);
}

// Real maps nobody tuned for (the niivue torso, 0.78 x 0.78 x 5 mm voxels; the TotalSegmentator
// abdomen, 3 mm, with a label of one voxel on the image's last slice): every label a region, the
// small ones too (each connected component seeded before the refinement, the image padded so the
// border's voxels are whole), and with the improvement no element above Q 10 or under 10 degrees.
TEST(LabelMapTetrahedralize, EveryLabelOfARealMapAndNoSliver)
{
  struct Map
  {
    const char* Path;
    double Distance, Size; // mm
  };
  for (const Map& map : { Map{ "niivue_torso_labels/torsoLabel.nii.gz", 2, 8 },
         Map{ "totalseg_abdomen_ct_labels/example_seg.nii.gz", 1, 4 } })
  {
    AM_REQUIRE_SHARED(path, map.Path);
    vtkNew<amImageReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    std::set<int> labels = amTest::DistinctValues(reader->GetOutput()->GetPointData()->GetScalars());
    labels.erase(0);
    vtkNew<amLabelMapTetrahedralize> m;
    m->SetInputConnection(reader->GetOutputPort());
    m->SetFacetDistance(map.Distance);
    m->SetFacetSize(map.Size);
    m->SetCellSize(map.Size);
    m->SetImproveQuality(true);
    m->Update();
    EXPECT_EQ(amTest::DistinctValues(m->GetOutput()->GetCellData()->GetArray("Region")), labels) << map.Path;
    vtkNew<amMeshQuality> quality;
    quality->SetInputData(m->GetOutput());
    quality->Update();
    std::printf("%s: %zu labels, %lld tetrahedra, worst Q %.2f, smallest dihedral %.2f deg\n", map.Path, labels.size(),
      static_cast<long long>(m->GetOutput()->GetNumberOfCells()), quality->GetMaximumQuality(),
      quality->GetMinimumDihedralAngle());
    EXPECT_EQ(m->GetNumberOfSlivers(), 0);
    EXPECT_LE(quality->GetMaximumQuality(), 10.0);
    EXPECT_GE(quality->GetMinimumDihedralAngle(), 10.0);
    amTest::RecordFigure("cgal_real.worst_q", quality->GetMaximumQuality(), "", 10.0);
    amTest::RecordFigure("cgal_real.smallest_dihedral", quality->GetMinimumDihedralAngle(), "deg", 10.0);
    amTest::RecordFigure("cgal_real.volume_misses", static_cast<double>(m->GetNumberOfVolumeMisses()), "", 0);
    amTest::RecordFigure("cgal_real.surface_moved", m->GetVolumeDisplacement(), "mm");
    // Every region of at least 1 cm3 within 2 % of its voxels (PreserveVolumes: without it the
    // abdomen has 29 regions off, up to -37 %).
    EXPECT_EQ(m->GetNumberOfVolumeMisses(), 0) << map.Path;
    double spacing[3];
    reader->GetOutput()->GetSpacing(spacing);
    EXPECT_LE(
      m->GetVolumeDisplacement(), std::max(map.Distance, 0.5 * std::max({ spacing[0], spacing[1], spacing[2] })) + 1e-9)
      << map.Path;
  }
}

// Generated atlases (30 Voronoi cells; clean, and with one-voxel sheets between them): CGAL's
// chords and the label function's rounding take a few per cent of the smaller cells; with
// PreserveVolumes every cell of at least 1 cm3 is within 2 % of its voxels, the surface moved
// by at most FacetDistance, and the element bar still holds.
TEST(LabelMapTetrahedralize, PreserveVolumesGivesEveryRegionItsVoxels)
{
  for (const double sheet : { 0.0, 1.0 })
  {
    vtkNew<amSyntheticAtlasSource> atlas;
    atlas->SetNumberOfLabels(30);
    atlas->SetSheetWidth(sheet);
    atlas->Update();
    vtkIdType misses[2] = { 0, 0 };
    for (const bool preserve : { false, true })
    {
      vtkNew<amLabelMapTetrahedralize> m;
      m->SetInputConnection(atlas->GetOutputPort());
      m->SetFacetSize(3);
      m->SetCellSize(3);
      m->SetFacetDistance(0.75);
      m->SetImproveQuality(true);
      m->SetPreserveVolumes(preserve);
      m->Update();
      misses[preserve] = m->GetNumberOfVolumeMisses();
      vtkDataArray* volumes = m->GetOutput()->GetFieldData()->GetArray("RegionVolumes");
      ASSERT_NE(volumes, nullptr);
      double worst = 0;
      for (vtkIdType r = 0; r < volumes->GetNumberOfTuples(); ++r)
        if (volumes->GetComponent(r, 1) >= 1000.0)
          worst = std::max(worst, std::fabs(volumes->GetComponent(r, 3)));
      std::printf("sheets %.0f mm, PreserveVolumes %d: %lld regions off by more than 2 %%, worst %.2f %%, surface "
                  "moved %.3f mm\n",
        sheet, preserve, static_cast<long long>(misses[preserve]), 100 * worst, m->GetVolumeDisplacement());
      amTest::RecordFigure(preserve ? "cgal_atlas.volume_misses" : "cgal_atlas.volume_misses_alone",
        static_cast<double>(misses[preserve]), "", preserve ? 0.0 : NAN);
      amTest::RecordFigure(preserve ? "cgal_atlas.worst_volume_off" : "cgal_atlas.worst_volume_off_alone", 100 * worst,
        "%", preserve ? 2.0 : NAN);
      if (preserve)
      {
        EXPECT_LE(worst, 0.02);
        EXPECT_GT(m->GetVolumeDisplacement(), 0.0);
        EXPECT_LE(m->GetVolumeDisplacement(), 0.75 + 1e-9);
        EXPECT_EQ(m->GetNumberOfSlivers(), 0);
      }
      else
        EXPECT_EQ(m->GetVolumeDisplacement(), 0.0);
    }
    EXPECT_GT(misses[0], 0) << "sheets " << sheet; // the correction has something to do
    EXPECT_EQ(misses[1], 0) << "sheets " << sheet;
  }
}
