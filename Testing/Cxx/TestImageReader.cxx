// amImageReader on every real volume of ../shared/data (header facts from each SOURCE.md), on the
// DICOM edge cases, and on broken input.
#include "amImageReader.h"
#include "amIntensityWindow.h"
#include "amTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

namespace
{
struct Expected
{
  const char* File;
  int Dims[3];
  double Spacing[3];
  int ScalarType;
  double Range[2];
  const char* Orientation;
};

vtkImageData* Read(amImageReader* reader, const std::string& path, amTest::ErrorCatcher* errors = nullptr)
{
  reader->SetFileName(path.c_str());
  if (errors)
    errors->Watch(reader);
  reader->Update();
  return reader->GetOutput();
}

std::string FieldString(vtkImageData* img, const char* name)
{
  auto* a = vtkStringArray::SafeDownCast(img->GetFieldData()->GetAbstractArray(name));
  return a && a->GetNumberOfValues() ? a->GetValue(0) : std::string();
}

void CheckHeader(const Expected& e)
{
  const std::string path = amTest::SharedData(e.File);
  if (path.empty())
    GTEST_SKIP() << "shared data '" << e.File << "' is absent";
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  vtkImageData* img = Read(reader, path, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  int dims[3];
  img->GetDimensions(dims);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(dims[i], e.Dims[i]) << e.File << " axis " << i;
    EXPECT_NEAR(img->GetSpacing()[i], e.Spacing[i], 2e-3) << e.File << " axis " << i;
  }
  EXPECT_EQ(img->GetScalarType(), e.ScalarType) << e.File;
  double range[2];
  img->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_DOUBLE_EQ(range[0], e.Range[0]) << e.File;
  EXPECT_DOUBLE_EQ(range[1], e.Range[1]) << e.File;
  EXPECT_EQ(FieldString(img, "SourceOrientation"), e.Orientation) << e.File;
  EXPECT_FALSE(FieldString(img, "Provenance").empty());
}
}

