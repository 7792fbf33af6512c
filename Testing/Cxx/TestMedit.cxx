// Medit .mesh/.sol: a round trip keeps every number; malformed files give the line of the problem.
#include "amBoxMesh.h"
#include "amMeditReader.h"
#include "amMeditWriter.h"
#include "amTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace
{
// Two tetrahedra of two regions sharing a face, with that face as a triangle, awkward numbers.
vtkSmartPointer<vtkUnstructuredGrid> TwoTets()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->InsertNextPoint(0.1, 0.2, 0.30000000000000004);
  pts->InsertNextPoint(1.0 / 3.0, 0.0, 0.0);
  pts->InsertNextPoint(0.0, 2.0 / 7.0, 1e-17);
  pts->InsertNextPoint(0.0, 0.0, 1.0e6 + 0.123456789);
  pts->InsertNextPoint(-3.14159265358979, -2.718281828459045, -1.4142135623730951);
  grid->SetPoints(pts);
  const vtkIdType t1[4] = { 0, 1, 2, 3 }, t2[4] = { 0, 2, 1, 4 }, tri[3] = { 0, 1, 2 };
  grid->InsertNextCell(VTK_TETRA, 4, t1);
  grid->InsertNextCell(VTK_TETRA, 4, t2);
  grid->InsertNextCell(VTK_TRIANGLE, 3, tri);
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->InsertNextValue(5);
  region->InsertNextValue(6);
  region->InsertNextValue(56);
  grid->GetCellData()->AddArray(region);
  vtkNew<vtkIntArray> ref;
  ref->SetName("Ref");
  for (int i = 0; i < 5; ++i)
    ref->InsertNextValue(10 + i);
  grid->GetPointData()->AddArray(ref);
  vtkNew<vtkDoubleArray> metric;
  metric->SetName("Metric");
  metric->SetNumberOfComponents(6);
  for (int i = 0; i < 5; ++i)
  {
    const double m[6] = { 1.0 + i, 2.0 / 3.0, 3.0, 0.1 * i, -0.25, 1e-9 };
    metric->InsertNextTypedTuple(m);
  }
  grid->GetPointData()->AddArray(metric);
  return grid;
}

vtkUnstructuredGrid* ReadBack(amMeditReader* reader, const std::string& path, amTest::ErrorCatcher* errors)
{
  reader->SetFileName(path.c_str());
  errors->Watch(reader);
  reader->Update();
  return reader->GetOutput();
}
}

