// amGmshWriter: a two-region tetrahedral mesh written as Gmsh 4.1 and parsed back section by
// section (physical groups, entities, nodes, elements); bad input leaves no file.
#include "amGmshWriter.h"
#include "amTestMeshes.h"
#include "amTestUtilities.h"

#include "vtkCellData.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> TwoRegions()
{
  return amTest::TwoTetrahedra({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.1, 0.2, -1.0 / 3 } },
    { 0, 1, 2, 3 }, { 0, 2, 1, 4 }, 6, 3);
}

std::map<std::string, std::vector<std::string>> Sections(const std::string& path)
{
  std::ifstream in(path);
  std::map<std::string, std::vector<std::string>> s;
  std::string line, current;
  while (std::getline(in, line))
  {
    if (line.rfind("$End", 0) == 0)
      current.clear();
    else if (line[0] == '$')
      current = line.substr(1);
    else if (!current.empty())
      s[current].push_back(line);
  }
  return s;
}
}

TEST(GmshWriter, TwoRegionsAsPhysicalVolumes)
{
  const std::string path = amTest::TempPath("two.msh");
  vtkNew<amGmshWriter> w;
  w->SetInputData(TwoRegions());
  w->SetFileName(path.c_str());
  w->WriteInterfacesOff();
  ASSERT_EQ(w->Write(), 1);
  auto s = Sections(path);
  EXPECT_EQ(s["MeshFormat"], (std::vector<std::string>{ "4.1 0 8" }));
  EXPECT_EQ(s["PhysicalNames"], (std::vector<std::string>{ "2", "3 3 \"Region 3\"", "3 6 \"Region 6\"" }));
  ASSERT_EQ(s["Entities"].size(), 3u);
  EXPECT_EQ(s["Entities"][0], "0 0 0 2");
  EXPECT_EQ(s["Entities"][1].substr(0, 2), "3 ");
  EXPECT_NE(s["Entities"][1].find(" 1 3 0"), std::string::npos) << s["Entities"][1]; // physical tag 3
  // Nodes: header, block header, 5 tags, 5 coordinates that read back exactly.
  ASSERT_EQ(s["Nodes"].size(), 12u);
  EXPECT_EQ(s["Nodes"][0], "1 5 1 5");
  std::istringstream last(s["Nodes"][11]);
  double c[3];
  last >> c[0] >> c[1] >> c[2];
  EXPECT_EQ(c[0], 0.1);
  EXPECT_EQ(c[1], 0.2);
  EXPECT_EQ(c[2], -1.0 / 3);
  // Elements: one block per region (sorted by label), 1-based node tags, cell order kept as tags.
  EXPECT_EQ(s["Elements"], (std::vector<std::string>{ "2 2 1 2", "3 3 4 1", "2 1 3 2 5", "3 6 4 1", "1 1 2 3 4" }));
}

TEST(GmshWriter, PhysicalGroupsTakeTheLabelNames)
{
  // A mesh carrying its label map's LabelNames (indexed by label) names its groups after the
  // organs; a label without a name keeps "Region N".
  auto mesh = TwoRegions();
  vtkNew<vtkStringArray> names;
  names->SetName("LabelNames");
  for (const char* name : { "Background", "", "", "Right lung", "", "" })
    names->InsertNextValue(name);
  mesh->GetFieldData()->AddArray(names);
  const std::string path = amTest::TempPath("named.msh");
  vtkNew<amGmshWriter> w;
  w->SetInputData(mesh);
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  EXPECT_EQ(Sections(path)["PhysicalNames"],
    (std::vector<std::string>{ "5", "2 3000 \"Right lung | Outside\"", "2 6000 \"Region 6 | Outside\"",
      "2 6003 \"Region 6 | Right lung\"", "3 3 \"Right lung\"", "3 6 \"Region 6\"" }));
}

