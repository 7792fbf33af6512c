// The whole domain segmented from the phantom varied as real scans and patients vary (contrast
// phase, noise, kernel, voxel shape, rotation, storage, field of view, fat, the heart's size and
// axis), with the library's defaults and the seeds moved with the anatomy: every organ against its
// truth.
#include "amFigures.h"
#include "amSnakeSegmentation.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"
#include "amTorsoSegmentation.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

namespace
{
struct Variation
{
  std::string Name;
  double Spacing[3];
  double Noise;
  double Blur;
  double Blood, Myocardium;
  double Rotation[3];
  double FieldOfView[3] = { 320, 240, 210 }; // the phantom's default: the whole body
  bool RAS = false; // stored from the patient's left and front (RAS), not from the right and back (LPS)
  // Habitus (amThoraxPhantomSource): fat (mm), the heart's scale and its axis (degrees).
  double Fat = 12, HeartScale = 1, HeartAngle = -30;
  bool Table = false;          // the patient lies on a table (AddTable)
  bool Arms = false;           // the arms lie beside the body in the field (AddArms)
  bool Airway = false;         // the trachea and the main bronchi (AddAirway)
  bool OesophagealGas = false; // a column of gas down the oesophagus, behind the trachea (AddAirway)
};

// The labels scored: the phantom's, the atria (11, none here) and the airway (12).
constexpr int Labels = 13;

// The body's extent in a truth label map (mm): its farthest point back (largest y), its widest
// |x|, and its mean y.
struct BodyExtent
{
  double Back = -1e30, Side = 0.0, MiddleY = 0.0;
};

BodyExtent ExtentOf(vtkImageData* truth)
{
  BodyExtent e;
  long count = 0;
  vtkDataArray* labels = truth->GetPointData()->GetScalars();
  for (vtkIdType v = 0; v < labels->GetNumberOfTuples(); ++v)
    if (labels->GetComponent(v, 0) != 0)
    {
      double p[3];
      truth->GetPoint(v, p);
      e.Back = std::max(e.Back, p[1]);
      e.Side = std::max(e.Side, std::fabs(p[0]));
      e.MiddleY += p[1];
      ++count;
    }
  e.MiddleY /= std::max<long>(count, 1);
  return e;
}

// Paints an object outside the body, the same in every slice, into the scan and its truth:
// paint(x, y, value, label) says whether (x, y) is the object's and sets its intensity (HU, to
// which the scan's noise is added) and its truth label (0: background). The object must not cross
// the body.
template<typename Paint>
void PaintOutsideBody(vtkImageData* ct, vtkImageData* truth, double noise, unsigned seed, Paint paint)
{
  vtkDataArray* hu = ct->GetPointData()->GetScalars();
  vtkDataArray* labels = truth->GetPointData()->GetScalars();
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  for (vtkIdType v = 0; v < ct->GetNumberOfPoints(); ++v)
  {
    double p[3], value = 0.0;
    int label = 0;
    ct->GetPoint(v, p);
    if (!paint(p[0], p[1], value, label))
      continue;
    if (labels->GetComponent(v, 0) != 0)
    {
      ADD_FAILURE() << "the painted object crosses the body at " << p[0] << " " << p[1] << " " << p[2];
      return;
    }
    hu->SetComponent(v, 0, value + gauss(random));
    labels->SetComponent(v, 0, label);
  }
}

// A patient table under the body's back, as scanners have: a carbon-fibre top of two shells
// (3 mm, 200 HU) around a foam core (32 mm, -900 HU), curved up towards its sides, 4 mm below
// the back at the middle, with the scan's noise. Outside the body: the truth there stays 0.
void AddTable(vtkImageData* ct, vtkImageData* truth, double noise)
{
  const double back = ExtentOf(truth).Back;
  PaintOutsideBody(ct, truth, noise, 7, [back](double x, double y, double& value, int& label) {
    const double depth = y - (back + 4.0 - x * x / 2400.0); // below the table's top
    if (std::fabs(x) > 200.0 || depth < 0.0 || depth >= 38.0)
      return false;
    value = depth < 3.0 || depth >= 35.0 ? 200.0 : -900.0;
    label = 0;
    return true;
  });
}

// The image stored the other way along its first two axes: voxel (i, j, k) of the result is
// (N0-1-i, N1-1-j, k) of the input, and the direction matrix says so (the same anatomy in world).
vtkSmartPointer<vtkImageData> StoredRAS(vtkImageData* lps)
{
  int n[3];
  lps->GetDimensions(n);
  double bounds[6];
  lps->GetBounds(bounds);
  auto ras = vtkSmartPointer<vtkImageData>::New();
  ras->SetDimensions(n);
  ras->SetSpacing(lps->GetSpacing());
  ras->SetOrigin(bounds[1], bounds[3], bounds[4]);
  ras->SetDirectionMatrix(-1, 0, 0, 0, -1, 0, 0, 0, 1);
  vtkDataArray* from = lps->GetPointData()->GetScalars();
  vtkSmartPointer<vtkDataArray> to = vtkSmartPointer<vtkDataArray>::Take(from->NewInstance());
  to->SetName(from->GetName());
  to->SetNumberOfTuples(from->GetNumberOfTuples());
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        to->SetTuple((static_cast<vtkIdType>(k) * n[1] + j) * n[0] + i,
          (static_cast<vtkIdType>(k) * n[1] + (n[1] - 1 - j)) * n[0] + (n[0] - 1 - i), from);
  ras->GetPointData()->SetScalars(to);
  return ras;
}

// Arms down beside the body, 8 mm from it, along the whole field: elliptic sections of 40 x 45 mm
// (muscle, 45 HU) in 6 mm of fat (-100 HU), round a humerus of radius 11 mm (a 3 mm cortex of
// 1000 HU round an adult's yellow marrow, -80 HU), with the scan's noise. Their truth is the
// body's scheme: soft tissue, fat, and the cortex bone (label 10, "ribs and other bone"); the
// marrow's fat is fat, as TorsoSegmentation labels it (only marrow brighter than soft tissue is
// trabecular bone: the spinal canal's cord and fluid must stay out).
void AddArms(vtkImageData* ct, vtkImageData* truth, double noise)
{
  const BodyExtent body = ExtentOf(truth);
  PaintOutsideBody(ct, truth, noise, 11, [body](double x, double y, double& value, int& label) {
    const double dx = std::fabs(x) - (body.Side + 8.0 + 40.0), dy = y - body.MiddleY;
    const double r = std::hypot(dx / 40.0, dy / 45.0), bone = std::hypot(dx, dy);
    if (r > 1.0)
      return false;
    value = 45.0;
    label = 1;
    if (bone <= 11.0)
    {
      value = bone > 8.0 ? 1000.0 : -80.0;
      label = bone > 8.0 ? 10 : 2;
    }
    else if (r > 1.0 - 6.0 / 42.5)
    {
      value = -100.0;
      label = 2;
    }
    return true;
  });
}

// Distance (mm) from p to the segment ab.
double ToSegment(const double p[3], const double a[3], const double b[3])
{
  double ab[3], ap[3], t = 0.0, length2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    ab[c] = b[c] - a[c];
    ap[c] = p[c] - a[c];
    t += ab[c] * ap[c];
    length2 += ab[c] * ab[c];
  }
  t = std::clamp(t / length2, 0.0, 1.0);
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c)
    d2 += (ap[c] - t * ab[c]) * (ap[c] - t * ab[c]);
  return std::sqrt(d2);
}

