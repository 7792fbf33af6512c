// The whole simulation domain from a CT: every organ of the noisy phantom against its truth, a
// synthetic heart whose wall has no contrast, the voxel operations, and bad input.
#include "Torso/amTorsoLabels.h"
#include "Torso/amVoxelGrid.h"
#include "amFigures.h"
#include "amIntensityWindow.h"
#include "amSnakeSegmentation.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomModel.h"
#include "amThoraxPhantomSource.h"
#include "amTorsoSegmentation.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <random>

namespace
{
// The main job's clicks on the phantom: the LV and RV blood pools, and the aorta's two.
void AddMainJobClicks(amSnakeSegmentation* snake, bool aorta)
{
  snake->AddSeed(29.4, -24.1, -28.0, 6);
  snake->AddSeed(-15.0, -25.0, -28.0, 7);
  if (aorta)
  {
    snake->AddSeed(5.0, 40.0, 0.0, 8);
    snake->AddSeed(5.0, -20.0, 30.0, 8);
  }
}

// The phantom at 2 mm (20 HU of noise) and a snake on it with the main job's clicks in the pools.
struct PhantomWithPoolClicks
{
  vtkNew<amThoraxPhantomSource> Phantom;
  vtkNew<amSnakeSegmentation> Snake;
  PhantomWithPoolClicks()
  {
    this->Phantom->SetSpacing(2, 2, 2);
    this->Phantom->SetSeed(1);
    this->Snake->SetInputConnection(this->Phantom->GetOutputPort(0));
    AddMainJobClicks(this->Snake, false);
  }
};

double Dice(vtkImageData* seg, vtkImageData* truth, int label)
{
  vtkDataArray* a = seg->GetPointData()->GetScalars();
  vtkDataArray* b = truth->GetPointData()->GetScalars();
  long both = 0, na = 0, nb = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const bool p = a->GetComponent(i, 0) == label, q = b->GetComponent(i, 0) == label;
    both += p && q;
    na += p;
    nb += q;
  }
  return na + nb ? 2.0 * both / (na + nb) : 1.0;
}

// The box torso has neither fat nor bone: the segmentation says so (two warnings naming them);
// the other warnings are returned.
std::vector<std::string> BeyondFatAndBone(const std::vector<std::string>& warnings)
{
  std::vector<std::string> rest;
  int named = 0;
  for (const auto& w : warnings)
    if (w.find("intensity class") != std::string::npos)
      named += (w.find("no fat") != std::string::npos) + (w.find("no bone") != std::string::npos);
    else
      rest.push_back(w);
  EXPECT_EQ(named, 2) << "the missing fat and bone are named";
  return rest;
}

// A 2 mm box torso of soft tissue with a spherical heart: blood pool (label 6, radius 15 mm)
// inside a wall (radius 30 mm) of wallHU, two lungs, the air outside; f gives each voxel's
// label and value from its position.
struct Torso
{
  vtkNew<vtkImageData> CT, Organs, Truth;
  Torso(double wallHU, double noise)
  {
    const int n = 60;
    for (vtkImageData* image : { CT.Get(), Organs.Get(), Truth.Get() })
    {
      image->SetDimensions(n, n, n);
      image->SetSpacing(2, 2, 2);
      image->SetOrigin(-59, -59, -59);
    }
    vtkNew<vtkFloatArray> ct;
    vtkNew<vtkUnsignedCharArray> organs, truth;
    ct->SetNumberOfTuples(n * n * n);
    organs->SetNumberOfTuples(n * n * n);
    truth->SetNumberOfTuples(n * n * n);
    organs->SetName("Labels");
    truth->SetName("Labels");
    std::mt19937 random(7);
    std::normal_distribution<double> gauss(0.0, noise);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
          const double x = -59 + 2 * i, y = -59 + 2 * j, z = -59 + 2 * k;
          const double r = std::sqrt(x * x + y * y + z * z);
          int label = 1;
          double hu = 40;
          if (std::fabs(x) > 52 || std::fabs(y) > 52 || std::fabs(z) > 52)
            label = 0, hu = -1000;
          else if (r < 15)
            label = 6, hu = 300;
          else if (r < 30)
            label = 5, hu = wallHU;
          else if (std::fabs(x) > 36 && std::fabs(x) < 48 && std::fabs(y) < 30 && std::fabs(z) < 30)
            label = x < 0 ? 3 : 4, hu = -850;
          const vtkIdType id = (static_cast<vtkIdType>(k) * n + j) * n + i;
          ct->SetValue(id, static_cast<float>(hu + (label ? gauss(random) : 0.0)));
          organs->SetValue(id, label == 6 ? 6 : 0);
          truth->SetValue(id, static_cast<unsigned char>(label));
        }
    CT->GetPointData()->SetScalars(ct);
    Organs->GetPointData()->SetScalars(organs);
    Truth->GetPointData()->SetScalars(truth);
  }
};
}

TEST(TorsoSegmentation, EveryOrganOfTheNoisyPhantomFromThreeSeededOrgans)
{
  // 2 mm, the default noise (20 HU): the snake gives the blood pools and the aorta from four
  // seeds, the torso segmentation everything else.
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(2, 2, 2);
  phantom->SetSeed(1);
  vtkNew<amSnakeSegmentation> snake;
  snake->SetInputConnection(phantom->GetOutputPort(0));
  AddMainJobClicks(snake, true);
  vtkNew<amTorsoSegmentation> torso;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(torso);
  torso->SetInputConnection(phantom->GetOutputPort(0));
  torso->SetOrganConnection(snake->GetOutputPort());
  torso->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  EXPECT_TRUE(errors->Warnings.empty()) << errors->Warnings[0];
  auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
  auto* truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  for (int label = 1; label <= 10; ++label)
    EXPECT_GE(Dice(seg, truth, label), label == 10 ? 0.95 : 0.96) << "label " << label;
  vtkDataArray* levels = seg->GetFieldData()->GetArray("MyocardiumLevels");
  ASSERT_NE(levels, nullptr);
  EXPECT_NEAR(levels->GetComponent(0, 0), 50.0, 1.0); // the wall's level, HU
  EXPECT_NEAR(levels->GetComponent(1, 0), 40.0, 1.0); // the surroundings'
  EXPECT_EQ(levels->GetComponent(4, 0), 1.0);
  EXPECT_NE(seg->GetFieldData()->GetAbstractArray("LabelNames"), nullptr);
}

namespace
{
// The blood pools' faces on anything but the heart (myocardium or blood).
long ExposedPoolFaces(vtkImageData* seg)
{
  int n[3];
  seg->GetDimensions(n);
  vtkDataArray* l = seg->GetPointData()->GetScalars();
  auto at = [&](int i, int j, int k) { return static_cast<int>(l->GetComponent(i + n[0] * (j + n[1] * k), 0)); };
  long exposed = 0;
  for (int k = 1; k + 1 < n[2]; ++k)
    for (int j = 1; j + 1 < n[1]; ++j)
      for (int i = 1; i + 1 < n[0]; ++i)
      {
        const int v = at(i, j, k);
        if (v != 6 && v != 7)
          continue;
        for (const int m :
          { at(i - 1, j, k), at(i + 1, j, k), at(i, j - 1, k), at(i, j + 1, k), at(i, j, k - 1), at(i, j, k + 1) })
          exposed += m < 5 || m > 7;
      }
  return exposed;
}
}

