// Seed points: the positions and labels given come out as labelled vertices; a seed without a
// label gets its index + 1; bad labels and positions are errors, extra labels a warning.
#include "amSeedPointsSource.h"
#include "amTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <limits>

TEST(SeedPointsSource, DefaultsAreTheMainJobsSeeds)
{
  vtkNew<amSeedPointsSource> src;
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 4);
  EXPECT_EQ(out->GetNumberOfVerts(), 4);
  vtkDataArray* labels = out->GetPointData()->GetArray("Label");
  ASSERT_NE(labels, nullptr);
  const int expected[4] = { 6, 7, 8, 8 };
  const double first[3] = { 29.4, -24.1, -28.0 }, last[3] = { 5.0, -20.0, 30.0 };
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(labels->GetTuple1(i), expected[i]) << i;
  double p[3];
  out->GetPoint(0, p);
  for (int c = 0; c < 3; ++c)
    EXPECT_DOUBLE_EQ(p[c], first[c]);
  out->GetPoint(3, p);
  for (int c = 0; c < 3; ++c)
    EXPECT_DOUBLE_EQ(p[c], last[c]);
}

TEST(SeedPointsSource, IndexedSettersAsParaViewCallsThem)
{
  vtkNew<amSeedPointsSource> src;
  // ParaView: the number first, then each seed by index; the labels likewise.
  src->SetNumberOfSeeds(3);
  src->SetSeedPosition(0, 1, 2, 3);
  src->SetSeedPosition(1, 4, 5, 6);
  src->SetSeedPosition(2, 7, 8, 9);
  src->SetNumberOfSeedLabels(2);
  src->SetSeedLabel(0, 12);
  src->SetSeedLabel(1, 200);
  src->SetLabelArrayName("Organ");
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 3);
  vtkDataArray* labels = out->GetPointData()->GetArray("Organ");
  ASSERT_NE(labels, nullptr);
  EXPECT_EQ(labels->GetTuple1(0), 12);
  EXPECT_EQ(labels->GetTuple1(1), 200);
  EXPECT_EQ(labels->GetTuple1(2), 3); // no label of its own: index + 1
  double p[3];
  out->GetPoint(1, p);
  EXPECT_EQ(p[0], 4);
  EXPECT_EQ(p[2], 6);
  EXPECT_EQ(src->GetSeedPosition(2)[1], 8);
  EXPECT_EQ(src->GetSeedLabel(1), 200);
  // Fewer seeds: the last ones go; none: an empty point set, not an error.
  src->SetNumberOfSeeds(0);
  src->SetNumberOfSeedLabels(0);
  src->Update();
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SeedPointsSource, BadInput)
{
  vtkNew<amTest::ErrorCatcher> errors;
  {
    vtkNew<amSeedPointsSource> src;
    errors->Watch(src);
    errors->Watch(src->GetExecutive());
    src->SetSeedLabel(1, 0);
    src->Update();
    EXPECT_TRUE(errors->ErrorContains("Seed 1 has label 0")) << errors->AllErrors();
    errors->Errors.clear();
    src->SetSeedLabel(1, 256);
    src->Update();
    EXPECT_TRUE(errors->ErrorContains("Seed 1 has label 256")) << errors->AllErrors();
    errors->Errors.clear();
    src->SetSeedLabel(1, 7);
    src->SetSeedPosition(2, 0, std::numeric_limits<double>::quiet_NaN(), 0);
    src->Update();
    EXPECT_TRUE(errors->ErrorContains("Seed 2 is at")) << errors->AllErrors();
  }
  {
    vtkNew<amSeedPointsSource> src;
    errors->Errors.clear();
    errors->Warnings.clear();
    errors->Watch(src);
    src->SetNumberOfSeeds(2); // a seed removed in the GUI: four labels for two seeds
    src->Update();
    EXPECT_FALSE(errors->HasError()) << errors->AllErrors();
    ASSERT_EQ(errors->Warnings.size(), 1u);
    EXPECT_NE(errors->Warnings[0].find("4 seed labels for 2 seeds"), std::string::npos) << errors->Warnings[0];
    EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 2);
  }
}