// The trachea and the main bronchi, their lumen air (-1000 HU): the trachea (radius 9 mm) from
// above the field down to the carina (z = 45 mm), 20 mm to the patient's right of the mid-line
// beside the aortic arch; the right main bronchus (radius 6.5 mm) down to (-45, 20, 32), the left
// (6 mm) under the arch to (40, 12, 22), both ending 12-15 mm inside their lungs. Each voxel takes
// the share of 27 samples in the lumen, with the scan's noise. The truth is Airway (12) outside
// the lungs and lung inside them; the lumen crosses no other organ. With oesophagealGas, gas down
// the oesophagus (radius 5 mm, from above the field to z = -20 mm, between the trachea, the aorta
// and the spine), whose truth stays soft tissue. The ends are the unrotated anatomy's (mm),
// turned with the patient.
void AddAirway(amThoraxPhantomSource* phantom, vtkImageData* ct, vtkImageData* truth, double noise, bool trachea,
  bool oesophagealGas)
{
  // The tubes' ends where the patient's rotation puts them.
  const double model[6][3] = { { -20, 25, 45 }, { -20, 25, 400 }, { -45, 20, 32 }, { 40, 12, 22 }, { -12, 45, -20 },
    { -12, 45, 400 } };
  double carina[3], top[3], right[3], left[3], gasBottom[3], gasTop[3];
  phantom->ModelToScanner(model[0], carina);
  phantom->ModelToScanner(model[1], top);
  phantom->ModelToScanner(model[2], right);
  phantom->ModelToScanner(model[3], left);
  phantom->ModelToScanner(model[4], gasBottom);
  phantom->ModelToScanner(model[5], gasTop);
  auto inLumen = [&](const double p[3]) {
    return trachea &&
      (ToSegment(p, carina, top) <= 9.0 || ToSegment(p, carina, right) <= 6.5 || ToSegment(p, carina, left) <= 6.0);
  };
  auto inGas = [&](const double p[3]) { return oesophagealGas && ToSegment(p, gasBottom, gasTop) <= 5.0; };
  vtkDataArray* hu = ct->GetPointData()->GetScalars();
  vtkDataArray* labels = truth->GetPointData()->GetScalars();
  const double* h = ct->GetSpacing();
  std::mt19937 random(13);
  std::normal_distribution<double> gauss(0.0, noise);
  for (vtkIdType v = 0; v < ct->GetNumberOfPoints(); ++v)
  {
    double p[3];
    ct->GetPoint(v, p);
    if (ToSegment(p, carina, top) > 12.0 + h[0] && ToSegment(p, carina, right) > 12.0 + h[0] &&
      ToSegment(p, carina, left) > 12.0 + h[0] && !(oesophagealGas && ToSegment(p, gasBottom, gasTop) < 8.0 + h[0]))
      continue;
    int inside = 0;
    for (int s = 0; s < 27; ++s)
    {
      const double q[3] = { p[0] + (s % 3 - 1) * h[0] / 3.0, p[1] + (s / 3 % 3 - 1) * h[1] / 3.0,
        p[2] + (s / 9 - 1) * h[2] / 3.0 };
      inside += inLumen(q) || inGas(q);
    }
    if (inside == 0)
      continue;
    const double old = hu->GetComponent(v, 0), share = inside / 27.0;
    hu->SetComponent(v, 0, old + share * (-1000.0 + gauss(random) - old));
    const int label = static_cast<int>(labels->GetComponent(v, 0));
    if (!inLumen(p) || label == 3 || label == 4)
      continue;
    if (label != 1)
    {
      ADD_FAILURE() << "the airway crosses label " << label << " at " << p[0] << " " << p[1] << " " << p[2];
      return;
    }
    labels->SetComponent(v, 0, 12);
  }
}

