// amMeshQuality: the paper's Q on known tetrahedra, dihedral angles, the Table 1 counts.
#include "amMeshQuality.h"
#include "amQualityTable.h"
#include "amTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Grid(const std::vector<std::array<double, 3>>& pts,
  const std::vector<std::array<vtkIdType, 4>>& tets, const std::vector<int>& regions)
{
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  for (const auto& x : pts)
    p->InsertNextPoint(x.data());
  g->SetPoints(p);
  for (const auto& t : tets)
    g->InsertNextCell(VTK_TETRA, 4, t.data());
  vtkNew<vtkIntArray> r;
  r->SetName("Region");
  for (int v : regions)
    r->InsertNextValue(v);
  g->GetCellData()->AddArray(r);
  return g;
}

/// The errors MeshQuality reports on g (empty when none).
std::string Errors(vtkUnstructuredGrid* g)
{
  vtkNew<amMeshQuality> q;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(q);
  errors->Watch(q->GetExecutive());
  q->SetInputData(g);
  q->Update();
  return errors->AllErrors();
}

double Cell(vtkUnstructuredGrid* g, const char* name, vtkIdType c)
{
  return g->GetCellData()->GetArray(name)->GetComponent(c, 0);
}
}

TEST(MeshQuality, RegularTetrahedronScoresOne)
{
  const double s = 3.7;
  auto g = Grid({ { 0, 0, 0 }, { s, 0, 0 }, { s / 2, s * std::sqrt(3.0) / 2, 0 },
                  { s / 2, s * std::sqrt(3.0) / 6, s * std::sqrt(2.0 / 3.0) } },
    { { 0, 1, 2, 3 } }, { 1 });
  vtkNew<amMeshQuality> q;
  q->SetInputData(g);
  q->Update();
  vtkUnstructuredGrid* out = q->GetOutput();
  EXPECT_NEAR(Cell(out, "Quality", 0), 1.0, 1e-12);
  EXPECT_NEAR(Cell(out, "RadiusRatio", 0), 1.0, 1e-12);
  const double regular = std::acos(1.0 / 3.0) * 180.0 / M_PI; // 70.53 degrees
  EXPECT_NEAR(Cell(out, "MinimumDihedralAngle", 0), regular, 1e-9);
  EXPECT_NEAR(Cell(out, "MaximumDihedralAngle", 0), regular, 1e-9);
  EXPECT_NEAR(Cell(out, "Volume", 0), s * s * s / (6 * std::sqrt(2.0)), 1e-9);
}

TEST(MeshQuality, CornerTetrahedronAndSliver)
{
  // Corner tetrahedron: h = sqrt 2, inradius 3V/A with V = 1/6, A = 3/2 + sqrt(3)/2.
  auto g = Grid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0.01 } },
    { { 0, 1, 2, 3 }, { 0, 1, 2, 4 } }, { 1, 1 });
  vtkNew<amMeshQuality> q;
  q->SetInputData(g);
  q->Update();
  vtkUnstructuredGrid* out = q->GetOutput();
  const double rho = 0.5 / (1.5 + std::sqrt(3.0) / 2);
  EXPECT_NEAR(Cell(out, "Quality", 0), std::sqrt(6.0) / 12 * std::sqrt(2.0) / rho, 1e-12);
  EXPECT_NEAR(Cell(out, "MinimumDihedralAngle", 0), std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(Cell(out, "MaximumDihedralAngle", 0), 90.0, 1e-9);
  // The nearly flat square (0,0,0) (1,0,0) (1,1,.01) (0,1,0): a sliver.
  EXPECT_GT(Cell(out, "Quality", 1), 50.0);
  EXPECT_LT(Cell(out, "MinimumDihedralAngle", 1), 2.0);
  EXPECT_GT(Cell(out, "MaximumDihedralAngle", 1), 170.0);
  EXPECT_EQ(q->GetNumberOfInvertedTetrahedra(), 0);
}

TEST(MeshQuality, TableCountsLikeThePaper)
{
  // Two tetrahedra of different regions on one face, a third (inverted) one in region 1.
  auto g = Grid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 }, { 5, 5, 5 }, { 6, 5, 5 },
                  { 5, 6, 5 }, { 5, 5, 6 } },
    { { 0, 1, 2, 3 }, { 0, 2, 1, 4 }, { 5, 7, 6, 8 } }, { 1, 2, 1 });
  vtkNew<amMeshQuality> q;
  q->SetInputData(g);
  q->Update();
  vtkTable* t = vtkTable::SafeDownCast(q->GetOutputDataObject(1));
  ASSERT_EQ(t->GetNumberOfRows(), 3); // regions 1, 2, all
  auto value = [&](int row, const char* col) { return t->GetValueByName(row, col).ToDouble(); };
  EXPECT_EQ(value(0, "Region"), 1);
  EXPECT_EQ(value(0, "np"), 8);
  EXPECT_EQ(value(0, "nt"), 8);
  EXPECT_EQ(value(0, "ne"), 2);
  EXPECT_EQ(value(0, "InvertedTetrahedra"), 1);
  EXPECT_EQ(value(1, "Region"), 2);
  EXPECT_EQ(value(1, "np"), 4);
  EXPECT_EQ(value(1, "nt"), 4);
  EXPECT_EQ(value(2, "Region"), -1);
  EXPECT_EQ(value(2, "np"), 9);
  EXPECT_EQ(value(2, "nt"), 11); // 3 + 3 outer faces, the shared interface once, 4 of the far one
  EXPECT_EQ(value(2, "ne"), 3);
  EXPECT_NEAR(value(2, "Volume"), 1.0 / 6 + 1.0 / 6 - 1.0 / 6, 1e-12);
  EXPECT_EQ(q->GetNumberOfInvertedTetrahedra(), 1);
}

