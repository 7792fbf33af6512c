// Classification and snake segmentation on the noisy thorax phantom (Dice against the exact
// labels), and every kind of bad input.
#include "amIntensityClassifier.h"
#include "amMorphologyCleaning.h"
#include "amSnakeSegmentation.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace
{
vtkImageData* Image(vtkAlgorithm* a, int port = 0)
{
  return vtkImageData::SafeDownCast(a->GetOutputDataObject(port));
}

// Dice of {a in A} and {b in B} over two label images of the same grid.
double Dice(vtkImageData* x, const std::function<bool(int)>& inX, vtkImageData* y, const std::function<bool(int)>& inY)
{
  vtkDataArray* a = x->GetPointData()->GetScalars();
  vtkDataArray* b = y->GetPointData()->GetScalars();
  long both = 0, na = 0, nb = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const bool p = inX(static_cast<int>(a->GetComponent(i, 0))), q = inY(static_cast<int>(b->GetComponent(i, 0)));
    both += p && q;
    na += p;
    nb += q;
  }
  return na + nb ? 2.0 * both / (na + nb) : 1.0;
}

double LabelDice(vtkImageData* seg, vtkImageData* truth, int label)
{
  return Dice(
    seg, [label](int v) { return v == label; }, truth, [label](int v) { return v == label; });
}

vtkSmartPointer<amThoraxPhantomSource> Phantom(double spacing)
{
  auto src = vtkSmartPointer<amThoraxPhantomSource>::New();
  src->SetSpacing(spacing, spacing, spacing);
  src->Update();
  return src;
}

void SeedOrgans(amSnakeSegmentation* seg, amThoraxPhantomSource* src, std::initializer_list<int> labels)
{
  for (int l : labels)
  {
    double c[3];
    src->GetOrganCenter(l, c);
    seg->AddSeed(c[0], c[1], c[2], l);
    if (l == 8)
      seg->AddSeed(5.0, -20.0, 30.0, 8); // a second click, on the ascending aorta
  }
}
}

TEST(SnakeSegmentation, ThreeDGetsEveryOrganOfTheNoisyPhantom)
{
  auto src = Phantom(2.0);
  vtkNew<amSnakeSegmentation> seg;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(seg);
  seg->SetInputConnection(src->GetOutputPort(0));
  SeedOrgans(seg, src, { 6, 7, 8, 3, 4 });
  seg->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  for (int l : { 6, 7, 8, 3, 4 })
  {
    const double d = LabelDice(Image(seg), Image(src, 1), l);
    EXPECT_GE(d, 0.95) << src->GetLabelName(l);
    std::cout << "3-D Dice " << src->GetLabelName(l) << " " << d << std::endl;
  }
  auto* volumes = vtkDoubleArray::SafeDownCast(Image(seg)->GetFieldData()->GetArray("SegmentedVolumes"));
  ASSERT_NE(volumes, nullptr);
  EXPECT_EQ(volumes->GetNumberOfTuples(), 5);
  // The automatic interval, refined to half contrast: blood stops near (300 + 50) / 2.
  auto* th = vtkDoubleArray::SafeDownCast(Image(seg)->GetFieldData()->GetArray("Thresholds"));
  EXPECT_NEAR(th->GetComponent(0, 1), 175.0, 15.0);
}

TEST(SnakeSegmentation, SliceBySlicePropagationFromSeedPoints)
{
  auto src = Phantom(2.0);
  // Seeds as a point set with a "Label" array (what ParaView's point widgets give).
  vtkNew<vtkPolyData> seeds;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  for (int l : { 6, 7, 3, 4 })
  {
    double c[3];
    src->GetOrganCenter(l, c);
    pts->InsertNextPoint(c);
    labels->InsertNextValue(l);
  }
  seeds->SetPoints(pts);
  seeds->GetPointData()->AddArray(labels);
  vtkNew<amSnakeSegmentation> seg;
  seg->SetInputConnection(src->GetOutputPort(0));
  seg->SetSeedData(seeds);
  seg->SetMode(amSnakeSegmentation::SliceBySlice);
  seg->Update();
  for (int l : { 6, 7, 3, 4 })
  {
    const double d = LabelDice(Image(seg), Image(src, 1), l);
    EXPECT_GE(d, 0.95) << src->GetLabelName(l);
    std::cout << "slice Dice " << src->GetLabelName(l) << " " << d << std::endl;
  }
  // The interval may also follow the structure from slice to slice.
  seg->SetAdaptiveSliceStatistics(true);
  seg->Update();
  for (int l : { 6, 7, 3, 4 })
    EXPECT_GE(LabelDice(Image(seg), Image(src, 1), l), 0.95) << "adaptive " << src->GetLabelName(l);
}