std::ostream& operator<<(std::ostream& os, const Variation& v)
{
  return os << v.Name;
}

// Dice per label of the torso segmentation of the variation, from the main job's clicks (without
// the aorta's two when aortaClicked is false: TorsoSegmentation finds it).
std::array<double, Labels> SegmentVariation(const Variation& v, bool aortaClicked = true, bool findTable = true)
{
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(v.Spacing[0], v.Spacing[1], v.Spacing[2]);
  phantom->SetNoiseStandardDeviation(v.Noise);
  phantom->SetBlurSigma(v.Blur);
  phantom->SetBloodHounsfieldUnits(v.Blood);
  phantom->SetMyocardiumHounsfieldUnits(v.Myocardium);
  phantom->SetPatientRotation(v.Rotation[0], v.Rotation[1], v.Rotation[2]);
  phantom->SetFieldOfView(v.FieldOfView[0], v.FieldOfView[1], v.FieldOfView[2]);
  phantom->SetFatThickness(v.Fat);
  phantom->SetHeartScale(v.HeartScale);
  phantom->SetHeartAngle(v.HeartAngle);
  phantom->SetSeed(1);
  phantom->Update();
  vtkSmartPointer<vtkImageData> ct = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(0));
  vtkSmartPointer<vtkImageData> truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  if (v.Table)
    AddTable(ct, truth, v.Noise);
  if (v.Arms)
    AddArms(ct, truth, v.Noise);
  if (v.Airway || v.OesophagealGas)
    AddAirway(phantom, ct, truth, v.Noise, v.Airway, v.OesophagealGas);
  if (v.RAS)
  {
    ct = StoredRAS(ct);
    truth = StoredRAS(truth);
  }
  vtkNew<amSnakeSegmentation> snake;
  snake->SetInputData(ct);
  // The main job's clicks, where the rotation (and the heart's size and axis) puts them.
  const double seeds[4][4] = { { 29.4, -24.1, -28.0, 6 }, { -15.0, -25.0, -28.0, 7 }, { 5.0, 40.0, 0.0, 8 },
    { 5.0, -20.0, 30.0, 8 } };
  const bool usualHeart = v.HeartScale == 1 && v.HeartAngle == -30;
  for (const auto& s : seeds)
  {
    if (s[3] == 8 && !aortaClicked)
      continue;
    double x[3];
    if (s[3] == 8 || usualHeart)
      phantom->ModelToScanner(s, x);
    else
      phantom->HeartToScanner(s, x);
    snake->AddSeed(x[0], x[1], x[2], s[3]);
  }
  vtkNew<amTorsoSegmentation> torso;
  torso->SetInputData(ct);
  torso->SetOrganConnection(snake->GetOutputPort());
  torso->SetFindPatientTable(findTable);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(torso);
  errors->Watch(snake);
  torso->Update();
  std::array<double, Labels> dice{};
  if (errors->HasError())
  {
    ADD_FAILURE() << v.Name << ": " << errors->AllErrors();
    return dice;
  }
  auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
  // The table is found where there is one (its painted shells and foam: 38 mm thick across the
  // field's width, the whole field's length) and nowhere else.
  vtkDataArray* table = seg->GetFieldData()->GetArray("PatientTable");
  EXPECT_TRUE(table != nullptr);
  const double tableVolume = table ? table->GetComponent(0, 0) : 0.0;
  const double painted = std::min(400.0, v.FieldOfView[0]) * 38.0 * v.FieldOfView[2];
  if (v.Table && findTable)
    EXPECT_NEAR(tableVolume, painted, 0.25 * painted) << v.Name;
  else
    EXPECT_EQ(tableVolume, 0.0) << v.Name;
  vtkDataArray* a = seg->GetPointData()->GetScalars();
  vtkDataArray* b = truth->GetPointData()->GetScalars();
  std::array<long, Labels> both{}, na{}, nb{};
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const int p = static_cast<int>(a->GetComponent(i, 0)), q = static_cast<int>(b->GetComponent(i, 0));
    if (p < Labels)
      ++na[p];
    if (q < Labels)
      ++nb[q];
    if (p == q && p < Labels)
      ++both[p];
  }
  for (int l = 0; l < Labels; ++l)
    dice[l] = na[l] + nb[l] ? 2.0 * both[l] / (na[l] + nb[l]) : 1.0;
  return dice;
}

