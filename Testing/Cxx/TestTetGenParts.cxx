// TetGen on two groups of regions at once: a block of label 1 that encloses three small blocks
// (2, 3, 4), so each group's run needs holes where the other group's regions lie.
#include "amGradedSizeField.h"
#include "amLabelSurface.h"
#include "amSurfaceMesh.h"
#include "amTetGenParts.h"
#include "amTetGenRun.h"
#include "amTetraGeometry.h"
#include "amTetraRegions.h"
#include "amTetrahedralize.h"

#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace
{
const int N = 14;

/// Label 1: the voxels [2, 12)^3; inside it, 2: [4, 7)^3, 3: [8, 11) x [4, 7) x [4, 7) and
/// 4: [4, 6) x [8, 11) x [7, 10) (voxel volumes 1000 - 72, 27, 27, 18 mm^3).
vtkSmartPointer<vtkPolyData> NestedSurface()
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(N, N, N);
  img->AllocateScalars(VTK_INT, 1);
  auto* a = vtkIntArray::SafeDownCast(img->GetPointData()->GetScalars());
  a->SetName("Labels");
  auto in = [](int v, int lo, int hi) { return v >= lo && v < hi; };
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
      {
        int label = in(i, 2, 12) && in(j, 2, 12) && in(k, 2, 12) ? 1 : 0;
        if (in(i, 4, 7) && in(j, 4, 7) && in(k, 4, 7))
          label = 2;
        if (in(i, 8, 11) && in(j, 4, 7) && in(k, 4, 7))
          label = 3;
        if (in(i, 4, 6) && in(j, 8, 11) && in(k, 7, 10))
          label = 4;
        a->SetValue((k * N + j) * N + i, label);
      }
  vtkNew<amLabelSurface> surface;
  surface->SetInputData(img);
  surface->SetComputeTopology(false);
  surface->Update();
  return surface->GetOutput();
}

amSurfaceMesh Nested()
{
  amSurfaceMesh mesh;
  std::string why;
  EXPECT_TRUE(mesh.Build(NestedSurface(), why)) << why;
  return mesh;
}

/// Sizes of 1 mm at the surface, graded by 1.5 up to 10 mm.
bool UnitSizes(const amSurfaceMesh& mesh, amGradedSizeField& field)
{
  std::string why;
  const double bounds[6] = { 0, N, 0, N, 0, N };
  const bool ok = field.Build(mesh.Points, std::vector<double>(mesh.Points.size(), 1.0), 1.5, 10.0, bounds, why);
  EXPECT_TRUE(ok) << why;
  return ok;
}

std::map<int, double> RegionVolumes(const amSurfaceMesh& mesh, const amTetGenRun::Result& out)
{
  amTetraRegions regions;
  std::string why;
  EXPECT_TRUE(regions.Assign(mesh, out, 0, why)) << why;
  std::map<int, double> volume;
  for (vtkIdType t = 0;
       t < out.NumberOfTetrahedra && regions.Label.size() == static_cast<size_t>(out.NumberOfTetrahedra); ++t)
  {
    const int* v = &out.Tetrahedra[4 * t];
    const double* p = out.Points.data();
    const double signed6 = amTetraGeometry::SignedVolume(p + 3 * v[0], p + 3 * v[1], p + 3 * v[2], p + 3 * v[3]);
    EXPECT_GT(std::fabs(signed6), 0.0) << "tetrahedron " << t << " is flat";
    volume[regions.Label[t]] += std::fabs(signed6);
  }
  return volume;
}
}

TEST(TetGenParts, GroupsOfAboutEqualWork)
{
  const amSurfaceMesh mesh = Nested();
  const auto groups = amTetGenParts::Groups(mesh, 0);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], std::vector<int>({ 1 })); // the large block outweighs the three small ones
  EXPECT_EQ(groups[1], std::vector<int>({ 2, 3, 4 }));
}

TEST(TetGenParts, TwoGroupsMakeTheMeshOfOneRun)
{
  const amSurfaceMesh mesh = Nested();
  amGradedSizeField field;
  ASSERT_TRUE(UnitSizes(mesh, field));
  const std::string switches = "pzQnMYq1.4/10O2/7";
  amTetGenRun::Result parts, whole;
  int groups = 0;
  const std::string failure = amTetGenParts::Run(mesh, field, switches, 0, true, parts, &groups);
  ASSERT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(groups, 2);
  ASSERT_TRUE(amTetGenRun::Run(mesh, field, switches, whole).empty());

  // As one run leaves it: the input points first and unchanged, every triangle a face (in the
  // triangles' order), the neighbours within range.
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  ASSERT_GE(parts.NumberOfPoints, np);
  for (vtkIdType v = 0; v < np; ++v)
    for (int d = 0; d < 3; ++d)
      ASSERT_EQ(parts.Points[3 * v + d], mesh.Points[v][d]);
  ASSERT_EQ(parts.NumberOfFaces, nt);
  for (vtkIdType s = 0; s < nt; ++s)
    EXPECT_EQ(parts.FaceMarkers[s], s + 1);
  for (int n : parts.Neighbors)
    ASSERT_LT(n, parts.NumberOfTetrahedra);

  // Every region filled as by one run, to rounding; nothing outside the regions.
  const auto volume = RegionVolumes(mesh, parts), reference = RegionVolumes(mesh, whole);
  EXPECT_NEAR(volume.at(1), 1000.0 - 72.0, 1e-9);
  for (int label : { 2, 3, 4 })
    EXPECT_NEAR(volume.at(label), reference.at(label), 1e-9) << "label " << label;
  EXPECT_NEAR(volume.at(4), 18.0, 1e-9);
  EXPECT_EQ(volume.count(0), 0u);
}

