// amImageWriter: round trips through every format keep geometry (with a rotated direction) and
// every voxel; failures leave no file behind.
#include "amImageReader.h"
#include "amImageWriter.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkImageData> RotatedLabels()
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(4, 4, 5);
  src->Update();
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->DeepCopy(src->GetOutputDataObject(1));
  // A non-trivial direction: 90 degrees about z plus a flipped z axis, and a shifted origin.
  const double dir[9] = { 0, -1, 0, 1, 0, 0, 0, 0, -1 };
  img->SetDirectionMatrix(dir);
  img->SetOrigin(12.5, -40.25, 300.0);
  return img;
}
}

class ImageWriterRoundTrip : public ::testing::TestWithParam<const char*>
{
};

TEST_P(ImageWriterRoundTrip, KeepsGeometryAndEveryVoxel)
{
  auto img = RotatedLabels();
  const std::string path = amTest::TempPath(std::string("labels") + GetParam());
  std::remove(path.c_str());
  vtkNew<amImageWriter> writer;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(writer);
  writer->SetInputData(img);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1) << errors->AllErrors();

  vtkNew<amImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* back = reader->GetOutput();
  int d1[3], d2[3];
  img->GetDimensions(d1);
  back->GetDimensions(d2);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(d1[i], d2[i]);
    EXPECT_NEAR(img->GetSpacing()[i], back->GetSpacing()[i], 1e-5);
    EXPECT_NEAR(img->GetOrigin()[i], back->GetOrigin()[i], 1e-4);
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(img->GetDirectionMatrix()->GetElement(i, j), back->GetDirectionMatrix()->GetElement(i, j), 1e-6);
  }
  EXPECT_EQ(back->GetScalarType(), VTK_UNSIGNED_CHAR);
  vtkDataArray* a = img->GetPointData()->GetScalars();
  vtkDataArray* b = back->GetPointData()->GetScalars();
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  vtkIdType differ = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    differ += a->GetComponent(i, 0) != b->GetComponent(i, 0);
  EXPECT_EQ(differ, 0);
}

INSTANTIATE_TEST_SUITE_P(Formats, ImageWriterRoundTrip, ::testing::Values(".nii.gz", ".nii", ".mha", ".mhd", ".nrrd"));

TEST(ImageWriter, FailuresLeaveNoFile)
{
  auto img = RotatedLabels();
  vtkNew<amImageWriter> writer;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(writer);
  writer->SetInputData(img);

  const std::string bad = amTest::TempPath("labels.xyz");
  writer->SetFileName(bad.c_str());
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("unknown extension '.xyz'")) << errors->AllErrors();
  EXPECT_FALSE(amTest::Exists(bad));

  errors->Errors.clear();
  writer->SetFileName("/no/such/folder/labels.nii.gz");
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("does not exist")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkImageData> empty;
  writer->SetInputData(empty);
  writer->SetFileName(amTest::TempPath("empty.nii").c_str());
  EXPECT_EQ(writer->Write(), 0);
  EXPECT_TRUE(errors->ErrorContains("empty")) << errors->AllErrors();
}