// A dissected vessel in fat: an oblique tube (radius 12 mm) whose true lumen (400 HU) fills only part
// of it, the rest a false lumen of soft-tissue intensity (70 HU, up to 9 mm thick) with a
// soft-tissue block (50 HU, an oesophagus) a millimetre of fat away; it ends 10 mm before the top.
// Blurred by the scanner, no intensity interval separates the false lumen from the block.
TEST(SnakeSegmentation, PolarContoursFollowADissectedVessel)
{
  const int n[3] = { 90, 80, 60 };
  vtkNew<vtkImageData> ct, truth;
  for (vtkImageData* im : { ct.GetPointer(), truth.GetPointer() })
  {
    im->SetDimensions(n[0], n[1], n[2]);
    im->SetSpacing(1.0, 1.0, 1.0);
    im->SetOrigin(-45.0, -40.0, 0.0);
  }
  ct->AllocateScalars(VTK_SHORT, 1);
  truth->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 20.0);
  const auto centre = [](double z) { return -8.0 + 0.3 * z; }; // the tube leans 17 degrees
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const double x = -45.0 + i, y = -40.0 + j, z = k, cx = centre(z);
        const double r = std::hypot(x - cx, y), rl = std::hypot(x - cx + 4.0, y - 2.0);
        const bool tube = r <= 12.0 && z < 50.0;
        double v = -100.0; // fat
        if (tube)
          v = rl <= 7.0 ? 400.0 : 70.0;
        else if (x > cx + 13.0 && x < cx + 30.0 && std::abs(y) < 9.0)
          v = 50.0; // the block the false lumen touches
        else if (y > 25.0)
          v = -800.0; // lung
        ct->GetPointData()->GetScalars()->SetComponent(
          ct->ComputePointId(std::array<int, 3>{ i, j, k }.data()), 0, std::round(v + noise(random)));
        truth->GetPointData()->GetScalars()->SetComponent(
          truth->ComputePointId(std::array<int, 3>{ i, j, k }.data()), 0, tube ? 1 : 0);
      }
  vtkNew<amSnakeSegmentation> seg;
  seg->SetInputData(ct);
  seg->SetMode(amSnakeSegmentation::SliceBySlice);
  seg->AddSeed(centre(25.0) - 4.0, 2.0, 25.0, 1); // one click, in the bright true lumen
  seg->Update();
  const auto in1 = [](int v) { return v == 1; };
  const double levelSet = Dice(Image(seg), in1, truth, in1);

  seg->SetContourModel(amSnakeSegmentation::Polar);
  seg->Update();
  const double polar = Dice(Image(seg), in1, truth, in1);
  std::cout << "dissected vessel Dice: level set " << levelSet << ", polar " << polar << std::endl;
  EXPECT_GE(polar, 0.93);
  EXPECT_GT(polar, levelSet + 0.2);
  // The track stops where the vessel ends, and never enters the block.
  vtkDataArray* labels = Image(seg)->GetPointData()->GetScalars();
  long above = 0, block = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (labels->GetComponent(ct->ComputePointId(std::array<int, 3>{ i, j, k }.data()), 0) == 1)
        {
          const double x = -45.0 + i, y = -40.0 + j, cx = centre(k);
          above += k >= 52;
          block += x > cx + 14.0 && std::abs(y) < 9.0;
        }
  EXPECT_EQ(above, 0);
  EXPECT_LT(block, 50);
  // Deterministic.
  vtkNew<vtkUnsignedCharArray> first;
  first->DeepCopy(labels);
  seg->Modified();
  seg->Update();
  vtkDataArray* again = Image(seg)->GetPointData()->GetScalars();
  for (vtkIdType q = 0; q < first->GetNumberOfTuples(); ++q)
    ASSERT_EQ(first->GetValue(q), again->GetComponent(q, 0));

  // Polar contours are slice by slice only.
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(seg);
  seg->SetMode(amSnakeSegmentation::ThreeD);
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("set Mode to SliceBySlice")) << errors->AllErrors();
}