// The phantom's thin-walled ventricles (LV 10 mm, RV 4 mm), pools from their clicks: at 1 mm the
// wall's intensity tells it, and the least wall keeps the pools inside it where the RV's 4 mm read as
// the tissue around them; at 2 mm intensity cannot tell the wall, and the RV's own nominal wall
// keeps its free wall 4 mm thick rather than the LV's 10.
TEST(TorsoSegmentation, AThinWalledHeartKeepsItsBloodInsideItsWall)
{
  for (const double spacing : { 1.0, 2.0 })
  {
    vtkNew<amThoraxPhantomSource> phantom;
    phantom->SetSpacing(spacing, spacing, spacing);
    phantom->SetHeartShape(amThoraxPhantomSource::VENTRICLES);
    vtkNew<amSnakeSegmentation> snake;
    snake->SetInputConnection(phantom->GetOutputPort(0));
    for (const int pool : { 6, 7 })
    {
      double c[3];
      phantom->GetOrganCenter(pool, c);
      snake->AddSeed(c[0], c[1], c[2], pool);
    }
    phantom->Update();
    auto* truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
    for (const bool usual : { true, false })
    {
      vtkNew<amTorsoSegmentation> torso;
      torso->SetInputConnection(phantom->GetOutputPort(0));
      torso->SetOrganConnection(snake->GetOutputPort());
      if (!usual && spacing == 1.0)
        torso->SetMinimumWallThickness(0);
      if (!usual && spacing == 2.0)
        torso->SetRightVentricleWallThickness(10);
      torso->Update();
      auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
      const double dice = Dice(seg, truth, 5);
      const long exposed = ExposedPoolFaces(seg);
      std::cout << "[ figures  ] ventricles at " << spacing << " mm" << (usual ? "" : ", without the fix")
                << ": myocardium Dice " << dice << ", pool faces on other tissue " << exposed << "\n";
      if (usual)
      {
        EXPECT_EQ(exposed, 0);
        EXPECT_GE(dice, 0.93);
        for (const int pool : { 6, 7 })
          EXPECT_GE(Dice(seg, truth, pool), 0.98) << pool;
      }
      else if (spacing == 1.0)
        EXPECT_GT(exposed, 50);
      else
        EXPECT_LT(dice, 0.9);
    }
  }
}

TEST(TorsoSegmentation, AScanWindowedAboveFatFindsItsLungsByDefault)
{
  // The phantom (3 mm) stored as the real chest CT is: 8 bits through a 600/300 HU window, so
  // fat, lung and air all read 0. Its blood pools come from its truth. With the defaults the
  // window sets the lung opening (12 mm: the fat beside the lungs is a thinner layer) and the gap
  // closing; without them the lungs take the fat around them.
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(3, 3, 3);
  phantom->SetSeed(1);
  phantom->Update();
  auto* ct = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(0));
  auto* truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  vtkNew<vtkImageData> windowed, organs;
  windowed->CopyStructure(ct);
  organs->CopyStructure(ct);
  vtkNew<vtkUnsignedCharArray> bytes, pools;
  const vtkIdType n = ct->GetNumberOfPoints();
  bytes->SetNumberOfTuples(n);
  pools->SetNumberOfTuples(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    const double hu = ct->GetPointData()->GetScalars()->GetComponent(v, 0);
    bytes->SetValue(v, static_cast<unsigned char>(std::lround(std::clamp(hu / 600.0 * 255.0, 0.0, 255.0))));
    const int l = static_cast<int>(truth->GetPointData()->GetScalars()->GetComponent(v, 0));
    pools->SetValue(v, l == 6 || l == 7 ? l : 0);
  }
  windowed->GetPointData()->SetScalars(bytes);
  organs->GetPointData()->SetScalars(pools);
  std::vector<double> lungs;
  for (const double setting : { -1.0, 0.0 })
  {
    vtkNew<amTorsoSegmentation> torso;
    EXPECT_EQ(torso->GetLungOpening(), -1.0);
    EXPECT_EQ(torso->GetBodyGapClosing(), -1.0);
    torso->SetInputData(windowed);
    torso->SetOrganData(organs);
    torso->SetInputWindow(600, 300);
    torso->SetLungOpening(setting);
    torso->SetBodyGapClosing(setting);
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(torso);
    torso->Update();
    ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
    auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
    lungs.push_back(std::min(Dice(seg, truth, 3), Dice(seg, truth, 4)));
  }
  EXPECT_GT(lungs[0], 0.95) << lungs[0] << " " << lungs[1];
  EXPECT_LT(lungs[1], lungs[0] - 0.02);
}

// The phantom's CT (3 mm) stored as a scan exported for viewing: 8 bits through a 400/40 window
// (fat reads 38, soft tissue 128, blood 217); the window recorded on the image, as amImageReader's
// IntensityWindow records it, serves both segmentations with their settings in HU: the torso
// segmentation needs no InputWindow, and the snake's least interval of 100 HU is 63.75 of the
// image's units (its intervals' upper bounds, mean + 100 HU, stand 36.25 units below those of the
// same image without the window, where 100 is read as units).
TEST(TorsoSegmentation, TheWindowTheImageCarriesServesBothSegmentations)
{
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(3, 3, 3);
  phantom->Update();
  auto* ct = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(0));
  auto* truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  const double window[2] = { 400.0, 40.0 };
  std::vector<std::vector<double>> upper;
  for (const bool carried : { true, false })
  {
    vtkNew<vtkImageData> windowed;
    windowed->CopyStructure(ct);
    vtkNew<vtkUnsignedCharArray> bytes;
    bytes->SetNumberOfTuples(ct->GetNumberOfPoints());
    for (vtkIdType v = 0; v < ct->GetNumberOfPoints(); ++v)
    {
      const double u = amIntensityWindow::Level(window, ct->GetPointData()->GetScalars()->GetComponent(v, 0));
      bytes->SetValue(v, static_cast<unsigned char>(std::lround(std::clamp(u, 0.0, 255.0))));
    }
    windowed->GetPointData()->SetScalars(bytes);
    if (carried)
      amIntensityWindow::Record(windowed, window);
    vtkNew<amSnakeSegmentation> snake;
    snake->SetInputData(windowed);
    AddMainJobClicks(snake, true);
    vtkNew<amTorsoSegmentation> torso;
    torso->SetInputData(windowed);
    torso->SetOrganConnection(snake->GetOutputPort());
    if (!carried)
      torso->SetInputWindow(window[0], window[1]);
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(torso);
    torso->Update();
    ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
    auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
    vtkDataArray* intervals = snake->GetOutput()->GetFieldData()->GetArray("Thresholds");
    ASSERT_NE(intervals, nullptr);
    upper.emplace_back();
    for (vtkIdType t = 0; t < intervals->GetNumberOfTuples(); ++t)
      upper.back().push_back(intervals->GetComponent(t, 2));
    std::cout << "[ figures  ] 400/40 window " << (carried ? "carried by the image" : "not carried, read as units")
              << ": LV " << Dice(seg, truth, 6) << ", RV " << Dice(seg, truth, 7) << ", myocardium "
              << Dice(seg, truth, 5) << ", lungs " << Dice(seg, truth, 3) << " " << Dice(seg, truth, 4) << "\n";
    if (carried)
    {
      for (const int label : { 3, 4, 6, 7, 8 })
        EXPECT_GE(Dice(seg, truth, label), 0.9) << label;
      EXPECT_GE(Dice(seg, truth, 5), 0.85);
    }
  }
  ASSERT_EQ(upper[0].size(), 3u); // LV, RV, aorta
  ASSERT_EQ(upper[1].size(), 3u);
  for (std::size_t t = 0; t < 3; ++t)
    EXPECT_NEAR(upper[1][t] - upper[0][t], 100.0 - 63.75, 1e-6) << t;
}