// Facts from the SOURCE.md files (nibabel/pydicom readings of the same files).
TEST(ImageReader, CardiacCTNIfTI)
{
  CheckHeader({ "totalseg_cardiac_ct/aorta_report/ct_cropped.nii.gz", { 120, 126, 164 }, { 1.5, 1.5, 1.5 }, VTK_SHORT,
    { -1078, 3343 }, "LPS" });
}
TEST(ImageReader, CardiacMasks)
{
  CheckHeader({ "totalseg_cardiac_ct/aorta_report/aorta.nii.gz", { 120, 126, 164 }, { 1.5, 1.5, 1.5 },
    VTK_UNSIGNED_CHAR, { 0, 1 }, "LPS" });
  CheckHeader({ "totalseg_cardiac_ct/pulmonary_report/heart.nii.gz", { 233, 167, 191 }, { 1.5, 1.5, 1.5 },
    VTK_UNSIGNED_CHAR, { 0, 1 }, "LPS" });
  CheckHeader({ "totalseg_cardiac_ct/pulmonary_report/ct_cropped.nii.gz", { 122, 102, 112 }, { 1.5, 1.5, 1.5 },
    VTK_SHORT, { -1064, 3343 }, "LPS" });
}
TEST(ImageReader, ChestCTMetaImage)
{
  CheckHeader({ "lidc_chest_ct_vtkjs/LIDC2.mha", { 256, 256, 133 }, { 1.40625, 1.40625, 2.5 }, VTK_UNSIGNED_CHAR,
    { 0, 255 }, "LAI" });
}
TEST(ImageReader, AbdomenNIfTI)
{
  CheckHeader({ "totalseg_abdomen_ct_labels/example_ct.nii.gz", { 122, 101, 112 }, { 3, 3, 3 }, VTK_INT,
    { -1207, 3382 }, "RAS" });
  CheckHeader({ "totalseg_abdomen_ct_labels/example_ct_sm.nii.gz", { 122, 101, 30 }, { 3, 3, 3 }, VTK_SHORT,
    { -1100, 1207 }, "RAS" });
  CheckHeader({ "totalseg_abdomen_ct_labels/example_seg.nii.gz", { 122, 101, 30 }, { 3, 3, 3 }, VTK_UNSIGNED_CHAR,
    { 0, 117 }, "RAS" });
  CheckHeader({ "totalseg_abdomen_ct_labels/example_seg_dicom.nii.gz", { 512, 512, 20 }, { 0.9766, 0.9766, 2.0 },
    VTK_UNSIGNED_CHAR, { 0, 117 }, "LAS" });
}
TEST(ImageReader, TorsoLabelsAnisotropic)
{
  CheckHeader({ "niivue_torso_labels/torsoLabel.nii.gz", { 384, 320, 89 }, { 0.782, 0.782, 5.0 }, VTK_UNSIGNED_CHAR,
    { 0, 11 }, "RAS" });
}
TEST(ImageReader, FrogMetaImageCompressed)
{
  CheckHeader(
    { "vtk_frog_tissue_labels/frogtissue.mhd", { 500, 470, 136 }, { 1, 1, 1.5 }, VTK_UNSIGNED_CHAR, { 0, 29 }, "LPS" });
}
TEST(ImageReader, FrogUnderstatedCompressedSizeIsRepaired)
{
  // The header says CompressedDataSize 260020; the stream has 262087 bytes. ITK alone inflates
  // the shorter part and leaves the last ~1 M voxels undefined. Figures from an independent
  // zlib inflate of the .zraw: sum of all voxels, voxels of label 13 (skeleton) overall and in
  // the last million.
  AM_REQUIRE_SHARED(path, amTest::FrogLabels);
  vtkNew<amTest::ErrorCatcher> messages;
  vtkNew<amImageReader> reader;
  messages->Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  ASSERT_FALSE(messages->HasError()) << messages->AllErrors();
  ASSERT_EQ(messages->Warnings.size(), 1u);
  EXPECT_NE(messages->Warnings[0].find("CompressedDataSize"), std::string::npos);
  vtkDataArray* v = reader->GetOutput()->GetPointData()->GetScalars();
  long long sum = 0, skeleton = 0, skeletonTail = 0;
  const vtkIdType n = v->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int x = static_cast<int>(v->GetComponent(i, 0));
    sum += x;
    skeleton += x == 13;
    skeletonTail += x == 13 && i >= n - 1000000;
  }
  EXPECT_EQ(sum, 12279472);
  EXPECT_EQ(skeleton, 440722);
  EXPECT_EQ(skeletonTail, 2721);
}
TEST(ImageReader, TruncatedCompressedStreamIsAnError)
{
  AM_REQUIRE_SHARED(zraw, "vtk_frog_tissue_labels/frogtissue.zraw");
  std::ifstream in(zraw, std::ios::binary);
  std::vector<char> head(100000);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const std::string data = amTest::TempPath("cut.zraw"), header = amTest::TempPath("cut.mhd");
  std::ofstream(data, std::ios::binary).write(head.data(), static_cast<std::streamsize>(head.size()));
  std::ofstream(header) << "ObjectType = Image\nNDims = 3\nBinaryData = True\nCompressedData = True\n"
                           "ElementSpacing = 1 1 1.5\nDimSize = 500 470 136\nElementType = MET_UCHAR\n"
                           "ElementDataFile = cut.zraw\n";
  vtkNew<amTest::ErrorCatcher> messages;
  vtkNew<amImageReader> reader;
  messages->Watch(reader);
  reader->SetFileName(header.c_str());
  reader->Update();
  EXPECT_TRUE(messages->ErrorContains("inflates to")) << messages->AllErrors();
  EXPECT_TRUE(messages->ErrorContains("cut.zraw")) << messages->AllErrors();
}
TEST(ImageReader, HeadMRMetaImage)
{
  CheckHeader(
    { "vtk_head_mr_volume/HeadMRVolume.mhd", { 48, 62, 42 }, { 4, 4, 4 }, VTK_UNSIGNED_CHAR, { 0, 255 }, "LPS" });
}
TEST(ImageReader, HeadCTNrrdSliceStack)
{
  CheckHeader({ "vtk_headsq_ct/quarter.nhdr", { 64, 64, 93 }, { 3.2, 3.2, 1.5 }, VTK_SHORT, { 0, 3926 }, "LPS" });
}