TEST(SnakeSegmentation, OrgansNeverOverlapAndPrecedenceIsSeedOrder)
{
  auto src = Phantom(3.0);
  vtkNew<amSnakeSegmentation> seg;
  seg->SetInputConnection(src->GetOutputPort(0));
  double c[3];
  src->GetOrganCenter(6, c);
  // Two labels seeded in the same blood pool: the first one keeps it all.
  seg->AddSeed(c[0], c[1], c[2], 20);
  seg->AddSeed(c[0], c[1], c[2], 21);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(seg);
  seg->Update();
  const double d = Dice(
    Image(seg), [](int v) { return v == 20; }, Image(src, 1), [](int v) { return v == 6; });
  EXPECT_GE(d, 0.9);
  EXPECT_FALSE(errors->Warnings.empty()); // label 21 got nothing, and the filter says so
}

TEST(SnakeSegmentation, BadInputGivesClearErrors)
{
  auto src = Phantom(4.0);
  vtkNew<amSnakeSegmentation> seg;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(seg);
  seg->SetInputConnection(src->GetOutputPort(0));
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("No seeds")) << errors->AllErrors();

  errors->Errors.clear();
  seg->AddSeed(0, 0, 500, 1);
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("is outside the image")) << errors->AllErrors();

  errors->Errors.clear();
  seg->RemoveAllSeeds();
  seg->AddSeed(-155, -115, 0, 1); // a corner of the image: air
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("lies in air")) << errors->AllErrors();

  errors->Errors.clear();
  seg->RemoveAllSeeds();
  seg->AddSeed(0, 0, 0, 300);
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("labels are 1..255")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkImageData> empty;
  seg->SetInputData(empty);
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("empty")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkImageData> vectors;
  vectors->SetDimensions(4, 4, 4);
  vectors->AllocateScalars(VTK_FLOAT, 3);
  seg->SetInputData(vectors);
  seg->Update();
  EXPECT_TRUE(errors->ErrorContains("3 components; a one-component image is needed")) << errors->AllErrors();

  // A NaN voxel (which GetRange skips) is refused, as an infinite one is.
  for (float bad : { std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity() })
  {
    errors->Errors.clear();
    vtkNew<vtkImageData> ct;
    ct->SetDimensions(8, 8, 8);
    ct->AllocateScalars(VTK_FLOAT, 1);
    auto* values = vtkFloatArray::SafeDownCast(ct->GetPointData()->GetScalars());
    values->FillValue(40.0f);
    values->SetValue(100, bad);
    seg->SetInputData(ct);
    seg->RemoveAllSeeds();
    seg->AddSeed(4, 4, 4, 1);
    seg->Update();
    EXPECT_TRUE(errors->ErrorContains("1 non-finite values (NaN or infinite)")) << errors->AllErrors();
  }
}

