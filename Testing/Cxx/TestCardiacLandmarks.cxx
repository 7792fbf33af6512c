// The heart's landmarks and the 12-lead electrodes computed from a segmented thorax: on the
// phantom's labels against its anatomy, on the phantom rotated, and on what has no heart.
#include "amCardiacLandmarks.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomModel.h"
#include "amThoraxPhantomSource.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

namespace
{
using Points = std::map<std::string, std::array<double, 3>>;

// The named points CardiacLandmarks finds on a label map.
Points LandmarksOf(vtkImageData* labels, amTest::ErrorCatcher* errors)
{
  vtkNew<amCardiacLandmarks> landmarks;
  errors->Watch(landmarks);
  landmarks->SetInputData(labels);
  landmarks->Update();
  Points points;
  vtkPolyData* out = landmarks->GetOutput();
  auto* names = vtkStringArray::SafeDownCast(out->GetPointData()->GetAbstractArray("Name"));
  for (vtkIdType i = 0; names && i < out->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> x;
    out->GetPoint(i, x.data());
    points[names->GetValue(i)] = x;
  }
  return points;
}

// ... on the phantom's exact labels.
Points Landmarks(amThoraxPhantomSource* phantom, amTest::ErrorCatcher* errors)
{
  phantom->Update();
  return LandmarksOf(vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1)), errors);
}

double Distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// A point on the skin: inside the body, with the outside within reach along an axis.
bool OnSkin(amThoraxPhantomSource* phantom, const std::array<double, 3>& x, double reach)
{
  if (phantom->GetLabelAtPoint(x[0], x[1], x[2]) == 0)
    return false;
  for (int a = 0; a < 3; ++a)
    for (const double s : { -reach, reach })
    {
      std::array<double, 3> y = x;
      y[a] += s;
      if (phantom->GetLabelAtPoint(y[0], y[1], y[2]) == 0)
        return true;
    }
  return false;
}
}