TEST(MeshQuality, TakesTheTetrahedraOfAMixedGrid)
{
  // The two-region mesh of TableCountsLikeThePaper with its boundary triangles, as a mesh read back
  // from Medit or Gmsh has them: the same table, the triangles left out of the output.
  auto g = Grid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 }, { 5, 5, 5 }, { 6, 5, 5 },
                  { 5, 6, 5 }, { 5, 5, 6 } },
    { { 0, 1, 2, 3 }, { 0, 2, 1, 4 }, { 5, 7, 6, 8 } }, { 1, 2, 1 });
  auto mixed = Grid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 }, { 5, 5, 5 }, { 6, 5, 5 },
                      { 5, 6, 5 }, { 5, 5, 6 } },
    { { 0, 1, 2, 3 }, { 0, 2, 1, 4 }, { 5, 7, 6, 8 } }, { 1, 2, 1 });
  const vtkIdType tri[2][3] = { { 0, 1, 3 }, { 5, 6, 8 } };
  for (const auto& t : tri)
  {
    mixed->InsertNextCell(VTK_TRIANGLE, 3, t);
    mixed->GetCellData()->GetArray("Region")->InsertNextTuple1(1000);
  }
  vtkNew<amMeshQuality> a, b;
  a->SetInputData(g);
  a->Update();
  b->SetInputData(mixed);
  b->Update();
  vtkTable* ta = vtkTable::SafeDownCast(a->GetOutputDataObject(1));
  vtkTable* tb = vtkTable::SafeDownCast(b->GetOutputDataObject(1));
  ASSERT_EQ(ta->GetNumberOfRows(), tb->GetNumberOfRows());
  for (vtkIdType r = 0; r < ta->GetNumberOfRows(); ++r)
    for (vtkIdType c = 0; c < ta->GetNumberOfColumns(); ++c)
      EXPECT_EQ(ta->GetValue(r, c).ToDouble(), tb->GetValue(r, c).ToDouble()) << r << " " << c;
  auto* out = vtkUnstructuredGrid::SafeDownCast(b->GetOutputDataObject(0));
  ASSERT_EQ(out->GetNumberOfCells(), 3);
  EXPECT_EQ(out->GetCellData()->GetArray("Region")->GetComponent(1, 0), 2);
  EXPECT_EQ(out->GetCellData()->GetArray("Quality")->GetNumberOfTuples(), 3);
}

TEST(MeshQuality, RefusesAMeshWithoutTetrahedra)
{
  vtkNew<vtkUnstructuredGrid> g;
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  for (int i = 0; i < 3; ++i)
    p->InsertNextPoint(i, i * i, 0);
  g->SetPoints(p);
  const vtkIdType tri[3] = { 0, 1, 2 };
  g->InsertNextCell(VTK_TRIANGLE, 3, tri);
  const std::string errors = Errors(g);
  EXPECT_NE(errors.find("has no tetrahedron"), std::string::npos) << errors;
}

// A tetrahedron that names a point the mesh does not have is an error naming both, not a read
// (or a count) past the points' end.
TEST(MeshQuality, RefusesAPointIdOutOfRange)
{
  auto g = Grid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, { { 0, 1, 2, 3 }, { 0, 1, 2, 7 } }, { 1, 1 });
  const std::string errors = Errors(g);
  EXPECT_NE(errors.find("Tetrahedron 1 refers to point 7, but the mesh has 4 points"), std::string::npos) << errors;
}

TEST(QualityTable, TwoRegionsSharingAFaceCountTheirOwnAndTheMeshsTriangles)
{
  // Two tetrahedra glued by face (0, 1, 2): apart they have 4 vertices and 4 boundary triangles
  // each; the mesh has 5 vertices, 6 outer triangles and the interface between them (7). One
  // region: the glued face is inside it (6 triangles).
  const std::vector<std::array<vtkIdType, 4>> tets = { { 0, 1, 2, 3 }, { 0, 2, 1, 4 } };
  const double q[2] = { 1.5, 2.5 }, dmin[2] = { 40, 20 }, dmax[2] = { 100, 120 }, vol[2] = { 1.0, -0.5 };
  std::map<int, amQualityTable::Row> rows;
  amQualityTable::Row all;
  amQualityTable::Count(tets, { 3, 7 }, 5, q, dmin, dmax, vol, rows, all);
  ASSERT_EQ(rows.size(), 2u);
  for (const int label : { 3, 7 })
  {
    EXPECT_EQ(rows[label].np, 4);
    EXPECT_EQ(rows[label].nt, 4);
    EXPECT_EQ(rows[label].ne, 1);
  }
  EXPECT_EQ(all.np, 5);
  EXPECT_EQ(all.nt, 7);
  EXPECT_EQ(all.ne, 2);
  EXPECT_DOUBLE_EQ(all.sumQ, 4.0);
  EXPECT_DOUBLE_EQ(all.maxQ, 2.5);
  EXPECT_DOUBLE_EQ(all.minD, 20);
  EXPECT_DOUBLE_EQ(all.maxD, 120);
  EXPECT_EQ(rows[7].inverted, 1); // a volume <= 0
  EXPECT_EQ(all.inverted, 1);
  amQualityTable::Count(tets, { 3, 3 }, 5, q, dmin, dmax, vol, rows, all);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[3].nt, 6);
  EXPECT_EQ(all.nt, 6);
}