TEST(TorsoSegmentation, TheAortaIsFoundWithoutItsClick)
{
  // The phantom (2 mm, 20 HU of noise) with clicks in its blood pools alone: the aorta is the
  // contrast that runs down in front of the spine, with its arch and ascending part. With
  // FindAorta off, or on a scan without contrast (the blood at soft tissue's 40 HU), none.
  PhantomWithPoolClicks pools;
  amThoraxPhantomSource* phantom = pools.Phantom;
  amSnakeSegmentation* snake = pools.Snake;
  vtkNew<amTorsoSegmentation> torso;
  torso->SetInputConnection(phantom->GetOutputPort(0));
  torso->SetOrganConnection(snake->GetOutputPort());
  EXPECT_TRUE(torso->GetFindAorta());
  torso->Update();
  auto* truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
  const double aorta = Dice(seg, truth, amThoraxPhantomModel::Aorta);
  EXPECT_GE(aorta, 0.95);
  for (int label : { 6, 7, 9, 10 }) // the pools and the bone as with the aorta's clicks
    EXPECT_GE(Dice(seg, truth, label), 0.95) << "label " << label;
  amTest::RecordFigure("segmentation.aorta_without_click_dice", aorta, "", 0.95);

  torso->FindAortaOff();
  torso->Update();
  EXPECT_EQ(Dice(vtkImageData::SafeDownCast(torso->GetOutputDataObject(0)), truth, amThoraxPhantomModel::Aorta), 0.0);

  vtkNew<amThoraxPhantomSource> plain;
  plain->SetSpacing(2, 2, 2);
  plain->SetSeed(1);
  plain->SetBloodHounsfieldUnits(40.0);
  plain->Update();
  vtkNew<vtkImageData> pool; // the LV pool from the truth (a snake cannot find it without contrast)
  pool->DeepCopy(plain->GetOutputDataObject(1));
  vtkDataArray* poolLabels = pool->GetPointData()->GetScalars();
  for (vtkIdType v = 0; v < poolLabels->GetNumberOfTuples(); ++v)
    if (poolLabels->GetComponent(v, 0) != amThoraxPhantomModel::LeftVentricleBlood)
      poolLabels->SetComponent(v, 0, 0);
  vtkNew<amTorsoSegmentation> noContrast;
  noContrast->SetInputConnection(plain->GetOutputPort(0));
  noContrast->SetOrganData(pool);
  noContrast->Update();
  EXPECT_EQ(
    Dice(vtkImageData::SafeDownCast(noContrast->GetOutputDataObject(0)), truth, amThoraxPhantomModel::Aorta), 0.0);
}

TEST(TorsoSegmentation, AClickedAortaIsCompletedByTheTubeInFrontOfTheSpine)
{
  // One click in the ascending aorta, its snake reaching 40 mm beyond it: the arch and the
  // descending aorta lie beyond. FindAorta adds the contrast running down in front of the spine
  // that the click's snake did not reach; off, the aorta is the snake's part alone.
  PhantomWithPoolClicks pools;
  amThoraxPhantomSource* phantom = pools.Phantom;
  amSnakeSegmentation* snake = pools.Snake;
  snake->AddSeed(5.0, -20.0, 30.0, 8);
  snake->SetMaximumDistance(40.0);
  vtkNew<amTorsoSegmentation> torso;
  torso->SetInputConnection(phantom->GetOutputPort(0));
  torso->SetOrganConnection(snake->GetOutputPort());
  torso->Update();
  auto* truth = vtkImageData::SafeDownCast(phantom->GetOutputDataObject(1));
  const double completed =
    Dice(vtkImageData::SafeDownCast(torso->GetOutputDataObject(0)), truth, amThoraxPhantomModel::Aorta);
  torso->FindAortaOff();
  torso->Update();
  const double clicked =
    Dice(vtkImageData::SafeDownCast(torso->GetOutputDataObject(0)), truth, amThoraxPhantomModel::Aorta);
  std::cout << "aorta from one click: " << clicked << ", completed " << completed << std::endl;
  EXPECT_GE(completed, 0.95);
  EXPECT_LT(clicked, 0.9);
}

TEST(TorsoSegmentation, AWallWithContrastIsFoundAndOneWithoutIsTheNominalThickness)
{
  for (const double wall : { 55.0, 40.0 })
  {
    Torso t(wall, 20.0);
    vtkNew<amTorsoSegmentation> torso;
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(torso);
    torso->SetInputData(t.CT);
    torso->SetOrganData(t.Organs);
    torso->SetBloodPoolLabels(6, 7);
    torso->Update();
    ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
    errors->Warnings = BeyondFatAndBone(errors->Warnings);
    auto* seg = vtkImageData::SafeDownCast(torso->GetOutputDataObject(0));
    EXPECT_GE(Dice(seg, t.Truth, 3), 0.95);
    EXPECT_GE(Dice(seg, t.Truth, 4), 0.95);
    if (wall > 40)
    {
      // 15 HU of contrast: the wall is found at its 30 mm radius.
      EXPECT_GE(Dice(seg, t.Truth, 5), 0.95);
      EXPECT_TRUE(errors->Warnings.empty());
    }
    else
    {
      // No contrast: a warning, and the wall is 10 mm thick (radius 25 mm, 4/7 of the volume).
      ASSERT_EQ(errors->Warnings.size(), 1u);
      EXPECT_NE(errors->Warnings[0].find("cannot be told from the tissue around it"), std::string::npos);
      vtkDataArray* labels = seg->GetPointData()->GetScalars();
      double volume = 0;
      for (vtkIdType i = 0; i < labels->GetNumberOfTuples(); ++i)
        volume += labels->GetComponent(i, 0) == 5 ? 8.0 : 0.0;
      const double expected = 4.0 / 3.0 * M_PI * (25.0 * 25.0 * 25.0 - 15.0 * 15.0 * 15.0);
      EXPECT_NEAR(volume / expected, 1.0, 0.08);
    }
  }
}