TEST(ImageReader, DicomSeriesJpeg2000InHounsfieldUnits)
{
  AM_REQUIRE_SHARED(folder, "totalseg_abdomen_ct_labels/example_ct_dicom");
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  vtkImageData* img = Read(reader, folder, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  int dims[3];
  img->GetDimensions(dims);
  EXPECT_EQ(dims[0], 512);
  EXPECT_EQ(dims[1], 512);
  EXPECT_EQ(dims[2], 20);
  EXPECT_NEAR(img->GetSpacing()[0], 0.9766, 1e-3);
  EXPECT_NEAR(img->GetSpacing()[2], 2.0, 1e-6);
  double range[2];
  img->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_DOUBLE_EQ(range[0], -1024.0); // rescale intercept -1024 applied
  EXPECT_DOUBLE_EQ(range[1], 1839.0);
  EXPECT_EQ(FieldString(img, "SourceFormat"), "DICOM");
  EXPECT_EQ(FieldString(img, "Modality"), "CT");

  // The NIfTI label map made from this series covers the same physical box (direction kept).
  AM_REQUIRE_SHARED(segPath, "totalseg_abdomen_ct_labels/example_seg_dicom.nii.gz");
  vtkNew<amImageReader> segReader;
  vtkImageData* seg = Read(segReader, segPath);
  double b1[6], b2[6];
  img->GetBounds(b1); // with direction: physical bounds
  seg->GetBounds(b2);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(b1[i], b2[i], 0.05) << "bound " << i;
}

TEST(ImageReader, DicomFolderOfTwoSeriesIsRefusedWithTheSeriesListed)
{
  // The abdomen series and the tilted head series side by side in one folder.
  AM_REQUIRE_SHARED(abdomen, "totalseg_abdomen_ct_labels/example_ct_dicom");
  AM_REQUIRE_SHARED(head, "dcm_qa_ct_ge_head_tilt");
  const std::string folder = amTest::TempPath("two_series");
  vtksys::SystemTools::RemoveADirectory(folder);
  vtksys::SystemTools::MakeDirectory(folder);
  int n = 0;
  for (const std::string& from : { abdomen, head })
  {
    vtksys::Directory dir;
    dir.Load(from);
    for (unsigned long i = 0; i < dir.GetNumberOfFiles(); ++i)
    {
      const std::string name = dir.GetFile(i);
      if (name != "." && name != "..")
        vtksys::SystemTools::CopyAFile(from + "/" + name, folder + "/" + std::to_string(n++) + ".dcm");
    }
  }
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  Read(reader, folder, errors);
  ASSERT_TRUE(errors->HasError());
  EXPECT_TRUE(errors->ErrorContains("holds 2 series; set SeriesUID")) << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains(": 20 files, e.g.")) << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains(": 28 files, e.g.")) << errors->AllErrors();

  // Named by one of its files, the abdomen series reads as it does alone.
  vtkNew<amImageReader> named;
  vtkNew<amTest::ErrorCatcher> quiet;
  vtkImageData* img = Read(named, folder + "/0.dcm", quiet);
  ASSERT_FALSE(quiet->HasError()) << quiet->AllErrors();
  EXPECT_EQ(img->GetDimensions()[2], 20);
}

TEST(ImageReader, DicomTiltAndUnevenGapsAreRefusedPrecisely)
{
  AM_REQUIRE_SHARED(folder, "dcm_qa_ct_ge_head_tilt");
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  reader->SetFileName(folder.c_str());
  errors->Watch(reader);
  reader->Update();
  ASSERT_TRUE(errors->HasError());
  EXPECT_TRUE(errors->ErrorContains("gantry tilt of 18.5")) << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains("uneven")) << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains("ResampleIrregularSeries")) << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains(folder)) << errors->AllErrors();
}