class SegmentationVariations : public ::testing::TestWithParam<Variation>
{
};

class AortaWithoutClicks : public ::testing::TestWithParam<Variation>
{
};

// The patient on a table (AddTable).
const Variation OnTable{ "on_table", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 300, 210 }, false, 12, 1, -30,
  true };

// One variation of each kind, at 2 mm and coarser slices.
const Variation Family[] = { { "arterial", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 } },
  { "late_phase", { 2, 2, 2 }, 20, 0.6, 170, 95, { 0, 0, 0 } },
  { "dense_contrast", { 2, 2, 2 }, 20, 0.6, 400, 60, { 0, 0, 0 } },
  { "noise_35", { 1.5, 1.5, 1.5 }, 35, 0.6, 300, 50, { 0, 0, 0 } },
  { "soft_kernel", { 2, 2, 2 }, 20, 1.5, 300, 50, { 0, 0, 0 } },
  { "thick_slices", { 0.8, 0.8, 2.5 }, 20, 0.6, 300, 50, { 0, 0, 0 } },
  { "rotated", { 2, 2, 2 }, 20, 0.6, 300, 50, { 4, -3, 5 } },
  { "stored_RAS", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 210 }, true },
  // A cardiac field of view: the body cut on every side, the lungs at the image's sides.
  { "cardiac_field", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 200, 170, 150 } },
  // Habitus: an obese patient (35 mm of fat), a large heart turned towards the horizontal, a small
  // one turned towards the vertical.
  { "obese", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 380, 290, 270 }, false, 35 },
  { "large_heart", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 210 }, false, 12, 1.15, -42 },
  { "small_heart", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 210 }, false, 12, 0.85, -18 },
  { "lean", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 210 }, false, 6 },
  // The patient on a scanner's table (AddTable), which is no part of the body.
  OnTable,
  // The arms down beside the body in the field (AddArms): body, not exterior; their humeri bone.
  { "arms_in_field", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 520, 240, 210 }, false, 12, 1, -30, false, true },
  // A chest's field of view (the neck cut at its top) with the trachea and the main bronchi (AddAirway).
  { "airway", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 170 }, false, 12, 1, -30, false, false, true } };