TEST(TorsoSegmentation, WarningsNameTheMissingOrgan)
{
  Torso t(55.0, 20.0);
  vtkNew<amTorsoSegmentation> torso;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(torso);
  torso->SetInputData(t.CT);
  torso->Update(); // no organ map: no blood pool
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  errors->Warnings = BeyondFatAndBone(errors->Warnings);
  ASSERT_EQ(errors->Warnings.size(), 1u);
  EXPECT_NE(errors->Warnings[0].find("no myocardium"), std::string::npos) << errors->Warnings[0];

  // A "blood pool" seeded in soft tissue, away from the heart: the pool is not brighter than the
  // tissue around it.
  vtkNew<vtkImageData> wrong;
  wrong->DeepCopy(t.Organs);
  vtkDataArray* labels = wrong->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < wrong->GetNumberOfPoints(); ++i)
  {
    double x[3];
    wrong->GetPoint(i, x);
    labels->SetComponent(i, 0, std::hypot(x[0], x[1] - 40.0, x[2] - 40.0) < 8.0 ? 6 : 0);
  }
  torso->SetOrganData(wrong);
  errors->Warnings.clear();
  torso->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  bool named = false;
  for (const auto& w : errors->Warnings)
    named = named || w.find("are not brighter than the tissue around them") != std::string::npos;
  EXPECT_TRUE(named) << (errors->Warnings.empty() ? "no warning" : errors->Warnings[0]);

  // A scan cropped through the heart: the blood pool reaches the border.
  vtkNew<vtkImageData> cropped;
  cropped->DeepCopy(t.Organs);
  labels = cropped->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < cropped->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cropped->GetPoint(i, x);
    if (x[2] < -56 && std::hypot(x[0], x[1]) < 10)
      labels->SetComponent(i, 0, 6); // the pool runs out through the bottom slice
  }
  torso->SetOrganData(cropped);
  errors->Warnings.clear();
  torso->Update();
  named = false;
  for (const auto& w : errors->Warnings)
    named = named || w.find("may cut the heart") != std::string::npos;
  EXPECT_TRUE(named) << (errors->Warnings.empty() ? "no warning" : errors->Warnings[0]);
}

TEST(TorsoSegmentation, BadInputGivesClearErrors)
{
  Torso t(55.0, 0.0);
  vtkNew<amTorsoSegmentation> torso;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(torso);
  torso->SetInputData(t.CT);
  vtkNew<vtkImageData> small;
  small->SetDimensions(4, 4, 4);
  small->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  torso->SetOrganData(small);
  torso->Update();
  EXPECT_TRUE(errors->ErrorContains("must share one grid")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkImageData> floats;
  floats->DeepCopy(t.Organs);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfTuples(floats->GetNumberOfPoints());
  values->FillValue(0.5f);
  floats->GetPointData()->SetScalars(values);
  torso->SetOrganData(floats);
  torso->Update();
  EXPECT_TRUE(errors->ErrorContains("whole numbers")) << errors->AllErrors();

  errors->Errors.clear();
  torso->SetOrganData(t.Organs);
  vtkFloatArray::SafeDownCast(t.CT->GetPointData()->GetScalars())->SetValue(100, std::nanf(""));
  t.CT->Modified();
  torso->Update();
  EXPECT_TRUE(errors->ErrorContains("non-finite value")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkImageData> empty;
  torso->SetInputData(empty);
  torso->Update();
  EXPECT_TRUE(errors->ErrorContains("empty")) << errors->AllErrors();
}

TEST(VoxelGrid, HolesSpecksAndHandOver)
{
  amVoxelGrid g;
  g.N[0] = g.N[1] = g.N[2] = 12;
  // A hollow cube (walls 2 voxels) of label 1 with one voxel of label 2 in its wall, and a
  // separate speck of label 1.
  std::vector<std::uint8_t> labels(g.Size(), 0);
  amVoxelMask shell(g.Size(), 0);
  for (int k = 1; k < 9; ++k)
    for (int j = 1; j < 9; ++j)
      for (int i = 1; i < 9; ++i)
      {
        const bool inner = i >= 3 && i < 7 && j >= 3 && j < 7 && k >= 3 && k < 7;
        labels[g.Index(i, j, k)] = inner ? 0 : 1;
        shell[g.Index(i, j, k)] = !inner;
      }
  labels[g.Index(1, 4, 4)] = 2;
  labels[g.Index(1, 5, 4)] = 2;
  labels[g.Index(4, 4, 1)] = 2;
  labels[g.Index(10, 10, 10)] = 1;
  amVoxelMask filled = shell;
  EXPECT_EQ(amVoxel::FillHoles(g, filled), 64u);
  EXPECT_EQ(amVoxel::Erode26(g, shell)[g.Index(2, 2, 2)], 0); // beside the cavity
  EXPECT_EQ(amVoxel::Erode26(g, filled)[g.Index(2, 2, 2)], 1);
  EXPECT_EQ(amVoxel::Erode26(g, filled)[g.Index(1, 1, 1)], 0);

  std::vector<bool> single(256, false);
  single[2] = true;
  std::vector<std::uint8_t> cleaned = labels;
  // The speck of label 1 (below 2 voxels) and label 2's smaller piece (label 2 keeps one piece)
  // go to their neighbours; a label's largest piece is kept whatever its size.
  EXPECT_EQ(amVoxel::DropSmallComponents(g, cleaned, 2, single), 2u);
  EXPECT_EQ(cleaned[g.Index(10, 10, 10)], 0);
  EXPECT_EQ(cleaned[g.Index(4, 4, 1)], 1);
  EXPECT_EQ(cleaned[g.Index(1, 4, 4)], 2);

  std::vector<std::uint8_t> pending(g.Size(), amVoxel::Pending);
  EXPECT_EQ(amVoxel::HandOver(g, pending), g.Size());
  EXPECT_EQ(pending[0], 0); // nothing to hand them to: background
}

TEST(TorsoSegmentation, AnImageWithNoSoftTissueClassIsRefusedNamingIt)
{
  // A CT stored unsigned without its rescale: every tissue 1024 HU too bright.
  Torso t(55.0, 20.0);
  vtkDataArray* ct = t.CT->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < ct->GetNumberOfTuples(); ++i)
    ct->SetComponent(i, 0, ct->GetComponent(i, 0) + 1024.0);
  vtkNew<amTorsoSegmentation> torso;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(torso);
  torso->SetInputData(t.CT);
  torso->Update();
  ASSERT_TRUE(errors->HasError());
  EXPECT_NE(errors->AllErrors().find("rescale"), std::string::npos) << errors->AllErrors();
  // With the fixed ranges it is classified (wrongly) without complaint: the automatic classes are
  // what notices.
  torso->AutomaticClassesOff();
  errors->Errors.clear();
  torso->Update();
  EXPECT_FALSE(errors->HasError()) << errors->AllErrors();
}

TEST(VoxelOperations, SliceHolesAreWhatARingEnclosesInOneSlice)
{
  amVoxelGrid g;
  g.N[0] = g.N[1] = 12;
  g.N[2] = 3;
  amVoxelMask ring(g.Size(), 0);
  // A square ring (3..8) in slice 1, and an open U in slice 2.
  for (int j = 3; j <= 8; ++j)
    for (int i = 3; i <= 8; ++i)
      if (i == 3 || i == 8 || j == 3 || j == 8)
      {
        ring[g.Index(i, j, 1)] = 1;
        if (j != 8)
          ring[g.Index(i, j, 2)] = 1;
      }
  const amVoxelMask holes = amVoxel::SliceHoles(g, ring, 2, 100);
  std::size_t inside = 0, other = 0;
  for (std::size_t v = 0; v < holes.size(); ++v)
  {
    int c[3];
    g.Ijk(v, c);
    (c[2] == 1 ? inside : other) += holes[v];
  }
  EXPECT_EQ(inside, 16u); // the 4x4 inside the ring
  EXPECT_EQ(other, 0u);   // the U is open; slice 0 is empty
  // Holes larger than the bound are not filled (a rib cage encloses the whole chest).
  const amVoxelMask small = amVoxel::SliceHoles(g, ring, 2, 15);
  EXPECT_EQ(std::count(small.begin(), small.end(), 1), 0);
}

TEST(TorsoTissues, JoinedLungsArePartedWhereTheyMeetNotAtTheMidPlane)
{
  // Two lungs (balls of radius 30 mm at x = -60 and x = +10) joined by an airway of radius 5 mm, in
  // a box of soft tissue centred on x = 0: the body's mid-plane would cut the left lung.
  amVoxelGrid g;
  g.N[0] = 110;
  g.N[1] = g.N[2] = 50;
  g.Spacing[0] = g.Spacing[1] = g.Spacing[2] = 2.0;
  std::vector<std::uint8_t> classes(g.Size()), truth(g.Size());
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        const double x = -109 + 2 * i, y = -49 + 2 * j, z = -49 + 2 * k;
        const std::size_t v = g.Index(i, j, k);
        const bool body = std::fabs(x) < 100 && std::fabs(y) < 44 && std::fabs(z) < 44;
        const bool right = std::hypot(x + 60, y, z) < 30, left = std::hypot(x - 10, y, z) < 30;
        const bool airway = x > -35 && x < -15 && std::hypot(y, z) < 5;
        classes[v] = !body ? amTorso::AirClass : right || left || airway ? amTorso::LungClass : amTorso::SoftClass;
        truth[v] = !body ? 0 : left ? 4 : right ? 3 : airway ? 255 : 1;
      }
  const double worldX[4] = { 2.0, 0.0, 0.0, -109.0 };
  amTorso::TissueParameters p;
  p.MinimumVoxels = 10;
  std::vector<std::uint8_t> labels;
  const amTorso::TissueReport report = amTorso::Tissues(g, classes, worldX, p, labels);
  EXPECT_TRUE(report.LungsSplit);
  EXPECT_FALSE(report.LungsSplitAtMidPlane);
  for (const int lung : { 3, 4 })
  {
    std::size_t both = 0, a = 0, b = 0;
    for (std::size_t v = 0; v < g.Size(); ++v)
    {
      if (truth[v] == 255)
        continue; // the airway goes to either side
      both += labels[v] == lung && truth[v] == lung;
      a += labels[v] == lung;
      b += truth[v] == lung;
    }
    EXPECT_GT(2.0 * both / (a + b), 0.99) << "lung " << lung;
  }
  // A single ball is not two lungs: no depth parts it, and it is split at the mid-plane.
  for (std::size_t v = 0; v < g.Size(); ++v)
    if (classes[v] == amTorso::LungClass)
    {
      int c[3];
      g.Ijk(v, c);
      const double x = -109 + 2 * c[0], y = -49 + 2 * c[1], z = -49 + 2 * c[2];
      if (std::hypot(x - 10, y, z) >= 30)
        classes[v] = amTorso::SoftClass;
    }
  EXPECT_TRUE(amTorso::Tissues(g, classes, worldX, p, labels).LungsSplitAtMidPlane);
}