TEST(IntensityClassifier, BoneAloneAndLungsAfterOpening)
{
  auto src = Phantom(1.5);
  vtkNew<amIntensityClassifier> cls;
  cls->SetInputConnection(src->GetOutputPort(0));
  cls->Update();
  vtkImageData* truth = Image(src, 1);
  const double bone = Dice(
    Image(cls), [](int v) { return v == 5; }, truth, [](int v) { return v == 9 || v == 10; });
  const double lungAlone = Dice(
    Image(cls), [](int v) { return v == 1; }, truth, [](int v) { return v == 3 || v == 4; });
  EXPECT_GE(bone, 0.95);
  // The partial-volume voxels of the skin against the air around the body fall in the lung's HU
  // range; ExteriorAir (default) gives them to the air, so the classifier alone gets the lungs.
  EXPECT_GE(lungAlone, 0.95);
  vtkIdTypeArray* exterior = vtkIdTypeArray::SafeDownCast(Image(cls)->GetFieldData()->GetArray("ExteriorVoxels"));
  ASSERT_NE(exterior, nullptr);
  EXPECT_GT(exterior->GetValue(0), 0);
  cls->ExteriorAirOff();
  cls->Update();
  const double lungWithSkin = Dice(
    Image(cls), [](int v) { return v == 1; }, truth, [](int v) { return v == 3 || v == 4; });
  EXPECT_LT(lungWithSkin, lungAlone);
  EXPECT_GE(lungWithSkin, 0.93);
  // An opening of 1.5 mm also removes that thin shell.
  vtkNew<amMorphologyCleaning> clean;
  clean->SetInputConnection(cls->GetOutputPort(0));
  clean->SetOperation(amMorphologyCleaning::Open);
  clean->SetRadius(1.5);
  clean->AddLabel(1);
  clean->Update();
  const double lung = Dice(
    Image(clean), [](int v) { return v == 1; }, truth, [](int v) { return v == 3 || v == 4; });
  EXPECT_GE(lung, 0.95);
  std::cout << "classifier Dice: bone " << bone << ", lungs " << lungAlone << " alone (" << lungWithSkin
            << " without ExteriorAir), " << lung << " after opening" << std::endl;
  vtkImageData* windowed = Image(cls, 1);
  double range[2];
  windowed->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_EQ(range[0], 0);
  EXPECT_EQ(range[1], 255);
}

TEST(IntensityClassifier, OtsuFindsTheTissueClasses)
{
  auto src = Phantom(3.0);
  vtkNew<amIntensityClassifier> cls;
  cls->SetInputConnection(src->GetOutputPort(0));
  cls->SetMode(amIntensityClassifier::Otsu);
  cls->SetNumberOfClasses(3);
  cls->Update();
  auto* th = vtkDoubleArray::SafeDownCast(Image(cls)->GetFieldData()->GetArray("Thresholds"));
  ASSERT_NE(th, nullptr);
  ASSERT_EQ(th->GetNumberOfTuples(), 2);
  // Air/lung | soft tissue and fat | ... : the first threshold lies between lung and fat.
  EXPECT_GT(th->GetValue(0), -850.0);
  EXPECT_LT(th->GetValue(0), -100.0);
  EXPECT_GT(th->GetValue(1), th->GetValue(0));
  double range[2];
  Image(cls)->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_EQ(range[0], 0);
  EXPECT_EQ(range[1], 2);
}

TEST(IntensityClassifier, RangesAndBadInput)
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(4, 1, 1);
  img->AllocateScalars(VTK_FLOAT, 1);
  auto* s = vtkFloatArray::SafeDownCast(img->GetPointData()->GetScalars());
  const float v[4] = { -5, 0, 5, 10 };
  for (int i = 0; i < 4; ++i)
    s->SetValue(i, v[i]);
  vtkNew<amIntensityClassifier> cls;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(cls);
  cls->SetInputData(img);
  cls->AddRange(-10, 1, 7);
  cls->AddRange(0, 6, 9); // overlaps the first: the first wins at 0
  cls->Update();
  vtkDataArray* l = Image(cls)->GetPointData()->GetScalars();
  EXPECT_EQ(l->GetComponent(0, 0), 7);
  EXPECT_EQ(l->GetComponent(1, 0), 7);
  EXPECT_EQ(l->GetComponent(2, 0), 9);
  EXPECT_EQ(l->GetComponent(3, 0), 0);

  s->SetValue(2, std::numeric_limits<float>::quiet_NaN());
  img->Modified();
  cls->Update();
  EXPECT_TRUE(errors->ErrorContains("1 non-finite values (NaN or infinite)")) << errors->AllErrors();

  // An infinite voxel is no bone: refused like a NaN.
  errors->Errors.clear();
  s->SetValue(2, std::numeric_limits<float>::infinity());
  img->Modified();
  cls->Update();
  EXPECT_TRUE(errors->ErrorContains("1 non-finite values")) << errors->AllErrors();
  s->SetValue(2, 5);
  img->Modified();

  errors->Errors.clear();
  cls->AddRange(5, 1, 3);
  cls->Update();
  EXPECT_TRUE(errors->ErrorContains("is invalid")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkImageData> none;
  none->SetDimensions(2, 2, 2);
  cls->SetInputData(none);
  cls->Update();
  EXPECT_TRUE(errors->ErrorContains("no scalars")) << errors->AllErrors();
}