// The airway turned with the patient and stored RAS, under 60 HU of noise, in thick slices, and
// beside an oesophagus holding gas.
const Variation AirwayFamily[] = { { "airway_rotated_RAS", { 2, 2, 2 }, 20, 0.6, 300, 50, { 4, -3, 5 },
                                     { 320, 240, 170 }, true, 12, 1, -30, false, false, true },
  { "airway_noise_60", { 2, 2, 2 }, 60, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 170 }, false, 12, 1, -30, false, false,
    true },
  { "airway_thick_slices", { 0.8, 0.8, 2.5 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 170 }, false, 12, 1, -30,
    false, false, true },
  // Gas down the oesophagus, also leaving the field at its top, and no trachea: no airway.
  { "oesophageal_gas", { 2, 2, 2 }, 20, 0.6, 300, 50, { 0, 0, 0 }, { 320, 240, 170 }, false, 12, 1, -30, false, false,
    false, true } };

// 60 HU of noise at 2 mm.
const Variation Noise60{ "noise_60", { 2, 2, 2 }, 60, 0.6, 300, 50, { 0, 0, 0 } };

std::string NameOf(const ::testing::TestParamInfo<Variation>& info)
{
  return info.param.Name;
}
}

TEST_P(SegmentationVariations, EveryOrganMeetsItsDice)
{
  const Variation& v = GetParam();
  const std::array<double, Labels> dice = SegmentVariation(v);
  // Labels 1-10 and the airway (12: 1 where neither the truth nor the segmentation has one).
  const int scored[] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12 };
  std::string row = v.Name + ":";
  for (const int l : scored)
    row += " " + std::to_string(dice[l]).substr(0, 5);
  std::cout << row << std::endl;
  int lowest = 1;
  for (const int l : scored)
  {
    EXPECT_GE(dice[l], l == 5 ? 0.93 : 0.95) << v.Name << ", label " << l;
    lowest = dice[l] < dice[lowest] ? l : lowest;
  }
  amTest::RecordFigure("variations.dice_lowest", dice[lowest], "", lowest == 5 ? 0.93 : 0.95);
}

TEST_P(AortaWithoutClicks, TheAortaIsTheContrastInFrontOfTheSpine)
{
  // The same scans with clicks in the blood pools alone: the aorta is the contrast running down in
  // front of the spine (TorsoSegmentation's FindAorta).
  const Variation& v = GetParam();
  const std::array<double, Labels> dice = SegmentVariation(v, false);
  std::cout << v.Name << ": aorta without its clicks " << dice[8] << std::endl;
  EXPECT_GE(dice[8], 0.95) << v.Name;
  amTest::RecordFigure("variations.aorta_without_click_lowest", dice[8], "", 0.95);
}

INSTANTIATE_TEST_SUITE_P(Sample, SegmentationVariations, ::testing::ValuesIn(Family), NameOf);

// The trachea and the main bronchi across orientation, noise and slices.
INSTANTIATE_TEST_SUITE_P(Airway, SegmentationVariations, ::testing::ValuesIn(AirwayFamily), NameOf);

// 60 HU of noise at 2 mm: the myocardium 10 HU above the soft tissue around it.
INSTANTIATE_TEST_SUITE_P(HeavyNoise, SegmentationVariations, ::testing::Values(Noise60), NameOf);

// The aorta without its clicks on the whole family, 60 HU of noise included.
INSTANTIATE_TEST_SUITE_P(Sample, AortaWithoutClicks, ::testing::ValuesIn(Family), NameOf);
INSTANTIATE_TEST_SUITE_P(HeavyNoise, AortaWithoutClicks, ::testing::Values(Noise60), NameOf);

// Under 60 HU of noise the scan is smoothed, and its bone is read from the unsmoothed intensities:
// the spine and the ribs meet their bars there.
TEST(HeavyNoise, BoneIsReadUnsmoothed)
{
  const std::array<double, Labels> dice = SegmentVariation(Noise60);
  std::cout << "noise_60 bone: spine " << dice[9] << ", ribs " << dice[10] << std::endl;
  EXPECT_GE(dice[9], 0.95);
  EXPECT_GE(dice[10], 0.95);
  amTest::RecordFigure("heavy_noise.spine_dice", dice[9], "", 0.95);
  amTest::RecordFigure("heavy_noise.ribs_dice", dice[10], "", 0.95);
}

// FindPatientTable off: the table is body, its foam a lung (as any segmentation without the table
// step takes it): the switch is the step's.
TEST(PatientTable, TurnedOffTheTableIsBody)
{
  const std::array<double, Labels> dice = SegmentVariation(OnTable, true, false);
  std::cout << "on_table without the table step: soft tissue " << dice[1] << ", left lung " << dice[4] << std::endl;
  EXPECT_LT(dice[1], 0.9);
  EXPECT_LT(dice[4], 0.5);
}