TEST(VoxelOperations, BasinsArePartsJoinedByThinnerNecks)
{
  // Two balls of radius 12 mm joined by a tube of radius 3 mm: two basins; a ball with a bump
  // of 2 mm on its side: one.
  amVoxelGrid g;
  g.N[0] = 70;
  g.N[1] = g.N[2] = 30;
  std::vector<std::uint8_t> mask(g.Size()), bumped(g.Size());
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        const double y = j - 15, z = k - 15;
        const bool a = std::hypot(i - 15, y, z) < 12, b = std::hypot(i - 55, y, z) < 12;
        mask[g.Index(i, j, k)] = a || b || (i > 15 && i < 55 && std::hypot(y, z) < 3);
        bumped[g.Index(i, j, k)] = a || std::hypot(i - 27, y, z) < 2;
      }
  for (const auto* m : { &mask, &bumped })
  {
    amVoxelMask outside(g.Size());
    for (std::size_t v = 0; v < g.Size(); ++v)
      outside[v] = !(*m)[v];
    std::vector<int> basin;
    const int count = amVoxel::Basins(g, *m, amVoxel::Distance(g, outside), 2.0, basin);
    EXPECT_EQ(count, m == &mask ? 2 : 1);
    EXPECT_EQ(basin[g.Index(15, 15, 15)], 0);
    EXPECT_EQ(basin[g.Index(0, 0, 0)], -1);
    if (m == &mask)
    {
      EXPECT_EQ(basin[g.Index(55, 15, 15)], 1);
      EXPECT_EQ(basin[g.Index(30, 15, 15)], 0); // the tube's half nearer each ball is its
      EXPECT_EQ(basin[g.Index(40, 15, 15)], 1);
    }
  }
}

TEST(TorsoTissues, GasBelowTheDiaphragmIsNotLung)
{
  // A lung (a half-ball of radius 40 mm, flat side down, with a wedge of a recess going down at
  // its back) above a diaphragm 10 mm thick, and a bubble of gas (radius 15 mm) below it, joined to
  // the recess by a passage of radius 3 mm; the head is at high k (superiorSign +1), then the same
  // stored the other way up.
  for (const int sign : { 1, -1 })
  {
    amVoxelGrid g;
    g.N[0] = g.N[1] = 60;
    g.N[2] = 80;
    g.Spacing[0] = g.Spacing[1] = g.Spacing[2] = 2.0;
    amVoxelMask air(g.Size());
    std::vector<std::uint8_t> truth(g.Size());
    for (int k = 0; k < g.N[2]; ++k)
      for (int j = 0; j < g.N[1]; ++j)
        for (int i = 0; i < g.N[0]; ++i)
        {
          const double x = 2 * i - 60, y = 2 * j - 60, z = sign > 0 ? 2 * k - 80 : 78 - 2 * k;
          const bool lung = (z > 0 && std::hypot(x, y, z) < 40) ||
            (y > 20 && y < 36 && z > -40 && z <= 0 && std::fabs(x) < 20 + 0.5 * z);
          const bool gas = std::hypot(x, y + 10, z + 35) < 15;
          const bool passage = std::hypot(x, y - 24) < 3 && z > -40 && z <= -30;
          air[g.Index(i, j, k)] = lung || gas || passage;
          truth[g.Index(i, j, k)] = lung ? 1 : gas ? 2 : 0;
        }
    const amVoxelMask below = amTorso::GasBelowLungs(g, air, 2, sign);
    std::size_t gas = 0, gasBelow = 0, lung = 0, lungBelow = 0;
    for (std::size_t v = 0; v < g.Size(); ++v)
    {
      gas += truth[v] == 2;
      gasBelow += truth[v] == 2 && below[v];
      lung += truth[v] == 1;
      lungBelow += truth[v] == 1 && below[v];
    }
    EXPECT_EQ(gasBelow, gas) << "sign " << sign;
    EXPECT_LT(lungBelow, lung / 200) << "sign " << sign;
    // With the head-feet axis unknown nothing is dropped.
    const amVoxelMask none = amTorso::GasBelowLungs(g, air, -1, sign);
    EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
  }
}