TEST(ImageReader, DicomTiltResampledOntoARegularGrid)
{
  AM_REQUIRE_SHARED(folder, "dcm_qa_ct_ge_head_tilt");
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  reader->SetResampleIrregularSeries(true);
  reader->SetOutputSliceSpacing(2.0);
  vtkImageData* img = Read(reader, folder, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  int dims[3];
  img->GetDimensions(dims);
  EXPECT_EQ(dims[0] >= 512 && dims[1] >= 512, true);
  EXPECT_NEAR(img->GetSpacing()[2], 2.0, 1e-9);
  EXPECT_NEAR(img->GetSpacing()[0], 0.4882812, 1e-6);
  // The grid follows the slices: its third axis is the slice normal (0, 0.3173, 0.9483).
  vtkMatrix3x3* d = img->GetDirectionMatrix();
  EXPECT_NEAR(d->GetElement(1, 2), 0.3173, 1e-3);
  EXPECT_NEAR(d->GetElement(2, 2), 0.9483, 1e-3);
  double range[2];
  img->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_GE(range[0], -1500.0);
  EXPECT_LE(range[1], 2121.0);
  EXPECT_FALSE(FieldString(img, "Resampling").empty());
}

TEST(ImageReader, BrokenInputGivesClearErrors)
{
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(reader);

  reader->Update();
  EXPECT_TRUE(errors->ErrorContains("No FileName")) << errors->AllErrors();

  errors->Errors.clear();
  reader->SetFileName("/no/such/scan.nii.gz");
  reader->Update();
  EXPECT_TRUE(errors->ErrorContains("'/no/such/scan.nii.gz' does not exist")) << errors->AllErrors();

  const std::string empty = amTest::TempPath("empty.nii");
  std::ofstream(empty).close();
  errors->Errors.clear();
  reader->SetFileName(empty.c_str());
  reader->Update();
  EXPECT_TRUE(errors->ErrorContains(empty)) << errors->AllErrors();

  const std::string garbage = amTest::TempPath("garbage.mha");
  std::ofstream(garbage) << "this is not an image\nNDims = banana\n";
  errors->Errors.clear();
  reader->SetFileName(garbage.c_str());
  reader->Update();
  EXPECT_TRUE(errors->ErrorContains(garbage)) << errors->AllErrors();

  const std::string noDicom = amTest::TempPath("no_dicom_here");
  ::mkdir(noDicom.c_str(), 0755);
  errors->Errors.clear();
  reader->SetFileName(noDicom.c_str());
  reader->Update();
  EXPECT_TRUE(errors->ErrorContains("No DICOM series")) << errors->AllErrors();
}

TEST(ImageReader, TruncatedFileIsAnErrorNotGarbage)
{
  AM_REQUIRE_SHARED(path, "vtk_head_mr_volume/HeadMRVolume.mhd");
  // Copy the header and half of the raw data.
  const std::string dir = amTest::TempPath("");
  std::ifstream h(path);
  std::string header((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
  std::ofstream(dir + "HeadMRVolume.mhd") << header;
  std::ifstream raw(amTest::SharedData("vtk_head_mr_volume/HeadMRVolume.raw"), std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(raw)), std::istreambuf_iterator<char>());
  std::ofstream(dir + "HeadMRVolume.raw", std::ios::binary).write(bytes.data(), bytes.size() / 2);
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  Read(reader, dir + "HeadMRVolume.mhd", errors);
  EXPECT_TRUE(errors->ErrorContains("HeadMRVolume.mhd")) << errors->AllErrors();
}

TEST(ImageReader, TheWindowOfAnEightBitScanIsCarriedOnTheImage)
{
  AM_REQUIRE_SHARED(path, "lidc_chest_ct_vtkjs/LIDC2.mha");
  vtkNew<amImageReader> reader;
  vtkNew<amTest::ErrorCatcher> errors;
  vtkImageData* img = Read(reader, path, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  double window[2] = { -1, -1 };
  EXPECT_FALSE(amIntensityWindow::Of(img, window)); // not stated: none recorded
  reader->SetIntensityWindow(600, 300);
  img = Read(reader, path, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  ASSERT_TRUE(amIntensityWindow::Of(img, window));
  EXPECT_EQ(window[0], 600.0);
  EXPECT_EQ(window[1], 300.0);
  EXPECT_NE(FieldString(img, "Provenance").find("IntensityWindow=600,300"), std::string::npos);
  // 100 HU of that window are 42.5 of its units; 0 HU, its floor, reads 0.
  EXPECT_DOUBLE_EQ(amIntensityWindow::Width(window, 100.0), 42.5);
  EXPECT_DOUBLE_EQ(amIntensityWindow::Level(window, 0.0), 0.0);
  // Not a window, and a window stated for a scan in HU: clear errors, no output.
  reader->SetIntensityWindow(-5, 40);
  Read(reader, path, errors);
  EXPECT_TRUE(errors->ErrorContains("is not a window")) << errors->AllErrors();
  errors->Errors.clear();
  const std::string hu = amTest::SharedData("totalseg_cardiac_ct/aorta_report/ct_cropped.nii.gz");
  if (hu.empty())
    return;
  reader->SetIntensityWindow(400, 40);
  Read(reader, hu, errors);
  EXPECT_TRUE(errors->ErrorContains("holds 0..255 made through a window, but its values span -1078 .. 3343"))
    << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains(hu)) << errors->AllErrors();
}
