// Organs whose regions overlap share their voxels by the nearest seeds: two chambers of one
// contrast joined by an opening (a ventricle and its atrium), each clicked.
#include "amSeedCompetition.h"
#include "amSnakeSegmentation.h"
#include "amTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace
{
// Two balls of contrast (300 HU, radius 12 mm, centres at x = -14 and +14 mm) joined by an
// opening 12 mm across, in soft tissue (40 HU), with 10 HU of noise; 1 mm voxels.
constexpr double Radius = 12.0, Centre = 14.0, Opening = 6.0;

bool InBall(double x, double y, double z, double cx)
{
  return (x - cx) * (x - cx) + y * y + z * z <= Radius * Radius;
}

// A scan of 71 x 41 x 41 voxels of 1 mm centred on the origin: value(p) HU at each voxel's
// position, with 10 HU of noise.
vtkSmartPointer<vtkImageData> Scan(const std::function<float(const double p[3])>& value, unsigned seed)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(71, 41, 41);
  image->SetOrigin(-35, -20, -20);
  image->SetSpacing(1, 1, 1);
  vtkNew<vtkFloatArray> hu;
  hu->SetName("CT");
  hu->SetNumberOfTuples(image->GetNumberOfPoints());
  std::mt19937 random(seed);
  std::normal_distribution<float> noise(0.0f, 10.0f);
  for (vtkIdType id = 0; id < image->GetNumberOfPoints(); ++id)
  {
    double p[3];
    image->GetPoint(id, p);
    hu->SetValue(id, value(p) + noise(random));
  }
  image->GetPointData()->SetScalars(hu);
  return image;
}

vtkSmartPointer<vtkImageData> TwoChambers()
{
  return Scan(
    [](const double p[3]) {
      const bool opening = std::abs(p[0]) < Centre && p[1] * p[1] + p[2] * p[2] <= Opening * Opening;
      const bool blood = InBall(p[0], p[1], p[2], -Centre) || InBall(p[0], p[1], p[2], Centre) || opening;
      return blood ? 300.0f : 40.0f;
    },
    7);
}

// Dice of a label against one ball.
double BallDice(vtkImageData* labels, int label, double cx)
{
  long both = 0, seg = 0, ball = 0;
  for (vtkIdType id = 0; id < labels->GetNumberOfPoints(); ++id)
  {
    double p[3];
    labels->GetPoint(id, p);
    const bool a = labels->GetPointData()->GetScalars()->GetComponent(id, 0) == label;
    const bool b = InBall(p[0], p[1], p[2], cx);
    both += a && b;
    seg += a;
    ball += b;
  }
  return 2.0 * both / static_cast<double>(seg + ball);
}
}

TEST(SeedCompetition, EachClickedChamberKeepsItsCavity)
{
  const auto image = TwoChambers();
  for (const bool compete : { true, false })
  {
    vtkNew<amSnakeSegmentation> snake;
    snake->SetInputData(image);
    snake->AddSeed(-Centre, 0, 0, 6); // the ventricle
    snake->AddSeed(Centre, 0, 0, 11); // the atrium
    snake->SetSeedsCompete(compete);
    vtkNew<amTest::ErrorCatcher> errors;
    errors->Watch(snake);
    snake->Update();
    ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
    vtkImageData* labels = snake->GetOutput();
    if (compete)
    {
      // Each snake alone fills both chambers; competing, each keeps its own, parted in the opening.
      EXPECT_GE(BallDice(labels, 6, -Centre), 0.95);
      EXPECT_GE(BallDice(labels, 11, Centre), 0.95);
      double lo[2] = { 1e9, 1e9 }, hi[2] = { -1e9, -1e9 };
      for (vtkIdType id = 0; id < labels->GetNumberOfPoints(); ++id)
      {
        const int l = static_cast<int>(labels->GetPointData()->GetScalars()->GetComponent(id, 0));
        if (l == 6 || l == 11)
        {
          const double x = labels->GetPoint(id)[0];
          lo[l == 11] = std::min(lo[l == 11], x);
          hi[l == 11] = std::max(hi[l == 11], x);
        }
      }
      EXPECT_LE(hi[0], 2.0); // the ventricle ends in the opening's middle
      EXPECT_GE(lo[1], -2.0);
      EXPECT_TRUE(errors->Warnings.empty());
    }
    else
    {
      // By precedence the first label takes both chambers, the atrium's click included: the
      // atrium keeps a few voxels of its rim.
      EXPECT_LT(BallDice(labels, 6, -Centre), 0.7);
      EXPECT_LT(BallDice(labels, 11, Centre), 0.01);
    }
  }
}