namespace
{
// Voxels of each truth class (0, 1, 2) and those of them labelled bone (spine or ribs).
struct BoneCount
{
  std::size_t Voxels[3] = { 0, 0, 0 };
  std::size_t Bone[3] = { 0, 0, 0 };
};

BoneCount CountBone(const std::vector<std::uint8_t>& labels, const std::vector<std::uint8_t>& truth)
{
  BoneCount count;
  for (std::size_t v = 0; v < labels.size(); ++v)
  {
    ++count.Voxels[truth[v]];
    count.Bone[truth[v]] += labels[v] == amThoraxPhantomModel::Spine || labels[v] == amThoraxPhantomModel::Ribs;
  }
  return count;
}
}

TEST(TorsoTissues, TrabecularBoneIsWhatTheCortexEnclosesInAnySlice)
{
  // A vertebral body: a cylinder (radius 10 mm, 20 mm tall, axis along k) of cortex 1.5 mm thick
  // with end plates, its side wall broken by a vertical slit (a foramen: no axial slice is closed),
  // filled with marrow 2.5 deviations above soft tissue; behind it a canal (a closed ring in every
  // axial slice) holding fluid darker than soft tissue.
  amVoxelGrid g;
  g.N[0] = g.N[1] = g.N[2] = 48;
  std::vector<std::uint8_t> classes(g.Size());
  std::vector<float> hu(g.Size());
  std::vector<std::uint8_t> truth(g.Size());
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        const std::size_t v = g.Index(i, j, k);
        const double r = std::hypot(i - 20.0, j - 20.0), canal = std::hypot(i - 20.0, j - 36.0);
        const bool body = i > 1 && j > 1 && i < 46 && j < 46;
        const bool inside = r < 10.0 && k >= 10 && k <= 30;
        const bool slit = std::fabs(i - 20.0) < 1.0 && j < 20 && r >= 8.5;
        const bool cortex = inside && (r >= 8.5 || k < 12 || k > 28) && !slit;
        const bool marrow = inside && !cortex && r < 8.5;
        const bool ring = canal >= 3.5 && canal < 5.0 && k >= 5 && k <= 35;
        classes[v] = !body ? amTorso::AirClass : cortex || ring ? amTorso::BoneClass : amTorso::SoftClass;
        hu[v] = !body ? -1000.0f : cortex || ring ? 800.0f : marrow ? 90.0f : canal < 3.5 ? 10.0f : 40.0f;
        truth[v] = marrow ? 1 : canal < 3.5 && k > 5 && k < 35 ? 2 : 0;
      }
  const double worldX[4] = { 1.0, 0.0, 0.0, -24.0 };
  amTorso::TissueParameters p;
  p.MinimumVoxels = 10;
  p.HU = hu.data();
  p.TrabecularLevel = 40.0 + 20.0; // soft tissue's centre and one deviation
  std::vector<std::uint8_t> labels;
  amTorso::Tissues(g, classes, worldX, p, labels);
  const BoneCount count = CountBone(labels, truth);
  const std::size_t marrow = count.Voxels[1], marrowBone = count.Bone[1], fluid = count.Voxels[2],
                    fluidBone = count.Bone[2];
  ASSERT_GT(marrow, 3000u);
  EXPECT_GT(marrowBone, 0.99 * marrow); // closed in sagittal and coronal slices, not in axial ones
  EXPECT_EQ(fluidBone, 0u);             // enclosed, but darker than marrow
  ASSERT_GT(fluid, 500u);
}

TEST(VoxelOperations, HandOverKeepsARefusedLabelWhileAnotherReaches)
{
  // A row of voxels: label 3 (lung) | two pending voxels | label 1 (tissue); the pending voxel
  // beside the lung refuses it and takes the tissue through its pending neighbour. A pending voxel
  // whose only neighbours are refused takes them.
  amVoxelGrid g;
  g.N[0] = 8;
  g.N[1] = g.N[2] = 1;
  std::vector<std::uint8_t> labels = { 3, 3, 3, amVoxel::Pending, amVoxel::Pending, 1, 1, 1 };
  const auto refuses = [](std::size_t, std::uint8_t l) { return l == 3; };
  std::vector<std::uint8_t> free = labels;
  amVoxel::HandOver(g, free);
  EXPECT_EQ(free[3], 3); // unconstrained, the lung's front reaches it first
  EXPECT_EQ(amVoxel::HandOver(g, labels, refuses), 2u);
  EXPECT_EQ(labels[3], 1);
  EXPECT_EQ(labels[4], 1);
  std::vector<std::uint8_t> enclosed = { 3, 3, 3, amVoxel::Pending, 3, 3, 3, 3 };
  amVoxel::HandOver(g, enclosed, refuses);
  EXPECT_EQ(enclosed[3], 3);
}

TEST(TorsoTissues, ContrastConnectedToThePoolsIsNeverBone)
{
  // A blood pool (radius 10 mm, 250 HU) with a vessel (radius 3 mm) to a bolus of dense contrast
  // (radius 6 mm, 600 HU: the window's ceiling, as bright as the cortex); apart from them, 5 mm of
  // soft tissue away, a vertebra: a cylinder of cortex 2 mm thick (600 HU) around marrow of 200 HU
  // (in the blood's range). The bolus is blood whatever the window; where the window clips bone,
  // the vertebra is its cortex and the marrow it reaches.
  amVoxelGrid g;
  g.N[0] = 80;
  g.N[1] = g.N[2] = 44;
  std::vector<std::uint8_t> classes(g.Size()), truth(g.Size()), organs(g.Size(), 0);
  std::vector<float> hu(g.Size());
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        const std::size_t v = g.Index(i, j, k);
        const bool body = i > 1 && j > 1 && i < 78 && j < 42;
        const bool pool = std::hypot(i - 15.0, j - 22.0, k - 22.0) < 10.0;
        const bool vessel = i >= 15 && i <= 35 && std::hypot(j - 22.0, k - 22.0) < 3.0;
        const bool bolus = std::hypot(i - 35.0, j - 22.0, k - 22.0) < 6.0;
        const double r = std::hypot(i - 60.0, j - 22.0);
        const bool vertebra = r < 12.0 && k > 6 && k < 38;
        const bool cortex = vertebra && (r >= 10.0 || k < 9 || k > 35);
        hu[v] = !body ? -1000.0f : bolus || cortex ? 600.0f : pool || vessel ? 250.0f : vertebra ? 200.0f : 41.0f;
        classes[v] = !body  ? amTorso::AirClass
          : hu[v] >= 600.0f ? amTorso::BoneClass
          : hu[v] >= 200.0f ? amTorso::BloodClass
                            : amTorso::SoftClass;
        organs[v] = pool ? 6 : 0;
        truth[v] = vertebra ? 1 : bolus ? 2 : 0;
      }
  amVoxelMask pools(g.Size());
  for (std::size_t v = 0; v < g.Size(); ++v)
    pools[v] = organs[v] == 6;
  const amVoxelMask vessels = amTorso::ContrastVessels(g, hu.data(), 200.0f, pools);
  const double worldX[4] = { 1.0, 0.0, 0.0, -40.0 };
  for (const bool clipped : { false, true })
  {
    amTorso::TissueParameters p;
    p.MinimumVoxels = 10;
    p.HU = hu.data();
    p.TrabecularLevel = 60.0;
    p.Vessels = &vessels;
    p.BoneClipped = clipped;
    p.CortexLevel = 400.0;
    p.MarrowLevel = 200.0 - 1.0;
    std::vector<std::uint8_t> labels;
    amTorso::Tissues(g, classes, worldX, p, labels);
    const BoneCount count = CountBone(labels, truth);
    const std::size_t vertebra = count.Voxels[1], vertebraBone = count.Bone[1], bolusBone = count.Bone[2],
                      otherBone = count.Bone[0];
    EXPECT_EQ(bolusBone, 0u) << "clipped " << clipped;
    EXPECT_EQ(otherBone, 0u) << "clipped " << clipped;
    // Unclipped, the marrow is what the cortex encloses; clipped, what it reaches.
    EXPECT_GT(vertebraBone, 0.99 * vertebra) << "clipped " << clipped;
  }
}

