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

#include <cstdio>

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
