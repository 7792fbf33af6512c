// amXdmfWriter: a two-region mesh (and an unused point) written with its heavy data in HDF5 and inline;
// the HDF5 datasets read back through HDF5's C library, the same bytes on a second write, bad input no file.
#include "amTestMeshes.h"
#include "amTestUtilities.h"
#include "amXdmfWriter.h"

#include "vtkCellData.h"
#include "vtkExecutive.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <vector>

namespace
{
/// TestGmshWriter's two regions, after a point no tetrahedron uses.
vtkSmartPointer<vtkUnstructuredGrid> TwoRegionsAndAnUnusedPoint()
{
  return amTest::TwoTetrahedra(
    { { 9, 9, 9 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.1, 0.2, -1.0 / 3 } }, { 1, 2, 3, 4 },
    { 1, 3, 2, 5 }, 6, 3);
}

std::string Text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A dataset of the file as int64 or double values, and its dimensions.
template<typename T>
std::vector<T> Dataset(const std::string& file, const std::string& name, std::vector<hsize_t>& dims)
{
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  const hid_t s = H5Dget_space(d);
  dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(s)), 0);
  H5Sget_simple_extent_dims(s, dims.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t k : dims)
    n *= k;
  std::vector<T> values(n);
  H5Dread(d, std::is_same<T, double>::value ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT,
    values.data());
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return values;
}
}

TEST(XdmfWriter, HeavyDataInHdf5ReadsBack)
{
  const std::string path = amTest::TempPath("xdmf_two.xdmf");
  vtkNew<amXdmfWriter> w;
  EXPECT_EQ(w->GetHeavyDataFormat(), amXdmfWriter::HDF5);
  w->SetInputData(TwoRegionsAndAnUnusedPoint());
  w->SetFileName(path.c_str());
  ASSERT_EQ(w->Write(), 1);
  const std::string xdmf = Text(path);
  EXPECT_NE(xdmf.find("Format=\"HDF\">xdmf_two.h5:/topology</DataItem>"), std::string::npos) << xdmf;
  EXPECT_NE(xdmf.find("Format=\"HDF\">xdmf_two.h5:/cell_tags</DataItem>"), std::string::npos) << xdmf;
  std::vector<hsize_t> dims;
  // The unused point 0 is left out and the others renumbered in order.
  EXPECT_EQ(Dataset<std::int64_t>(amTest::TempPath("xdmf_two.h5"), "/topology", dims),
    (std::vector<std::int64_t>{ 0, 1, 2, 3, 0, 2, 1, 4 }));
  EXPECT_EQ(dims, (std::vector<hsize_t>{ 2, 4 }));
  const std::vector<double> xyz = Dataset<double>(amTest::TempPath("xdmf_two.h5"), "/geometry", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{ 5, 3 }));
  EXPECT_EQ(xyz[3], 1.0);
  EXPECT_EQ(xyz[14], -1.0 / 3);
  EXPECT_EQ(
    Dataset<std::int64_t>(amTest::TempPath("xdmf_two.h5"), "/cell_tags", dims), (std::vector<std::int64_t>{ 6, 3 }));
  // The facets: the interface 6 | 3 once, and the outer faces of each region (tag 1000 x region).
  const std::vector<std::int64_t> tags =
    Dataset<std::int64_t>(amTest::TempPath("xdmf_two_facets.h5"), "/facet_tags", dims);
  EXPECT_EQ(tags.size(), 7u);
  EXPECT_EQ(std::count(tags.begin(), tags.end(), 6003), 1);
  EXPECT_EQ(std::count(tags.begin(), tags.end(), 6000), 3);
  EXPECT_EQ(std::count(tags.begin(), tags.end(), 3000), 3);
  // The same bytes on a second write (HDF5 records no times here).
  const std::string first = Text(amTest::TempPath("xdmf_two.h5"));
  ASSERT_EQ(w->Write(), 1);
  EXPECT_EQ(Text(amTest::TempPath("xdmf_two.h5")), first);
}

TEST(XdmfWriter, InlineTextIsOneSelfContainedFile)
{
  const std::string path = amTest::TempPath("xdmf_inline.xdmf");
  std::remove(amTest::TempPath("xdmf_inline.h5").c_str());
  vtkNew<amXdmfWriter> w;
  w->SetInputData(TwoRegionsAndAnUnusedPoint());
  w->SetFileName(path.c_str());
  w->SetHeavyDataFormat(amXdmfWriter::XML);
  ASSERT_EQ(w->Write(), 1);
  const std::string xdmf = Text(path);
  EXPECT_NE(xdmf.find("Format=\"XML\">\n0 1 2 3\n0 2 1 4\n"), std::string::npos) << xdmf;
  EXPECT_NE(xdmf.find("0.1 0.2 -0.3333333333333333\n"), std::string::npos) << xdmf;
  EXPECT_FALSE(amTest::Exists(amTest::TempPath("xdmf_inline.h5")));
}

TEST(XdmfWriter, NonTetrahedraAreRefusedWithoutAFile)
{
  auto g = TwoRegionsAndAnUnusedPoint();
  const vtkIdType tri[3] = { 1, 2, 3 };
  g->InsertNextCell(VTK_TRIANGLE, 3, tri);
  g->GetCellData()->GetArray("Region")->InsertNextTuple1(1);
  const std::string path = amTest::TempPath("xdmf_bad.xdmf");
  std::remove(path.c_str());
  vtkNew<amXdmfWriter> w;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(w);
  errors->Watch(w->GetExecutive());
  w->SetInputData(g);
  w->SetFileName(path.c_str());
  EXPECT_EQ(w->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("only tetrahedra are written")) << errors->AllErrors();
  EXPECT_FALSE(amTest::Exists(path));
  EXPECT_FALSE(amTest::Exists(amTest::TempPath("xdmf_bad.h5")));
}
