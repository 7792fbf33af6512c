// Morphology cleaning on label maps with known answers.
#include "amMorphologyCleaning.h"
#include "amTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <functional>

namespace
{
// A 40x40x40 map (spacing s): label 1 fills a box, label 2 a sphere inside it, plus noise blobs.
vtkSmartPointer<vtkImageData> Map(double sx = 1, double sy = 1, double sz = 1)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(40, 40, 40);
  img->SetSpacing(sx, sy, sz);
  img->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* a = vtkUnsignedCharArray::SafeDownCast(img->GetPointData()->GetScalars());
  a->SetName("Labels");
  for (int k = 0; k < 40; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
      {
        unsigned char v = 0;
        if (i >= 5 && i < 35 && j >= 5 && j < 35 && k >= 5 && k < 35)
          v = 1;
        if ((i - 20) * (i - 20) + (j - 20) * (j - 20) + (k - 20) * (k - 20) <= 64)
          v = 2;
        a->SetValue((k * 40 + j) * 40 + i, v);
      }
  return img;
}

unsigned char& At(vtkImageData* img, int i, int j, int k)
{
  return vtkUnsignedCharArray::SafeDownCast(img->GetPointData()->GetScalars())->GetPointer(0)[(k * 40 + j) * 40 + i];
}

long Count(vtkImageData* img, int label)
{
  auto* a = vtkUnsignedCharArray::SafeDownCast(img->GetPointData()->GetScalars());
  long c = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    c += a->GetValue(i) == label;
  return c;
}

vtkImageData* Clean(amMorphologyCleaning* f, vtkImageData* in, amTest::ErrorCatcher* errors = nullptr)
{
  f->SetInputData(in);
  if (errors)
    errors->Watch(f);
  f->Update();
  return f->GetOutput();
}
}

TEST(MorphologyCleaning, SmallComponentsGoLargeOnesStayAndNoVoxelIsLost)
{
  auto img = Map();
  // Speckles: three single voxels of label 2 inside label 1, a 2x2x2 blob of label 3 in label 1,
  // and a 5x5x5 block of label 3 (125 mm^3) in the background.
  At(img, 8, 8, 8) = 2;
  At(img, 30, 8, 9) = 2;
  At(img, 9, 30, 30) = 2;
  for (int k = 10; k < 12; ++k)
    for (int j = 10; j < 12; ++j)
      for (int i = 28; i < 30; ++i)
        At(img, i, j, k) = 3;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i)
        At(img, i, j, 35 + k) = 3;
  const long before1 = Count(img, 1), before2 = Count(img, 2), before0 = Count(img, 0);
  vtkNew<amMorphologyCleaning> f;
  f->SetMinimumComponentVolume(20.0);
  vtkImageData* out = Clean(f, img);
  // The speckles (1 and 8 voxels) are gone and handed to label 1, which surrounds them.
  EXPECT_EQ(Count(out, 2), before2 - 3);
  EXPECT_EQ(Count(out, 1), before1 + 3 + 8);
  EXPECT_EQ(Count(out, 3), 125);
  EXPECT_EQ(Count(out, 0), before0); // no voxel lost its label
  auto* removed = vtkDoubleArray::SafeDownCast(out->GetFieldData()->GetArray("RemovedComponents"));
  ASSERT_NE(removed, nullptr);
  EXPECT_EQ(removed->GetNumberOfTuples(), 4);
  double total = 0;
  for (vtkIdType r = 0; r < removed->GetNumberOfTuples(); ++r)
    total += removed->GetComponent(r, 2);
  EXPECT_DOUBLE_EQ(total, 11.0);
}

TEST(MorphologyCleaning, KeepLargestAndVanishedLabelIsReported)
{
  auto img = Map();
  At(img, 1, 1, 1) = 4; // a label made only of one voxel
  vtkNew<amMorphologyCleaning> f;
  vtkNew<amTest::ErrorCatcher> errors;
  f->SetMinimumComponentVolume(2.0);
  vtkImageData* out = Clean(f, img, errors);
  EXPECT_EQ(Count(out, 4), 0);
  auto* vanished = vtkIntArray::SafeDownCast(out->GetFieldData()->GetArray("VanishedLabels"));
  ASSERT_NE(vanished, nullptr);
  ASSERT_EQ(vanished->GetNumberOfTuples(), 1);
  EXPECT_EQ(vanished->GetValue(0), 4);
  ASSERT_EQ(errors->Warnings.size(), 1u);
  EXPECT_NE(errors->Warnings[0].find("Label 4"), std::string::npos);
}

TEST(MorphologyCleaning, HolesFillOnlyUnlabelledCavities)
{
  auto img = Map();
  // An empty 3x3x3 cavity in label 1, and label 2 (a sphere) that must not be swallowed.
  for (int k = 8; k < 11; ++k)
    for (int j = 8; j < 11; ++j)
      for (int i = 8; i < 11; ++i)
        At(img, i, j, k) = 0;
  const long two = Count(img, 2);
  vtkNew<amMorphologyCleaning> f;
  f->SetFillHoles(true);
  vtkImageData* out = Clean(f, img);
  EXPECT_EQ(At(out, 9, 9, 9), 1);
  EXPECT_EQ(Count(out, 2), two);
  EXPECT_EQ(Count(out, 0), 40L * 40 * 40 - 30L * 30 * 30);
}