TEST(GmshWriter, InterfacesAndBoundaryAsPhysicalSurfaces)
{
  // Two tetrahedra on one face: the interface (one triangle, tag 1000 * 6 + 3) and each region's
  // outer boundary (three triangles, tags 6000 and 3000), numbered after the tetrahedra.
  const std::string path = amTest::TempPath("surfaces.msh");
  vtkNew<amGmshWriter> w;
  w->SetInputData(TwoRegions());
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  auto s = Sections(path);
  ASSERT_EQ(s["Entities"].size(), 6u);
  EXPECT_EQ(s["Entities"][0], "0 0 3 2");
  for (int i = 1; i <= 3; ++i)
    EXPECT_NE(s["Entities"][i].find(" 1 " + s["Entities"][i].substr(0, 4) + " 0"), std::string::npos)
      << s["Entities"][i];
  // Each volume lists its bounding surfaces (Gmsh's getBoundary), negative where the surface's
  // normal points into it: region 3 is the lower side of the interface 6003.
  EXPECT_NE(s["Entities"][4].find(" 1 3 2 3000 -6003"), std::string::npos) << s["Entities"][4];
  EXPECT_NE(s["Entities"][5].find(" 1 6 2 6000 6003"), std::string::npos) << s["Entities"][5];
  ASSERT_GE(s["Elements"].size(), 1u);
  EXPECT_EQ(s["Elements"][0], "5 9 1 9");
  std::map<std::string, int> blocks; // "dim tag" -> element count
  for (size_t i = 1; i < s["Elements"].size();)
  {
    std::istringstream in(s["Elements"][i]);
    int dim, tag, type, count;
    ASSERT_TRUE(in >> dim >> tag >> type >> count) << s["Elements"][i];
    blocks[std::to_string(dim) + " " + std::to_string(tag)] = count;
    i += 1 + count;
  }
  EXPECT_EQ(blocks,
    (std::map<std::string, int>{ { "2 3000", 3 }, { "2 6000", 3 }, { "2 6003", 1 }, { "3 3", 1 }, { "3 6", 1 } }));
  // The interface's triangle is the shared face, its normal from region 6 into region 3.
  const auto at = std::find(s["Elements"].begin(), s["Elements"].end(), "2 6003 2 1");
  ASSERT_NE(at, s["Elements"].end());
  std::istringstream tri(*(at + 1));
  int tag, a, b, c;
  tri >> tag >> a >> b >> c;
  EXPECT_GE(tag, 3);
  std::vector<int> face = { a, b, c };
  std::sort(face.begin(), face.end());
  EXPECT_EQ(face, (std::vector<int>{ 1, 2, 3 }));
}

TEST(GmshWriter, BadInputLeavesNoFile)
{
  auto check = [](vtkUnstructuredGrid* g, const char* name, const char* expected) {
    const std::string path = amTest::TempPath(name);
    std::remove(path.c_str());
    vtkNew<amGmshWriter> w;
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(w);
    errors->Watch(w->GetExecutive());
    w->SetInputData(g);
    w->SetFileName(path.c_str());
    EXPECT_EQ(w->Write(), 0);
    EXPECT_NE(errors->AllErrors().find(expected), std::string::npos) << errors->AllErrors();
    EXPECT_NE(errors->AllErrors().find(name), std::string::npos) << errors->AllErrors();
    EXPECT_FALSE(amTest::Exists(path));
  };
  auto zero = TwoRegions();
  vtkIntArray::SafeDownCast(zero->GetCellData()->GetArray("Region"))->SetValue(1, 0);
  check(zero, "zero.msh", "positive");
  auto mixed = TwoRegions();
  const vtkIdType tri[3] = { 0, 1, 2 };
  mixed->InsertNextCell(VTK_TRIANGLE, 3, tri);
  vtkIntArray::SafeDownCast(mixed->GetCellData()->GetArray("Region"))->InsertNextValue(1);
  check(mixed, "mixed.msh", "only tetrahedra");
  auto nan = TwoRegions();
  nan->GetPoints()->SetPoint(4, 0, std::nan(""), 0);
  check(nan, "nan.msh", "non-finite");
  vtkNew<vtkUnstructuredGrid> empty;
  check(empty, "empty.msh", "no tetrahedra");
}