TEST(SeedCompetition, SharedVoxelsGoToTheNearestSeedAndTiesToTheEarlierOrgan)
{
  // A row of 9 voxels that both organs claim whole, seeds at either end (spacing 2 mm along x):
  // the first four are the first organ's, the last four the second's, the middle one (equally
  // far) the earlier organ's; a voxel only one organ claims is that organ's.
  const int dims[3] = { 10, 1, 1 };
  const double spacing[3] = { 2, 1, 1 };
  std::vector<unsigned char> all(9, 1), wider(10, 1);
  std::vector<amSeedCompetition::Organ> organs(2);
  organs[0].Label = 3;
  organs[0].Size[0] = 9;
  organs[0].Size[1] = organs[0].Size[2] = 1;
  organs[0].Inside = &all;
  organs[0].Seeds = { { 0, 0, 0 } };
  organs[1].Label = 5;
  organs[1].Size[0] = 10;
  organs[1].Size[1] = organs[1].Size[2] = 1;
  organs[1].Inside = &wider;
  organs[1].Seeds = { { 8, 0, 0 } };
  std::vector<unsigned char> out(10, 0);
  const auto voxels = amSeedCompetition::Paste(organs, dims, spacing, true, out.data());
  EXPECT_EQ(std::vector<unsigned char>(out), (std::vector<unsigned char>{ 3, 3, 3, 3, 3, 5, 5, 5, 5, 5 }));
  EXPECT_EQ(voxels[0], 5u);
  EXPECT_EQ(voxels[1], 5u);
  std::fill(out.begin(), out.end(), 0);
  amSeedCompetition::Paste(organs, dims, spacing, false, out.data());
  EXPECT_EQ(std::vector<unsigned char>(out), (std::vector<unsigned char>{ 3, 3, 3, 3, 3, 3, 3, 3, 3, 5 }));
}

TEST(SeedCompetition, TheSameLabelsWhateverTheThreadCount)
{
  // The organs' snakes run at once, one per thread; the shared voxels are dealt after, in one
  // order: one thread or two give the same bytes.
  const auto image = TwoChambers();
  std::vector<std::vector<unsigned char>> runs;
  for (const int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    vtkNew<amSnakeSegmentation> snake;
    snake->SetInputData(image);
    snake->AddSeed(-Centre, 0, 0, 6);
    snake->AddSeed(Centre, 0, 0, 11);
    snake->AddSeed(Centre + 3, 2, 0, 7); // a third organ sharing the atrium's contrast
    snake->Update();
    auto* labels = vtkUnsignedCharArray::SafeDownCast(snake->GetOutput()->GetPointData()->GetScalars());
    ASSERT_NE(labels, nullptr);
    runs.emplace_back(labels->GetPointer(0), labels->GetPointer(0) + labels->GetNumberOfValues());
  }
  vtkSMPTools::Initialize(2);
  EXPECT_TRUE(runs[0] == runs[1]);
}