TEST(TorsoTissues, RibsJoinedToTheSpineAreParted)
{
  // A skeleton at 2 mm (x to the patient's left, y to the back, z to the head): five vertebrae
  // (bodies of radius 15 mm, 20 mm tall, discs of 4 mm between them; a spinous process behind
  // and transverse processes reaching 40 mm either side), a pair of ribs joined to each body's
  // sides and running 120 mm out, a sternum in front, and two humeral heads (radius 22 mm, deeper
  // than any vertebral body) far to the sides, joined to the ribs. All one piece of bone.
  amVoxelGrid g;
  g.N[0] = 130, g.N[1] = 90, g.N[2] = 60;
  g.Spacing[0] = g.Spacing[1] = g.Spacing[2] = 2.0;
  amVoxelMask bone(g.Size(), 0);
  std::vector<std::uint8_t> part(g.Size(), 0); // 1 vertebra, 2 rib, 3 sternum, 4 humerus
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        const double x = 2.0 * i - 130.0, y = 2.0 * j - 90.0, z = 2.0 * k;
        const double level = std::fmod(z - 2.0, 24.0); // within a vertebra: 0..20, a disc beyond
        const bool inColumn = z >= 2.0 && z < 118.0 && level < 20.0;
        const bool body = inColumn && std::hypot(x, y - 20.0) < 15.0;
        const bool spinous = inColumn && std::fabs(x) < 3.0 && y >= 30.0 && y < 60.0;
        const bool transverse = inColumn && std::fabs(level - 6.0) < 4.0 && std::fabs(x) < 40.0 && y >= 30.0 &&
          y < 38.0 && std::fabs(x) >= 2.0;
        const bool rib = inColumn && std::fabs(level - 14.0) < 4.0 && std::fabs(x) >= 14.0 && std::fabs(x) < 120.0 &&
          y >= 16.0 && y < 24.0;
        const bool sternum = std::fabs(x) < 12.0 && y >= -80.0 && y < -68.0 && z >= 10.0 && z < 110.0;
        const bool humerus = std::hypot(std::fabs(x) - 110.0, y - 0.0, z - 100.0) < 22.0 ||
          (std::fabs(x) >= 105.0 && std::fabs(x) < 115.0 && y >= 0.0 && y < 24.0 && std::fabs(z - 86.0) < 4.0);
        const std::size_t v = g.Index(i, j, k);
        part[v] = body || spinous || transverse ? 1 : rib ? 2 : sternum ? 3 : humerus ? 4 : 0;
        bone[v] = part[v] != 0;
      }
  const double worldX[4] = { 2.0, 0.0, 0.0, -130.0 };
  amTorso::ColumnParameters p;
  p.Midline = 0.0;
  const amVoxelMask column = amTorso::VertebralColumn(g, bone, worldX, 2, p);
  std::size_t count[5] = { 0, 0, 0, 0, 0 }, inColumn[5] = { 0, 0, 0, 0, 0 }, farRib = 0;
  for (std::size_t v = 0; v < g.Size(); ++v)
  {
    ++count[part[v]];
    inColumn[part[v]] += column[v] != 0;
    int c[3];
    g.Ijk(v, c);
    farRib += part[v] == 2 && column[v] && std::fabs(2.0 * c[0] - 130.0) > 38.0;
  }
  ASSERT_GT(count[1], 10000u);
  ASSERT_GT(count[2], 5000u);
  EXPECT_GT(inColumn[1], 0.99 * count[1]); // bodies, spinous and transverse processes
  EXPECT_LT(inColumn[2], 0.25 * count[2]); // the ribs' heads and necks within 35 mm
  EXPECT_EQ(farRib, 0u);
  EXPECT_EQ(inColumn[3], 0u); // in the band, but thin
  EXPECT_EQ(inColumn[4], 0u); // deep, but far from the midline
  EXPECT_EQ(inColumn[0], 0u);
  // Without a head-feet axis, the bone is one column.
  EXPECT_EQ(amTorso::VertebralColumn(g, bone, worldX, -1, p), bone);
}

TEST(TorsoSegmentation, TheAscendingAortaIsTakenBackFromTheAtria)
{
  // A tube 24 mm wide running down (1 mm voxels, the head towards k or -k): the aorta's label
  // above, the atria's for 15 mm (the atria's snake took it), the LV's below (the root opens into
  // it); an atrium touching the tube's side; a descending aorta 12 mm wide; and a second tube
  // ending on a wide atrium under it. The first tube's atrial part becomes aorta, the atria keep
  // theirs (less the tube's margin), the LV its own.
  for (const int sign : { 1, -1 })
  {
    amVoxelGrid g;
    g.N[0] = 110;
    g.N[1] = 70;
    g.N[2] = 40;
    std::vector<std::uint8_t> labels(g.Size(), 0), truth(g.Size(), 0);
    for (int k = 0; k < g.N[2]; ++k)
      for (int j = 0; j < g.N[1]; ++j)
        for (int i = 0; i < g.N[0]; ++i)
        {
          const int up = sign > 0 ? k : g.N[2] - 1 - k; // height above the bottom slice
          std::uint8_t l = 0, t = 0;
          if (std::hypot(i - 42, j - 30, up - 15) < 12)
            l = t = amTorso::Atria;
          if (std::hypot(i - 75, j - 30) < 30 && up < 20)
            l = t = amTorso::Atria; // the wide atrium under the second tube
          if (std::hypot(i - 20, j - 30) < 12)
          {
            l = up >= 25 ? amThoraxPhantomModel::Aorta
              : up >= 10 ? amTorso::Atria
                         : amThoraxPhantomModel::LeftVentricleBlood;
            t = up >= 10 ? amThoraxPhantomModel::Aorta : amThoraxPhantomModel::LeftVentricleBlood;
          }
          if (std::hypot(i - 75, j - 30) < 12 && up >= 20)
            l = t = amThoraxPhantomModel::Aorta;
          if (std::hypot(i - 20, j - 62) < 6)
            l = t = amThoraxPhantomModel::Aorta;
          labels[g.Index(i, j, k)] = l;
          truth[g.Index(i, j, k)] = t;
        }
    std::size_t tubeAtria = 0;
    for (std::size_t v = 0; v < g.Size(); ++v)
      tubeAtria += truth[v] == amThoraxPhantomModel::Aorta && labels[v] == amTorso::Atria;
    const std::size_t moved = amTorso::AortaOutOfAtria(g, 2, sign, amTorso::AscendingAortaParameters(), labels);
    std::size_t tube = 0, tubeTaken = 0, atria = 0, atriaKept = 0, lv = 0, lvKept = 0;
    for (std::size_t v = 0; v < g.Size(); ++v)
    {
      const bool inTube = truth[v] == amThoraxPhantomModel::Aorta;
      tube += inTube;
      tubeTaken += inTube && labels[v] == amThoraxPhantomModel::Aorta;
      atria += truth[v] == amTorso::Atria;
      atriaKept += truth[v] == amTorso::Atria && labels[v] == amTorso::Atria;
      lv += truth[v] == amThoraxPhantomModel::LeftVentricleBlood;
      lvKept += labels[v] == amThoraxPhantomModel::LeftVentricleBlood;
    }
    EXPECT_EQ(tubeTaken, tube) << "sign " << sign;
    EXPECT_GT(atriaKept, 0.97 * atria) << "sign " << sign;
    EXPECT_EQ(lvKept, lv) << "sign " << sign;
    EXPECT_GT(tubeAtria, 15u * 400u);
    EXPECT_EQ(moved, tubeAtria + (atria - atriaKept)) << "sign " << sign;
  }
}

