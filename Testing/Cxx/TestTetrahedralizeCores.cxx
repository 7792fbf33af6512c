// The tetrahedralizer's parts without a pipeline: the surface check, TetGen in its child process
// and the region flood fill, on the surface of two blocks of voxels side by side.
#include "amGradedSizeField.h"
#include "amLabelSurface.h"
#include "amRegionVolumes.h"
#include "amSurfaceMesh.h"
#include "amTestUtilities.h"
#include "amTetGenRun.h"
#include "amTetraGeometry.h"
#include "amTetraRegions.h"
#include "amTetraSurfaceCheck.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

namespace
{
/// Labels 1 (a 2 x 2 x 2 block of 1 mm voxels) and 2 (the block beside it along x) in a 6^3 map.
vtkSmartPointer<vtkPolyData> TwoBlocks()
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(6, 6, 6);
  img->AllocateScalars(VTK_INT, 1);
  auto* a = vtkIntArray::SafeDownCast(img->GetPointData()->GetScalars());
  a->SetName("Labels");
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i)
      {
        const bool inside = j >= 2 && j < 4 && k >= 2 && k < 4;
        a->SetValue((k * 6 + j) * 6 + i, inside && i >= 1 && i < 3 ? 1 : (inside && i >= 3 && i < 5 ? 2 : 0));
      }
  vtkNew<amLabelSurface> surface;
  surface->SetInputData(img);
  surface->SetComputeTopology(false);
  surface->Update();
  return surface->GetOutput();
}

amSurfaceMesh MeshOf(vtkPolyData* pd)
{
  amSurfaceMesh mesh;
  std::string why;
  EXPECT_TRUE(mesh.Build(pd, why)) << why;
  return mesh;
}

/// The labels of triangle t of pd set to (a, b).
void SetLabels(vtkPolyData* pd, vtkIdType t, int a, int b)
{
  auto* labels = vtkIntArray::SafeDownCast(pd->GetCellData()->GetArray("Labels"));
  labels->SetTypedComponent(t, 0, a);
  labels->SetTypedComponent(t, 1, b);
  labels->Modified();
}
}

TEST(TetraSurfaceCheck, AcceptsClosedRegionsAndNamesWhatIsWrong)
{
  auto good = TwoBlocks();
  std::string why;
  EXPECT_TRUE(amTetraSurfaceCheck::Check(good, MeshOf(good), 0, why)) << why;

  vtkNew<vtkPolyData> same;
  same->DeepCopy(good);
  SetLabels(same, 5, 1, 1);
  EXPECT_FALSE(amTetraSurfaceCheck::Check(same, MeshOf(same), 0, why));
  EXPECT_NE(why.find("Triangles 5 have the same label on both sides"), std::string::npos) << why;

  // One triangle less: the region it bounded is open there.
  vtkNew<vtkPolyData> open;
  open->DeepCopy(good);
  open->BuildCells();
  open->DeleteCell(0);
  open->RemoveDeletedCells();
  EXPECT_FALSE(amTetraSurfaceCheck::Check(open, MeshOf(open), 0, why));
  EXPECT_NE(why.find("The surface is open"), std::string::npos) << why;

  // Every label pair swapped: each region's triangles face inwards and enclose no volume.
  vtkNew<vtkPolyData> inverted;
  inverted->DeepCopy(good);
  for (vtkIdType t = 0; t < inverted->GetNumberOfCells(); ++t)
  {
    double l[2];
    inverted->GetCellData()->GetArray("Labels")->GetTuple(t, l);
    SetLabels(inverted, t, static_cast<int>(l[1]), static_cast<int>(l[0]));
  }
  EXPECT_FALSE(amTetraSurfaceCheck::Check(inverted, MeshOf(inverted), 0, why));
  EXPECT_NE(why.find("encloses no volume"), std::string::npos) << why;

  std::vector<vtkIdType> many(25);
  for (int i = 0; i < 25; ++i)
    many[i] = i;
  EXPECT_EQ(amTetraSurfaceCheck::List(many), "0, 1, 2, 3, 4, 5, 6, 7, 8, 9 and 15 more");
}

TEST(TetraRegions, EveryTetrahedronInItsBlock)
{
  auto surface = TwoBlocks();
  const amSurfaceMesh mesh = MeshOf(surface);
  amGradedSizeField field;
  std::string why;
  const double bounds[6] = { 0, 6, 0, 6, 0, 6 };
  ASSERT_TRUE(field.Build(mesh.Points, std::vector<double>(mesh.Points.size(), 1.0), 1.5, 10.0, bounds, why)) << why;
  amTetGenRun::Result out;
  const std::string failure = amTetGenRun::Run(mesh, field, "pzQnMYq1.4/10O2/7", out);
  ASSERT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(out.NumberOfFaces, mesh.NumberOfTriangles()); // Y: the surface kept
  amTetraRegions regions;
  ASSERT_TRUE(regions.Assign(mesh, out, 0, why)) << why;
  std::map<int, double> volume;
  for (vtkIdType t = 0; t < out.NumberOfTetrahedra; ++t)
  {
    const int* v = &out.Tetrahedra[4 * t];
    const double* p = out.Points.data();
    volume[regions.Label[t]] +=
      std::abs(amTetraGeometry::SignedVolume(p + 3 * v[0], p + 3 * v[1], p + 3 * v[2], p + 3 * v[3]));
  }
  EXPECT_NEAR(volume[1], 8.0, 1e-9);
  EXPECT_NEAR(volume[2], 8.0, 1e-9);
  EXPECT_EQ(volume.size(), 2u); // the two blocks make a box: nothing else inside TetGen's hull
  // Each boundary face has its two sides' tetrahedra (the hull's faces only one).
  for (vtkIdType s = 0; s < out.NumberOfFaces; ++s)
  {
    const vtkIdType src = amTetraRegions::SourceOf(out, s);
    for (int side = 0; side < 2; ++side)
      if (mesh.Labels[src][side] != 0)
      {
        ASSERT_GE(regions.SubfaceTet[s][side], 0);
        EXPECT_EQ(regions.Label[regions.SubfaceTet[s][side]], mesh.Labels[src][side]);
      }
  }
}