TEST(SeedCompetition, AWallBetweenThePoolsSlowsTheFrontsThatCrossIt)
{
  // A row of 12 voxels (1 mm): the first organ claims all, the second the first 11; seeds at 0 and
  // 10; voxel 7 is a wall both intervals take at their edge. By path length alone the first organ
  // would reach 0-5; the wall costs each front 50 mm more, so the first keeps 0-6 and the wall
  // goes to the second, which reaches it sooner. Voxel 11, behind the second organ's seed, is the
  // first organ's alone but its front cannot reach it: nobody's.
  const int dims[3] = { 12, 1, 1 };
  const double spacing[3] = { 1, 1, 1 };
  std::vector<unsigned char> all(12, 1), shorter(11, 1);
  std::vector<float> intensity(12, 100.0f);
  intensity[7] = 40.0f;
  std::vector<amSeedCompetition::Organ> organs(2);
  for (auto& o : organs)
  {
    o.Size[1] = o.Size[2] = 1;
    o.Lower = 40.0;
    o.Upper = 160.0;
  }
  organs[0].Label = 3;
  organs[0].Size[0] = 12;
  organs[0].Inside = &all;
  organs[0].Seeds = { { 0, 0, 0 } };
  organs[1].Label = 5;
  organs[1].Size[0] = 11;
  organs[1].Inside = &shorter;
  organs[1].Seeds = { { 10, 0, 0 } };
  std::vector<unsigned char> out(12, 0);
  amSeedCompetition::Paste(organs, dims, spacing, true, out.data(), intensity.data());
  EXPECT_EQ(out, (std::vector<unsigned char>{ 3, 3, 3, 3, 3, 3, 3, 5, 5, 5, 5, 0 }));
  std::fill(out.begin(), out.end(), 0);
  amSeedCompetition::Paste(organs, dims, spacing, true, out.data());
  EXPECT_EQ(out, (std::vector<unsigned char>{ 3, 3, 3, 3, 3, 3, 5, 5, 5, 5, 5, 0 }));
  // Intervals that do not reach the wall's intensity leave it at the pace of path length.
  for (auto& o : organs)
    o.Upper = o.Lower = 0.0;
  std::fill(out.begin(), out.end(), 0);
  amSeedCompetition::Paste(organs, dims, spacing, true, out.data(), intensity.data());
  EXPECT_EQ(out, (std::vector<unsigned char>{ 3, 3, 3, 3, 3, 3, 5, 5, 5, 5, 5, 0 }));
}

TEST(SeedCompetition, TwoVentriclesPartAtTheSeptumNotBetweenTheirClicks)
{
  // Two cavities of contrast (300 HU) side by side, parted at x = 0 by a septum 3 mm thick whose
  // partial volume reads 180 HU, inside both snakes' intervals (about 170-400 HU), so each snake
  // runs into the other cavity. The RV's click lies 5 mm from the septum, the LV's 14 mm: half-way
  // between them the RV would take 4 mm of the LV's cavity. The fronts cross the septum slowly:
  // each cavity keeps its side.
  const auto image = Scan(
    [](const double p[3]) {
      const bool cavity = std::abs(p[0]) <= 25.0 && p[1] * p[1] + p[2] * p[2] <= 12.0 * 12.0;
      return !cavity ? 40.0f : std::abs(p[0]) <= 1.0 ? 180.0f : 300.0f;
    },
    11);
  vtkNew<amSnakeSegmentation> snake;
  snake->SetInputData(image);
  snake->AddSeed(-14, 0, 0, 6);
  snake->AddSeed(5, 0, 0, 7);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(snake);
  snake->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  vtkImageData* labels = snake->GetOutput();
  long lvBeyond = 0, rvBeyond = 0, lv = 0, rv = 0;
  for (vtkIdType id = 0; id < labels->GetNumberOfPoints(); ++id)
  {
    const int l = static_cast<int>(labels->GetPointData()->GetScalars()->GetComponent(id, 0));
    const double x = labels->GetPoint(id)[0];
    lv += l == 6;
    rv += l == 7;
    lvBeyond += l == 6 && x > 1.0;
    rvBeyond += l == 7 && x < -1.0;
  }
  EXPECT_GT(lv, 8000); // each cavity about 11,000 voxels, 23 mm long
  EXPECT_GT(rv, 8000);
  EXPECT_EQ(lvBeyond, 0);
  EXPECT_EQ(rvBeyond, 0);
}