TEST(TetGenParts, OneRunWhenTheSurfaceMayMove)
{
  const amSurfaceMesh mesh = Nested();
  amGradedSizeField field;
  ASSERT_TRUE(UnitSizes(mesh, field));
  amTetGenRun::Result out;
  int groups = 0;
  ASSERT_TRUE(amTetGenParts::Run(mesh, field, "pzQnMq1.4/10O2/7", 0, false, out, &groups).empty());
  EXPECT_EQ(groups, 1);
}

TEST(TetGenParts, TetrahedralizeTakesTwoGroupsOnlyWhenAsked)
{
  auto surface = NestedSurface();
  std::map<int, double> volume[2];
  for (int parallel = 0; parallel < 2; ++parallel)
  {
    vtkNew<amTetrahedralize> tets;
    tets->SetInputData(surface);
    EXPECT_EQ(tets->GetParallelGroups(), 0); // the default: one run
    tets->SetParallelGroups(parallel);
    tets->SetImproveQuality(false);
    tets->Update();
    EXPECT_EQ(tets->GetNumberOfGroups(), parallel ? 2 : 1);
    vtkUnstructuredGrid* grid = tets->GetOutput();
    vtkDataArray* region = grid->GetCellData()->GetArray("Region");
    ASSERT_NE(region, nullptr);
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      double p[4][3];
      for (int k = 0; k < 4; ++k)
        grid->GetPoint(grid->GetCell(c)->GetPointId(k), p[k]);
      volume[parallel][static_cast<int>(region->GetComponent(c, 0))] +=
        std::fabs(amTetraGeometry::SignedVolume(p[0], p[1], p[2], p[3]));
    }
  }
  ASSERT_EQ(volume[0].size(), 4u);
  for (const auto& [label, v] : volume[0])
    EXPECT_NEAR(volume[1].at(label), v, 1e-9) << "label " << label;
}

namespace
{
/// Label 1: a 6 mm cube; around it a gap of label 2, then a 2 mm wall of label 3, then label 2
/// again to the border; the gap squeezed to 1 um (a monotone map of each axis, so nothing
/// crosses). Every hole point a hundredth of an inradius off the cube or the wall's inside would
/// land past the gap, in the region on its other side.
amSurfaceMesh SqueezedGap()
{
  const int n = 16;
  vtkNew<vtkImageData> img;
  img->SetDimensions(n, n, n);
  img->AllocateScalars(VTK_INT, 1);
  auto* a = vtkIntArray::SafeDownCast(img->GetPointData()->GetScalars());
  a->SetName("Labels");
  auto box = [](int i, int j, int k, int lo, int hi) {
    return i >= lo && i < hi && j >= lo && j < hi && k >= lo && k < hi;
  };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        a->SetValue((k * n + j) * n + i,
          box(i, j, k, 5, 11)     ? 1
            : box(i, j, k, 4, 12) ? 2
            : box(i, j, k, 3, 13) ? 3
            : box(i, j, k, 1, 15) ? 2
                                  : 0);
  vtkNew<amLabelSurface> surface;
  surface->SetInputData(img);
  surface->SetComputeTopology(false);
  surface->Update();
  amSurfaceMesh mesh;
  std::string why;
  EXPECT_TRUE(mesh.Build(surface->GetOutput(), why)) << why;
  // The wall's inside (3.5, 11.5) moves to 1 um from the cube (4.5, 10.5); the wall stretches.
  const double gap = 1e-3;
  auto squeeze = [gap](double x) {
    if (x > 2.5 && x <= 3.5)
      return 2.5 + (x - 2.5) * (4.5 - gap - 2.5);
    if (x > 3.5 && x < 4.5)
      return 4.5 - gap + (x - 3.5) * gap;
    if (x > 10.5 && x < 11.5)
      return 10.5 + (x - 10.5) * gap;
    if (x >= 11.5 && x < 12.5)
      return 10.5 + gap + (x - 11.5) * (12.5 - 10.5 - gap);
    return x;
  };
  for (auto& p : mesh.Points)
    for (double& x : p)
      x = squeeze(x);
  return mesh;
}
}

TEST(TetGenParts, HolePointsStayOutOfARegionBeyondAThinGap)
{
  const amSurfaceMesh mesh = SqueezedGap();
  const auto groups = amTetGenParts::Groups(mesh, 0);
  ASSERT_EQ(groups.size(), 2u);
  ASSERT_EQ(groups[0], std::vector<int>({ 2 })); // the cube and the wall together, the gap's region apart
  amGradedSizeField field;
  std::string why;
  const double bounds[6] = { 0, 16, 0, 16, 0, 16 };
  ASSERT_TRUE(field.Build(mesh.Points, std::vector<double>(mesh.Points.size(), 1.0), 1.5, 10.0, bounds, why)) << why;
  // No quality refinement: a 1 um gap has no good tetrahedron.
  const std::string switches = "pzQnMY";
  amTetGenRun::Result parts, whole;
  int used = 0;
  ASSERT_TRUE(amTetGenParts::Run(mesh, field, switches, 0, true, parts, &used).empty());
  EXPECT_EQ(used, 2); // not the one run the merge falls back to when a group's region was carved away
  ASSERT_TRUE(amTetGenRun::Run(mesh, field, switches, whole).empty());
  const auto volume = RegionVolumes(mesh, parts), reference = RegionVolumes(mesh, whole);
  EXPECT_NEAR(volume.at(1), 216.0, 1e-9);
  for (int label : { 1, 2, 3 })
    EXPECT_NEAR(volume.at(label), reference.at(label), 1e-9) << "label " << label;
  EXPECT_EQ(volume.count(0), 0u);
}