TEST(CardiacLandmarks, ThePhantomsElectrodesLieOnItsSkinWhereTheStandardPutsThem)
{
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(2, 2, 2);
  vtkNew<amTest::ErrorCatcher> errors;
  const Points p = Landmarks(phantom, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  ASSERT_EQ(p.size(), 13u);
  double standard[9][3];
  amThoraxPhantomModel::StandardElectrodes(standard);
  const char* leads[9] = { "RA", "LA", "LL", "V1", "V2", "V3", "V4", "V5", "V6" };
  for (int e = 0; e < 9; ++e)
  {
    const auto& x = p.at(leads[e]);
    EXPECT_TRUE(OnSkin(phantom, x, 3.0)) << leads[e];
    const std::array<double, 3> s{ standard[e][0], standard[e][1], standard[e][2] };
    std::cout << leads[e] << " " << x[0] << " " << x[1] << " " << x[2] << "  (standard " << Distance(x, s)
              << " mm away)" << std::endl;
    // The precordial leads within 30 mm of where the phantom's standard placement puts them (the
    // limb electrodes are on the front, Mason-Likar's torso sites, not at the phantom's sides).
    if (e >= 3)
      EXPECT_LT(Distance(x, s), 30.0) << leads[e];
  }
  // The precordial leads go round the chest from right to left, V1 and V2 astride the mid-line.
  EXPECT_LT(p.at("V1")[0], 0.0);
  EXPECT_GT(p.at("V2")[0], 0.0);
  for (const auto& pair :
    { std::make_pair("V2", "V3"), std::make_pair("V3", "V4"), std::make_pair("V4", "V5"), std::make_pair("V5", "V6") })
    EXPECT_LT(p.at(pair.first)[0], p.at(pair.second)[0]) << pair.first << " " << pair.second;
  EXPECT_GT(p.at("V1")[2], p.at("V4")[2]); // one intercostal space higher
  EXPECT_LT(p.at("RA")[0], 0.0);
  EXPECT_GT(p.at("LA")[0], 0.0);
  EXPECT_LT(p.at("LL")[2], p.at("V4")[2]);
  // The apex points to the patient's left, front and feet; the stimulus lies in the wall.
  const auto& apex = p.at("LVApexEpicardium");
  const auto& base = p.at("LVBase");
  EXPECT_GT(apex[0], base[0]);
  EXPECT_LT(apex[1], base[1]);
  EXPECT_LT(apex[2], base[2]);
  const auto& s = p.at("Stimulus");
  EXPECT_EQ(phantom->GetLabelAtPoint(s[0], s[1], s[2]), 5);
}

TEST(CardiacLandmarks, TheLandmarksTurnWithThePatient)
{
  vtkNew<amThoraxPhantomSource> upright, turned;
  upright->SetSpacing(2, 2, 2);
  turned->SetSpacing(2, 2, 2);
  turned->SetPatientRotation(4, -3, 5);
  vtkNew<amTest::ErrorCatcher> errors;
  const Points a = Landmarks(upright, errors);
  const Points b = Landmarks(turned, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  for (const auto& [name, x] : a)
  {
    std::array<double, 3> moved;
    turned->ModelToScanner(x.data(), moved.data());
    // The heart's points move with it; the electrodes' levels are the scanner's axial planes, so
    // they slide along the skin, the limb electrodes most (near the body's rounded ends).
    const bool heart = name.rfind("LV", 0) == 0 || name == "Stimulus";
    const bool limb = name == "RA" || name == "LA" || name == "LL";
    const double bound = heart ? 6.0 : limb ? 45.0 : 20.0;
    EXPECT_LT(Distance(moved, b.at(name)), bound) << name;
  }
}

TEST(CardiacLandmarks, ALabelMapWithoutAHeartIsRefusedNamingIt)
{
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(4, 4, 4);
  phantom->Update();
  vtkNew<vtkImageData> noHeart;
  noHeart->DeepCopy(phantom->GetOutputDataObject(1));
  vtkDataArray* labels = noHeart->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < labels->GetNumberOfTuples(); ++i)
    if (labels->GetComponent(i, 0) == 6)
      labels->SetComponent(i, 0, 1);
  vtkNew<amCardiacLandmarks> landmarks;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(landmarks);
  landmarks->SetInputData(noHeart);
  landmarks->Update();
  EXPECT_TRUE(errors->ErrorContains("no left-ventricular blood pool")) << errors->AllErrors();
}

TEST(CardiacLandmarks, V1AndV2LieAtTheSternumsBordersWhereTheBoneShowsIt)
{
  // The phantom's exact labels (2 mm) with a sternum added: bone 24 mm wide centred 4 mm left of
  // the mid-line, under the front of the chest from the collar bones' level to the heart's apex.
  // V1 and V2 move from 25 mm either side of the skin's mid-line to its borders, and the sternum
  // is a landmark of its own; the phantom alone (its ribs end short of the mid-line) has none.
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(2, 2, 2);
  phantom->Update();
  auto* labels = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  vtkNew<vtkImageData> withSternum;
  withSternum->DeepCopy(labels);
  vtkDataArray* scalars = withSternum->GetPointData()->GetScalars();
  for (vtkIdType v = 0; v < withSternum->GetNumberOfPoints(); ++v)
  {
    double x[3];
    withSternum->GetPoint(v, x);
    if (std::fabs(x[0] - 4.0) <= 12.0 && x[1] >= -92.0 && x[1] <= -82.0 && x[2] >= -80.0 && x[2] <= 60.0)
      scalars->SetComponent(v, 0, amThoraxPhantomModel::Ribs);
  }
  vtkNew<amTest::ErrorCatcher> errors;
  const Points plain = Landmarks(phantom, errors);
  EXPECT_EQ(plain.count("Sternum"), 0u);
  const Points p = LandmarksOf(withSternum, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  ASSERT_EQ(p.size(), 14u);
  ASSERT_EQ(p.count("Sternum"), 1u);
  EXPECT_NEAR(p.at("Sternum")[0], 4.0, 1.5);
  EXPECT_NEAR(p.at("Sternum")[1], -87.0, 2.5);
  EXPECT_NEAR(p.at("Sternum")[2], p.at("V1")[2], 12.5);
  EXPECT_NEAR(p.at("V1")[0], 4.0 - 12.0, 3.5); // the right border, within a voxel (LPS: x grows to the left)
  EXPECT_NEAR(p.at("V2")[0], 4.0 + 12.0, 3.5);
  EXPECT_NEAR(plain.at("V1")[0], -25.0, 2.5);
  EXPECT_NEAR(plain.at("V2")[0], 25.0, 2.5);
  for (const char* lead : { "V1", "V2" })
    EXPECT_TRUE(OnSkin(phantom, p.at(lead), 3.0)) << lead;
  for (const char* other : { "V4", "V5", "V6", "RA", "LA", "LL", "Stimulus" }) // V3: half-way from V2 to V4
    EXPECT_EQ(Distance(p.at(other), plain.at(other)), 0.0) << other;
}

// The phantom's exact labels (2 mm, a field 520 mm wide) with arms down beside the body (soft
// tissue, 40 x 45 mm), gap mm from its side (negative: pressed against it); returns the body's
// half-width.
double PaintArms(amThoraxPhantomSource* phantom, vtkImageData* withArms, double gap)
{
  phantom->SetSpacing(2, 2, 2);
  phantom->SetFieldOfView(520, 240, 210);
  phantom->Update();
  withArms->DeepCopy(phantom->GetOutputDataObject(1));
  vtkDataArray* scalars = withArms->GetPointData()->GetScalars();
  double side = 0.0;
  for (vtkIdType v = 0; v < withArms->GetNumberOfPoints(); ++v)
    if (scalars->GetComponent(v, 0) != 0)
      side = std::max(side, std::fabs(withArms->GetPoint(v)[0]));
  vtkIdType armVoxels = 0;
  for (vtkIdType v = 0; v < withArms->GetNumberOfPoints(); ++v)
  {
    double x[3];
    withArms->GetPoint(v, x);
    if (std::hypot((std::fabs(x[0]) - side - gap - 40.0) / 40.0, x[1] / 45.0) > 1.0)
      continue;
    if (scalars->GetComponent(v, 0) != 0)
    {
      // An arm apart from the body never reaches into it; one pressed against it keeps the body's.
      EXPECT_LT(gap, 0.0) << "an arm crosses the body at " << x[0] << " " << x[1] << " " << x[2];
      continue;
    }
    scalars->SetComponent(v, 0, amThoraxPhantomModel::SoftTissue);
    ++armVoxels;
  }
  EXPECT_GT(armVoxels, 10000);
  return side;
}

TEST(CardiacLandmarks, ArmsBesideTheTrunkCarryNoElectrode)
{
  // Arms 8 mm from the body: on the whole body's skin V6 (its leftmost point) and the limb
  // electrodes (60 % of the way to its sides) would move onto the arms; on the trunk's skin every
  // landmark is where it is without them.
  vtkNew<amThoraxPhantomSource> phantom;
  vtkNew<vtkImageData> withArms;
  const double side = PaintArms(phantom, withArms, 8.0);
  vtkNew<amTest::ErrorCatcher> errors;
  const Points plain = Landmarks(phantom, errors), armed = LandmarksOf(withArms, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  ASSERT_EQ(armed.size(), plain.size());
  for (const auto& [name, x] : plain)
    EXPECT_LT(Distance(x, armed.at(name)), 1e-9) << name;
  EXPECT_LT(armed.at("V6")[0], side + 1.0);
}

TEST(CardiacLandmarks, ArmsAgainstTheTrunkCarryNoElectrode)
{
  // Arms pressed 4 mm into the body's side, one body with it (a contact 35 mm wide along the
  // whole field): the arm is a part of the body joined by a neck far thinner than its own depth,
  // not the trunk. Where the trunk's and the arm's basins meet is the watershed of the body's
  // depth, not the trunk's skin before the arm lay on it: the limb electrodes move by up to 15 mm
  // (84-109 mm onto the arm when the trunk was all the body joined to the heart), V6 by 8 (74).
  vtkNew<amThoraxPhantomSource> phantom;
  vtkNew<vtkImageData> withArms;
  const double side = PaintArms(phantom, withArms, -4.0);
  vtkNew<amTest::ErrorCatcher> errors;
  const Points plain = Landmarks(phantom, errors), armed = LandmarksOf(withArms, errors);
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  ASSERT_EQ(armed.size(), plain.size());
  for (const auto& [name, x] : plain)
    EXPECT_LT(Distance(x, armed.at(name)), name == "V6" ? 10.0 : 15.0) << name;
  EXPECT_LT(armed.at("V6")[0], side + 1.0);
}