TEST(ImageWriter, LabelNamesGoToATableBeside)
{
  // The phantom's label map has LabelNames: its NIfTI file gets "<name>.ctbl" beside it, one line
  // per label with a fixed colour; a CT (no names) gets none.
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(8, 8, 8);
  src->Update();
  const std::string path = amTest::TempPath("labels_with_names.nii.gz");
  const std::string table = amTest::TempPath("labels_with_names.ctbl");
  std::remove(table.c_str());
  vtkNew<amImageWriter> writer;
  writer->SetInputConnection(src->GetOutputPort(1));
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
  FILE* f = std::fopen(table.c_str(), "r");
  ASSERT_NE(f, nullptr);
  char line[256];
  std::vector<std::string> lines;
  while (std::fgets(line, sizeof(line), f))
    lines.emplace_back(line);
  std::fclose(f);
  ASSERT_EQ(lines.size(), 12u); // a comment, then labels 0..10
  EXPECT_EQ(lines[1], "0 Background 0 0 0 0\n");
  int value = -1, r = -1, g = -1, b = -1, a = -1;
  char name[64];
  ASSERT_EQ(std::sscanf(lines[6].c_str(), "%d %63s %d %d %d %d", &value, name, &r, &g, &b, &a), 6);
  EXPECT_EQ(value, 5);
  EXPECT_STREQ(name, "Myocardium");
  EXPECT_EQ(a, 255);
  EXPECT_GT(r + g + b, 0);
  // ITK-SNAP's label description beside it, the same colours: IDX R G B A VIS MSH "LABEL".
  f = std::fopen(amTest::TempPath("labels_with_names.itksnap.txt").c_str(), "r");
  ASSERT_NE(f, nullptr);
  std::vector<std::string> snap;
  while (std::fgets(line, sizeof(line), f))
    if (line[0] != '#')
      snap.emplace_back(line);
  std::fclose(f);
  ASSERT_EQ(snap.size(), 11u);
  int idx = -1, sr = -1, sg = -1, sb = -1, vis = -1, msh = -1;
  double alpha = -1;
  char label[64];
  ASSERT_EQ(
    std::sscanf(snap[5].c_str(), "%d %d %d %d %lf %d %d \"%63[^\"]\"", &idx, &sr, &sg, &sb, &alpha, &vis, &msh, label),
    8);
  EXPECT_EQ(idx, 5);
  EXPECT_EQ(std::vector<int>({ sr, sg, sb }), std::vector<int>({ r, g, b }));
  EXPECT_EQ(alpha, 1.0);
  EXPECT_EQ(vis, 1);
  EXPECT_STREQ(label, "Myocardium");
  EXPECT_NE(snap[0].find("\"Clear Label\""), std::string::npos);

  const std::string ct = amTest::TempPath("ct_without_names.nii.gz");
  std::remove(amTest::TempPath("ct_without_names.ctbl").c_str());
  writer->SetInputConnection(src->GetOutputPort(0));
  writer->SetFileName(ct.c_str());
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_FALSE(amTest::Exists(amTest::TempPath("ct_without_names.ctbl")));
  EXPECT_FALSE(amTest::Exists(amTest::TempPath("ct_without_names.itksnap.txt")));
}

TEST(ImageWriter, CompressionLevelKeepsTheVoxels)
{
  // A noisy CT at levels 1 and 9: the same voxels back, a smaller file at 9, a gzip stream either
  // way (nibabel and ITK read .nii.gz by its gzip magic), and no temporary left beside it.
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(4, 4, 4);
  src->SetNoiseStandardDeviation(20);
  src->Update();
  vtkImageData* ct = vtkImageData::SafeDownCast(src->GetOutputDataObject(0));
  const std::filesystem::path folder = amTest::TempPath("compression_levels");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  long long sizes[2] = { 0, 0 };
  const int levels[2] = { 1, 9 };
  for (int k = 0; k < 2; ++k)
  {
    const std::string path = (folder / ("ct_level" + std::to_string(levels[k]) + ".nii.gz")).string();
    vtkNew<amImageWriter> writer;
    EXPECT_EQ(writer->GetCompressionLevel(), 1);
    writer->SetInputData(ct);
    writer->SetFileName(path.c_str());
    writer->SetCompressionLevel(levels[k]);
    ASSERT_EQ(writer->Write(), 1);
    FILE* f = std::fopen(path.c_str(), "rb");
    ASSERT_NE(f, nullptr);
    unsigned char magic[2] = { 0, 0 };
    EXPECT_EQ(std::fread(magic, 1, 2, f), 2u);
    std::fseek(f, 0, SEEK_END);
    sizes[k] = std::ftell(f);
    std::fclose(f);
    EXPECT_EQ(magic[0], 0x1f);
    EXPECT_EQ(magic[1], 0x8b);

    vtkNew<amImageReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkDataArray* a = ct->GetPointData()->GetScalars();
    vtkDataArray* b = reader->GetOutput()->GetPointData()->GetScalars();
    ASSERT_NE(b, nullptr);
    ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      differ += a->GetComponent(i, 0) != b->GetComponent(i, 0);
    EXPECT_EQ(differ, 0) << "level " << levels[k];
  }
  EXPECT_LT(sizes[1], sizes[0]);
  // The two files and nothing else: the plain .nii written on the way is gone.
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, std::vector<std::string>({ "ct_level1.nii.gz", "ct_level9.nii.gz" }));
  vtkNew<amImageWriter> writer;
  writer->SetCompressionLevel(0);
  EXPECT_EQ(writer->GetCompressionLevel(), 1);
  writer->SetCompressionLevel(12);
  EXPECT_EQ(writer->GetCompressionLevel(), 9);
}