TEST(TorsoSegmentation, TheRightVentricleEndsAtTheHeartsBase)
{
  // 1 mm voxels. The LV's pool a half-ellipsoid from its base at x = 20 (radius 10 mm) to its apex at
  // x = 60; the atria a ball against its base; the RV's pool a box beside it from x = 0 to 54, its
  // part more than 10 mm above the base (x < 10) the right atrium its snake ran into.
  amVoxelGrid g;
  g.N[0] = 70;
  g.N[1] = 60;
  g.N[2] = 60;
  using P = amThoraxPhantomModel;
  const auto make = [&](bool withAtria) {
    std::vector<std::uint8_t> labels(g.Size(), 0);
    for (int k = 0; k < g.N[2]; ++k)
      for (int j = 0; j < g.N[1]; ++j)
        for (int i = 0; i < g.N[0]; ++i)
        {
          std::uint8_t& l = labels[g.Index(i, j, k)];
          const double t = (i - 20) / 40.0, r2 = (j - 30) * (j - 30) + (k - 30) * (k - 30);
          if (i >= 20 && t <= 1.0 && r2 <= 100.0 * (1.0 - t * t) + 1e-9)
            l = P::LeftVentricleBlood;
          else if (withAtria && std::hypot(i - 10, j - 30, k - 30) < 10.0)
            l = amTorso::Atria;
          if (i < 55 && j >= 42 && j < 50 && k >= 25 && k < 35)
            l = P::RightVentricleBlood;
        }
    return labels;
  };
  std::vector<std::uint8_t> labels = make(true);
  const amTorso::ValvePlane base = amTorso::FindValvePlane(g, labels, P::LeftVentricleBlood);
  ASSERT_TRUE(base.Found);
  EXPECT_NEAR(base.Point[0], 20.0, 1e-9);
  EXPECT_NEAR(base.Normal[0], 1.0, 1e-9);
  EXPECT_EQ(amTorso::EndVentriclesAtValves(g, base, P::RightVentricleBlood, 10.0, labels), 10u * 8u * 10u);
  for (int i = 0; i < 55; ++i)
    EXPECT_EQ(labels[g.Index(i, 45, 30)], i < 10 ? amTorso::Atria : P::RightVentricleBlood) << i;
  // Without atria or an aorta against the LV (the phantom's capped heart), no base: nothing moves.
  labels = make(false);
  const amTorso::ValvePlane none = amTorso::FindValvePlane(g, labels, P::LeftVentricleBlood);
  EXPECT_FALSE(none.Found);
  EXPECT_EQ(amTorso::EndVentriclesAtValves(g, none, P::RightVentricleBlood, 10.0, labels), 0u);
}

TEST(TorsoSegmentation, AVentriclesBloodLiesInsideItsWall)
{
  // 1 mm voxels, a scan whose wall shows no contrast (every voxel 40 HU: the fallback wall). The LV's
  // pool a ball (radius 10 mm) with the atria against its base; the RV's pool a box beside it whose
  // free side lies against fat (a 4 mm wall lost in partial volume), 8 mm of it; soft tissue
  // elsewhere. Below the base the fat within the RV's wall thickness (4 mm) of its pool is wall, the
  // fat beyond stays fat; above the base (the atria's side) no wall grows.
  amVoxelGrid g;
  g.N[0] = g.N[1] = g.N[2] = 64;
  using P = amThoraxPhantomModel;
  std::vector<std::uint8_t> labels(g.Size(), P::SoftTissue);
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < g.N[0]; ++i)
      {
        std::uint8_t& l = labels[g.Index(i, j, k)];
        if (std::hypot(i - 32, j - 30, k - 32) <= 10.0)
          l = P::LeftVentricleBlood;
        else if (std::hypot(i - 16, j - 30, k - 32) <= 6.0)
          l = amTorso::Atria;
        else if (i >= 24 && i < 44 && j >= 44 && j < 52 && k >= 26 && k < 38)
          l = P::RightVentricleBlood;
        else if (i >= 24 && i < 44 && j >= 52 && j < 60 && k >= 26 && k < 38)
          l = P::Fat;
      }
  const std::vector<float> hu(g.Size(), 40.0f);
  std::vector<std::uint8_t> classes(g.Size(), amTorso::SoftClass);
  amTorso::WallParameters p;
  p.Base = amTorso::FindValvePlane(g, labels, P::LeftVentricleBlood);
  ASSERT_TRUE(p.Base.Found);
  amTorso::MyocardiumWall(g, hu.data(), classes, p, labels);
  for (int j = 52; j < 60; ++j)
    EXPECT_EQ(labels[g.Index(34, j, 32)], j < 56 ? P::Myocardium : P::Fat) << j;
  // The base lies at x = 22 (the LV's voxels against the atria), the apex at x = 42: nothing more than
  // 10 mm above it (x < 12) is wall.
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
      for (int i = 0; i < 12; ++i)
        ASSERT_NE(labels[g.Index(i, j, k)], P::Myocardium) << i << " " << j << " " << k;
  // Without a base (no atria or aorta against the LV) fat next to a pool stays fat.
  std::vector<std::uint8_t> again = labels;
  for (auto& l : again)
    if (l == P::Myocardium || l == amTorso::Atria)
      l = l == amTorso::Atria ? P::SoftTissue : P::Fat;
  amTorso::WallParameters q;
  q.Base = amTorso::FindValvePlane(g, again, P::LeftVentricleBlood);
  EXPECT_FALSE(q.Base.Found);
  amTorso::MyocardiumWall(g, hu.data(), classes, q, again);
  EXPECT_EQ(again[g.Index(34, 53, 32)], P::Fat);
}