TEST(Medit, RoundTripKeepsEveryNumber)
{
  auto grid = TwoTets();
  const std::string path = amTest::TempPath("two.mesh");
  vtkNew<amMeditWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(path.c_str());
  writer->SetSolutionArrayName("Metric");
  ASSERT_EQ(writer->Write(), 1);
  ASSERT_TRUE(amTest::Exists(amTest::TempPath("two.sol")));

  vtkNew<amMeditReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  vtkUnstructuredGrid* back = ReadBack(reader, path, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  ASSERT_EQ(back->GetNumberOfPoints(), 5);
  for (vtkIdType i = 0; i < 5; ++i)
  {
    double a[3], b[3];
    grid->GetPoint(i, a);
    back->GetPoint(i, b);
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(a[d], b[d]) << "point " << i; // bit-exact
  }
  ASSERT_EQ(back->GetNumberOfCells(), 3);
  // Medit order: triangles before tetrahedra.
  EXPECT_EQ(back->GetCellType(0), VTK_TRIANGLE);
  EXPECT_EQ(back->GetCellType(1), VTK_TETRA);
  auto* region = vtkIntArray::SafeDownCast(back->GetCellData()->GetArray("Region"));
  ASSERT_NE(region, nullptr);
  EXPECT_EQ(region->GetValue(0), 56);
  EXPECT_EQ(region->GetValue(1), 5);
  EXPECT_EQ(region->GetValue(2), 6);
  vtkIdType npts;
  const vtkIdType* ids;
  back->GetCellPoints(2, npts, ids);
  EXPECT_EQ(ids[3], 4);
  auto* ref = vtkIntArray::SafeDownCast(back->GetPointData()->GetArray("Ref"));
  ASSERT_NE(ref, nullptr);
  EXPECT_EQ(ref->GetValue(4), 14);
  auto* metric = back->GetPointData()->GetArray("Metric");
  ASSERT_NE(metric, nullptr);
  ASSERT_EQ(metric->GetNumberOfComponents(), 6);
  for (vtkIdType i = 0; i < 5; ++i)
    for (int c = 0; c < 6; ++c)
      EXPECT_EQ(metric->GetComponent(i, c), grid->GetPointData()->GetArray("Metric")->GetComponent(i, c));
}

TEST(Medit, TetrahedraComeWithTheirInterfaceTriangles)
{
  // A 3 x 2 x 2 box of cubes, region 2 in the cubes with x > 1, region 1 elsewhere; a negative
  // tetrahedron among them (the faces must still face the right way).
  const int n[3] = { 3, 2, 2 };
  const double origin[3] = { 0, 0, 0 }, size[3] = { 3, 2, 2 };
  auto grid = amTest::BoxMesh(n, origin, size, [](const double* c) { return c[0] > 1 ? 2 : 1; });
  vtkIdType npts;
  const vtkIdType* ids;
  grid->GetCellPoints(0, npts, ids);
  const vtkIdType flipped[4] = { ids[0], ids[2], ids[1], ids[3] };
  grid->ReplaceCell(0, 4, flipped);
  const std::string path = amTest::TempPath("box.mesh");
  vtkNew<amMeditWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
  vtkNew<amMeditReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  vtkUnstructuredGrid* back = ReadBack(reader, path, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  // Boundary: 2 triangles per outer square (2 * (3*2 + 3*2 + 2*2) squares); interface x = 1: 2 * 4.
  std::map<int, int> count;
  std::map<int, double> flux; // divergence theorem: sum of x * n_x * area per reference
  vtkDataArray* region = back->GetCellData()->GetArray("Region");
  for (vtkIdType c = 0; c < back->GetNumberOfCells(); ++c)
  {
    if (back->GetCellType(c) != VTK_TRIANGLE)
      continue;
    const int ref = static_cast<int>(region->GetComponent(c, 0));
    ++count[ref];
    back->GetCellPoints(c, npts, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      back->GetPoint(ids[k], p[k]);
    const double nx = (p[1][1] - p[0][1]) * (p[2][2] - p[0][2]) - (p[1][2] - p[0][2]) * (p[2][1] - p[0][1]);
    flux[ref] += 0.5 * nx * (p[0][0] + p[1][0] + p[2][0]) / 3.0;
  }
  EXPECT_EQ(count[2001], 2 * 4); // the interface, once
  EXPECT_EQ(count[1000] + count[2000], 2 * 2 * (6 + 6 + 4));
  EXPECT_EQ(count.size(), 3u);
  // Region 2 (x in [1, 3], volume 8) is bounded by 2000 (outwards) and 2001 (from 2 into 1):
  // the integral of div(x e_x) = 1 over it is its volume.
  EXPECT_NEAR(flux[2000] + flux[2001], 8.0, 1e-12);
  EXPECT_NEAR(flux[1000] - flux[2001], 4.0, 1e-12); // region 1: 2001's normal points into it

  // Regions beyond 999 cannot be named: the tetrahedra are written, without triangles, and a warning.
  vtkDataArray* r = grid->GetCellData()->GetArray("Region");
  r->SetComponent(5, 0, 1234);
  r->Modified();
  vtkNew<amTest::ErrorCatcher> warnings;
  warnings->Watch(writer);
  writer->SetInputData(grid);
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_FALSE(warnings->Warnings.empty());
  reader->Modified();
  back = ReadBack(reader, path, errors);
  EXPECT_EQ(back->GetNumberOfCells(), grid->GetNumberOfCells());
  // And none when asked for none.
  r->SetComponent(5, 0, 2);
  r->Modified();
  writer->WriteInterfacesOff();
  writer->SetInputData(grid);
  ASSERT_EQ(writer->Write(), 1);
  reader->Modified();
  back = ReadBack(reader, path, errors);
  EXPECT_EQ(back->GetNumberOfCells(), grid->GetNumberOfCells());
}

TEST(Medit, MalformedFilesNameTheLine)
{
  struct Case
  {
    const char* Text;
    const char* Expect;
  };
  const Case cases[] = {
    { "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 1 1 0\nTriangles\n1\n1 2 3 7\nEnd\n",
      "line 9: Triangles #1 uses vertex 3 (the mesh has 2)" },
    { "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 x 1 0\n", "line 6: expected a vertex coordinate" },
    { "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n", "unexpected end of file" },
    { "MeshVersionFormatted 2\nDimension 3\nBananas\n3\n", "line 3: unknown or unsupported section 'Bananas'" },
    { "Dimension 3\nVertices\n1\n0 0 0 0\n", "no MeshVersionFormatted" },
    { "MeshVersionFormatted 2\nDimension 3\nVertices\n1\nnan 0 0 0\n", "non-finite" },
    { "", "no MeshVersionFormatted" },
    // Cut between two sections (before the tetrahedra): not a smaller valid mesh.
    { "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n0 1 0 0\nTriangles\n1\n1 2 3 7\n",
      "ends without its End keyword after the Triangles section" },
  };
  int k = 0;
  for (const Case& c : cases)
  {
    const std::string path = amTest::TempPath("bad" + std::to_string(k++) + ".mesh");
    std::ofstream(path) << c.Text;
    vtkNew<amMeditReader> reader;
    vtkNew<amTest::ErrorCatcher> errors;
    ReadBack(reader, path, errors);
    EXPECT_TRUE(errors->ErrorContains(path)) << errors->AllErrors();
    EXPECT_TRUE(errors->ErrorContains(c.Expect)) << "expected '" << c.Expect << "' in: " << errors->AllErrors();
  }
  vtkNew<amMeditReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  ReadBack(reader, "/no/such.mesh", errors);
  EXPECT_TRUE(errors->ErrorContains("'/no/such.mesh' does not exist")) << errors->AllErrors();
}

TEST(Medit, SolutionWithWrongCountIsRefused)
{
  const std::string mesh = amTest::TempPath("solcount.mesh"), sol = amTest::TempPath("solcount.sol");
  std::ofstream(mesh) << "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 1 1 0\nEnd\n";
  std::ofstream(sol) << "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n3\n1 1\n0.5\n0.25\n0.125\nEnd\n";
  vtkNew<amMeditReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  ReadBack(reader, mesh, errors);
  EXPECT_TRUE(errors->ErrorContains("SolAtVertices has 3 values for 2 vertices")) << errors->AllErrors();
}

TEST(Medit, WriterRefusesNaNAndUnsupportedCellsWithoutLeavingAFile)
{
  auto grid = TwoTets();
  grid->GetPoints()->SetPoint(2, std::nan(""), 0, 0);
  const std::string path = amTest::TempPath("nan.mesh");
  std::remove(path.c_str());
  vtkNew<amMeditWriter> writer;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(writer);
  writer->SetInputData(grid);
  writer->SetFileName(path.c_str());
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("point 2 has a non-finite coordinate")) << errors->AllErrors();
  EXPECT_FALSE(amTest::Exists(path));

  auto wedge = TwoTets();
  const vtkIdType w[6] = { 0, 1, 2, 3, 4, 0 };
  wedge->InsertNextCell(VTK_WEDGE, 6, w);
  errors->Errors.clear();
  writer->SetInputData(wedge);
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("cell 3 has VTK type 13")) << errors->AllErrors();
  EXPECT_FALSE(amTest::Exists(path));
}