TEST(TetraRegions, InconsistentLabelsAreNamed)
{
  auto surface = TwoBlocks();
  // A triangle of block 1's outer boundary claims block 2 inside.
  vtkIdType t = 0;
  double l[2];
  for (; t < surface->GetNumberOfCells(); ++t)
  {
    surface->GetCellData()->GetArray("Labels")->GetTuple(t, l);
    if (l[0] == 1 && l[1] == 0)
      break;
  }
  SetLabels(surface, t, 2, 0);
  const amSurfaceMesh mesh = MeshOf(surface);
  amGradedSizeField field;
  std::string why;
  const double bounds[6] = { 0, 6, 0, 6, 0, 6 };
  ASSERT_TRUE(field.Build(mesh.Points, std::vector<double>(mesh.Points.size(), 1.0), 1.5, 10.0, bounds, why));
  amTetGenRun::Result out;
  ASSERT_TRUE(amTetGenRun::Run(mesh, field, "pzQnMYq1.4/10O2/7", out).empty());
  amTetraRegions regions;
  EXPECT_FALSE(regions.Assign(mesh, out, 0, why));
  EXPECT_NE(why.find("labels are inconsistent"), std::string::npos) << why;
  EXPECT_NE(why.find(std::to_string(t)), std::string::npos) << why;
}

TEST(TetGenRun, CrossingSurfaceIsAMessageNotACrash)
{
  // Two triangles crossing each other: TetGen refuses, in its child process.
  amSurfaceMesh mesh;
  mesh.Points = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0.5, 0.5, -1 }, { 0.5, 0.5, 1 }, { 1.5, -1, 0.2 } };
  mesh.Triangles = { { 0, 1, 2 }, { 3, 4, 5 } };
  mesh.BuildTopology();
  amGradedSizeField field;
  std::string why;
  const double bounds[6] = { -1, 3, -2, 3, -2, 2 };
  ASSERT_TRUE(field.Build(mesh.Points, std::vector<double>(6, 1.0), 1.5, 10.0, bounds, why));
  amTetGenRun::Result out;
  const std::string failure = amTetGenRun::Run(mesh, field, "pzQnMYq1.4/10O2/7", out);
  EXPECT_FALSE(failure.empty());
  std::printf("TetGen on crossing triangles: %s\n", failure.c_str());
}

TEST(RegionVolumes, ComparesEachRegionWithItsVoxels)
{
  // Two corner tetrahedra of 30 mm (4500 mm^3 each), regions 1 and 2; the voxels give region 1
  // exactly, region 2 twice its mesh volume, label 3 (no tetrahedra) 5000 mm^3 and label 4 a
  // volume too small to count.
  vtkNew<vtkUnstructuredGrid> mesh;
  vtkNew<vtkPoints> points;
  const double x[7][3] = { { 0, 0, 0 }, { 30, 0, 0 }, { 0, 30, 0 }, { 0, 0, 30 }, { 100, 0, 0 }, { 130, 0, 0 },
    { 100, 30, 0 } };
  for (const auto& p : x)
    points->InsertNextPoint(p);
  points->InsertNextPoint(100, 0, 30);
  mesh->SetPoints(points);
  const vtkIdType a[4] = { 0, 1, 2, 3 }, b[4] = { 4, 6, 5, 7 }; // the second one inverted
  mesh->InsertNextCell(VTK_TETRA, 4, a);
  mesh->InsertNextCell(VTK_TETRA, 4, b);
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->InsertNextValue(1);
  region->InsertNextValue(2);
  mesh->GetCellData()->AddArray(region);
  vtkNew<vtkDoubleArray> voxels;
  voxels->SetNumberOfComponents(2);
  for (const auto& row : { std::array<double, 2>{ 1, 4500 }, { 2, 9000 }, { 3, 5000 }, { 4, 900 } })
    voxels->InsertNextTuple(row.data());
  const auto misses = amRegionVolumes::Compare(mesh, "Region", voxels, 1000.0, 0.02);
  ASSERT_EQ(misses.size(), 2u);
  EXPECT_EQ(misses[0].Label, 3); // -100 %, the largest difference first
  EXPECT_EQ(misses[0].Mesh, 0.0);
  EXPECT_EQ(misses[1].Label, 2);
  EXPECT_NEAR(misses[1].Mesh, 4500.0, 1e-9);
  auto* table = vtkDoubleArray::SafeDownCast(mesh->GetFieldData()->GetArray("RegionVolumes"));
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->GetNumberOfTuples(), 4);
  EXPECT_EQ(table->GetComponent(0, 0), 1);
  EXPECT_NEAR(table->GetComponent(0, 3), 0.0, 1e-12);
  EXPECT_NEAR(table->GetComponent(1, 3), -0.5, 1e-12);
  EXPECT_NE(amRegionVolumes::Describe(misses, 1).find("label 3 (5 cm3 of voxels, 0 in the mesh, -100 %) and 1 more"),
    std::string::npos)
    << amRegionVolumes::Describe(misses, 1);
}