TEST(MorphologyCleaning, RadiusIsInMillimetresOnAnisotropicVoxels)
{
  // Spacing 0.5 x 0.5 x 1 mm: eroding the box by 1 mm removes 2 voxels in x and y, 1 in z.
  auto img = Map(0.5, 0.5, 1.0);
  vtkNew<amMorphologyCleaning> f;
  f->SetOperation(amMorphologyCleaning::Erode);
  f->SetRadius(1.0);
  f->AddLabel(1);
  vtkImageData* out = Clean(f, img);
  EXPECT_EQ(At(out, 5, 20, 20), 0);
  EXPECT_EQ(At(out, 6, 20, 20), 0);
  EXPECT_EQ(At(out, 7, 20, 20), 1);
  EXPECT_EQ(At(out, 20, 20, 5), 0);
  EXPECT_EQ(At(out, 20, 20, 6), 1);
}

TEST(MorphologyCleaning, GaussianRegularisationKeepsVolumesAndLeavesNoGap)
{
  auto img = Map();
  const long one = Count(img, 1), two = Count(img, 2), zero = Count(img, 0);
  vtkNew<amMorphologyCleaning> f;
  f->SetSmoothingSigma(1.0);
  vtkImageData* out = Clean(f, img);
  // The sphere is smooth already: its volume barely changes. The box's 12 sharp edges and 8
  // corners are rounded (what regularisation is for): about 1.4 % of a 30 mm cube at sigma 1 mm.
  EXPECT_NEAR(static_cast<double>(Count(out, 2)) / two, 1.0, 0.01);
  EXPECT_NEAR(static_cast<double>(Count(out, 1)) / one, 1.0, 0.02);
  EXPECT_EQ(Count(out, 0) + Count(out, 1) + Count(out, 2), zero + one + two);
  // Inside the box nothing became background.
  for (int k = 7; k < 33; ++k)
    EXPECT_NE(At(out, 7, 20, k), 0);
}

TEST(MorphologyCleaning, BadInput)
{
  vtkNew<amMorphologyCleaning> f;
  vtkNew<amTest::ErrorCatcher> errors;
  vtkNew<vtkImageData> empty;
  Clean(f, empty, errors);
  EXPECT_TRUE(errors->ErrorContains("empty")) << errors->AllErrors();
  errors->Errors.clear();
  vtkNew<vtkImageData> real;
  real->SetDimensions(2, 2, 2);
  real->AllocateScalars(VTK_FLOAT, 1);
  real->GetPointData()->GetScalars()->FillComponent(0, 0.5);
  Clean(f, real, errors);
  EXPECT_TRUE(errors->ErrorContains("whole numbers")) << errors->AllErrors();
}

TEST(MorphologyCleaning, ModeFilterCleansANoisyClassification)
{
  // The box-and-sphere map with 10 % of its voxels given a random label 0..3: two passes of the
  // 3x3x3 mode filter give what they give on the clean map (which loses the box's edges, where
  // most of a voxel's neighbours lie outside) but for a few voxels, and report how many changed.
  auto truth = Map();
  vtkNew<vtkImageData> noisy;
  noisy->DeepCopy(truth);
  auto* a = vtkUnsignedCharArray::SafeDownCast(noisy->GetPointData()->GetScalars());
  unsigned state = 12345;
  auto next = [&]() { return state = state * 1664525u + 1013904223u; };
  vtkIdType flipped = 0;
  for (vtkIdType v = 0; v < a->GetNumberOfTuples(); ++v)
    if (next() % 10 == 0)
    {
      const unsigned char l = static_cast<unsigned char>(next() >> 16) % 4;
      flipped += l != a->GetValue(v);
      a->SetValue(v, l);
    }
  auto mode = [](vtkImageData* in) {
    vtkNew<amMorphologyCleaning> clean;
    clean->SetInputData(in);
    clean->SetModeFilterRadius(1);
    clean->SetModeFilterPasses(2);
    clean->Update();
    auto out = vtkSmartPointer<vtkImageData>::New();
    out->DeepCopy(clean->GetOutput());
    return out;
  };
  auto fromNoisy = mode(noisy), fromClean = mode(truth);
  vtkDataArray* x = fromNoisy->GetPointData()->GetScalars();
  vtkDataArray* y = fromClean->GetPointData()->GetScalars();
  vtkDataArray* exact = truth->GetPointData()->GetScalars();
  vtkIdType differ = 0, edges = 0;
  for (vtkIdType v = 0; v < x->GetNumberOfTuples(); ++v)
  {
    differ += x->GetComponent(v, 0) != y->GetComponent(v, 0);
    edges += y->GetComponent(v, 0) != exact->GetComponent(v, 0);
  }
  EXPECT_GT(flipped, 4000);
  EXPECT_LT(differ, flipped / 50) << "flipped " << flipped;
  EXPECT_LT(edges, 600); // the box's 12 edges of 30 voxels, and its corners
  vtkDataArray* changed = fromNoisy->GetFieldData()->GetArray("ModeFilterChanged");
  ASSERT_NE(changed, nullptr);
  EXPECT_GE(changed->GetComponent(0, 0), flipped - differ - edges);
}
