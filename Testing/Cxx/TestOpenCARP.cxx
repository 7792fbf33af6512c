// amOpenCARPWriter and amOpenCARPReader: a mesh with an unused point, regions, fibres and sheets and
// a tagged surface written as openCARP files, parsed by hand and read back identically; bad input
// leaves no file.
#include "amOpenCARPReader.h"
#include "amOpenCARPWriter.h"
#include "amTestMeshes.h"
#include "amTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Two tetrahedra on five points and a sixth point no tetrahedron uses (as a mesher may leave).
vtkSmartPointer<vtkUnstructuredGrid> Mesh()
{
  auto g =
    amTest::TwoTetrahedra({ { 0, 0, 0 }, { 9, 9, 9 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.1, 0.2, -1.0 / 3 } },
      { 0, 2, 3, 4 }, { 0, 3, 2, 5 }, 5, 1);
  vtkNew<vtkDoubleArray> f, s;
  f->SetName("Fibers");
  s->SetName("Sheets");
  f->SetNumberOfComponents(3);
  s->SetNumberOfComponents(3);
  f->InsertNextTuple3(0.6, 0.8, 0);
  f->InsertNextTuple3(0, 0, 0);
  s->InsertNextTuple3(0, 0, 1);
  s->InsertNextTuple3(0, 0, 0);
  g->GetCellData()->AddArray(f);
  g->GetCellData()->AddArray(s);
  return g;
}

vtkSmartPointer<vtkPolyData> Surface()
{
  auto s = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> p;
  const double x[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  for (const auto& q : x)
    p->InsertNextPoint(q);
  s->SetPoints(p);
  s->AllocateEstimate(1, 3);
  const vtkIdType t[3] = { 0, 1, 2 };
  s->InsertNextCell(VTK_TRIANGLE, 3, t);
  vtkNew<vtkIntArray> tag;
  tag->SetName("VentricularTag");
  tag->InsertNextValue(3);
  s->GetCellData()->AddArray(tag);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("InputPointId");
  for (vtkIdType v : { 2, 3, 4 })
    ids->InsertNextValue(v);
  s->GetPointData()->AddArray(ids);
  vtkNew<vtkStringArray> names;
  names->SetName("TagNames");
  names->InsertNextValue("3 Epicardium");
  s->GetFieldData()->AddArray(names);
  return s;
}

std::vector<std::string> LinesOf(const std::string& path)
{
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}
}

TEST(OpenCARP, WritesEveryFileAndReadsItBack)
{
  const std::string base = amTest::TempPath("opencarp_mesh");
  vtkNew<amOpenCARPWriter> writer;
  writer->SetInputData(Mesh());
  writer->SetSurfacesData(Surface());
  writer->SetFileName((base + ".pts").c_str());
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(writer->GetWrittenFiles().size(), 5u);

  // The unused point is left out: five points, numbered in their order, in micrometres.
  const auto pts = LinesOf(base + ".pts");
  ASSERT_EQ(pts.size(), 6u);
  EXPECT_EQ(pts[0], "5");
  EXPECT_EQ(pts[2], "1000 0 0");
  const auto elem = LinesOf(base + ".elem");
  ASSERT_EQ(elem.size(), 3u);
  EXPECT_EQ(elem[1], "Tt 0 1 2 3 5");
  EXPECT_EQ(elem[2], "Tt 0 2 1 4 1");
  const auto lon = LinesOf(base + ".lon");
  ASSERT_EQ(lon.size(), 3u);
  EXPECT_EQ(lon[0], "2");
  EXPECT_EQ(lon[1], "0.6 0.8 0 0 0 1");
  const auto surf = LinesOf(base + ".Epicardium.surf");
  ASSERT_EQ(surf.size(), 2u);
  EXPECT_EQ(surf[1], "Tr 1 2 3");
  const auto vtx = LinesOf(base + ".Epicardium.vtx");
  ASSERT_EQ(vtx.size(), 5u);
  EXPECT_EQ(vtx[1], "intra");

  vtkNew<amOpenCARPReader> reader;
  reader->SetFileName(base.c_str());
  reader->Update();
  vtkUnstructuredGrid* back = reader->GetOutput();
  ASSERT_EQ(back->GetNumberOfPoints(), 5);
  ASSERT_EQ(back->GetNumberOfCells(), 2);
  auto original = Mesh();
  const vtkIdType kept[5] = { 0, 2, 3, 4, 5 };
  for (vtkIdType i = 0; i < 5; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(back->GetPoint(i)[c], original->GetPoint(kept[i])[c], 1e-15) << i;
  EXPECT_EQ(back->GetCellData()->GetArray("Region")->GetComponent(1, 0), 1);
  EXPECT_DOUBLE_EQ(back->GetCellData()->GetArray("Fibers")->GetComponent(0, 1), 0.8);
  EXPECT_DOUBLE_EQ(back->GetCellData()->GetArray("Sheets")->GetComponent(0, 2), 1.0);
  for (const auto& f : writer->GetWrittenFiles())
    std::remove(f.c_str());
}

TEST(OpenCARP, BadInputLeavesNoFile)
{
  const std::string base = amTest::TempPath("opencarp_bad");
  auto mesh = Mesh();
  mesh->GetPoints()->SetPoint(2, std::nan(""), 0, 0);
  vtkNew<amOpenCARPWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(base.c_str());
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(writer);
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("point 2 has a non-finite coordinate")) << errors->AllErrors();
  EXPECT_FALSE(amTest::Exists(base + ".pts"));

  // A reader given an element of another kind, or a node out of range, says which line.
  {
    std::ofstream p(base + ".pts");
    p << "4\n0 0 0\n1000 0 0\n0 1000 0\n0 0 1000\n";
    std::ofstream e(base + ".elem");
    e << "1\nTt 0 1 2 7 1\n";
  }
  vtkNew<amOpenCARPReader> reader;
  reader->SetFileName(base.c_str());
  vtkNew<amTest::ErrorCatcher> readErrors;
  readErrors->Watch(reader);
  reader->Update();
  EXPECT_TRUE(readErrors->ErrorContains(".elem' line 2: node 7 is not one of the 4 points")) << readErrors->AllErrors();
  std::remove((base + ".pts").c_str());
  std::remove((base + ".elem").c_str());
}
