// The synthetic atlas: every cell present as a label, of the type asked, the same bytes for the same
// seed whatever the threads, sheets thin, noise at the fraction asked, anisotropic voxels honoured.
#include "amSyntheticAtlasSource.h"
#include "amTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace
{
std::vector<int> Values(amSyntheticAtlasSource* src)
{
  src->Update();
  vtkDataArray* a = src->GetOutput()->GetPointData()->GetScalars();
  std::vector<int> v(static_cast<size_t>(a->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    v[i] = static_cast<int>(a->GetTuple1(i));
  return v;
}
}

TEST(SyntheticAtlasSource, EveryCellALabelOfTheTypeAsked)
{
  for (int n : { 10, 300 })
  {
    vtkNew<amSyntheticAtlasSource> src;
    src->SetNumberOfLabels(n);
    src->SetDimensions(64, 56, 48);
    const std::vector<int> v = Values(src);
    EXPECT_EQ(src->GetOutput()->GetScalarType(), VTK_SHORT);
    std::set<int> labels(v.begin(), v.end());
    EXPECT_EQ(static_cast<int>(labels.size()), n + 1) << n; // every cell, and the outside
    EXPECT_EQ(*labels.begin(), 0);
    EXPECT_EQ(*labels.rbegin(), n);
    // The ellipsoid (semi-axes 45 % of the extent) holds about pi/6 * 0.9^3 of the box.
    const double inside = static_cast<double>(v.size() - std::count(v.begin(), v.end(), 0)) / v.size();
    EXPECT_NEAR(inside, M_PI / 6 * 0.729, 0.02);
  }
}

TEST(SyntheticAtlasSource, SameBytesWhateverTheThreads)
{
  std::vector<int> first;
  for (const char* backend : { "STDThread", "Sequential" })
  {
    vtkSMPTools::SetBackend(backend);
    vtkNew<amSyntheticAtlasSource> src;
    src->SetNumberOfLabels(100);
    src->SetDimensions(40, 40, 40);
    src->SetSheetWidth(1.0);
    src->SetNoiseFraction(0.05);
    const std::vector<int> v = Values(src);
    if (first.empty())
      first = v;
    else
      EXPECT_EQ(v, first);
  }
  vtkSMPTools::SetBackend("STDThread");
  vtkNew<amSyntheticAtlasSource> other;
  other->SetNumberOfLabels(100);
  other->SetDimensions(40, 40, 40);
  other->SetSheetWidth(1.0);
  other->SetNoiseFraction(0.05);
  other->SetSeed(2);
  EXPECT_NE(Values(other), first);
}

TEST(SyntheticAtlasSource, SheetsNoiseAndAnisotropy)
{
  vtkNew<amSyntheticAtlasSource> clean;
  clean->SetNumberOfLabels(20);
  clean->SetDimensions(48, 48, 48);
  const std::vector<int> c = Values(clean);
  // Sheets: the membrane label N + 1 takes a thin layer between the cells.
  vtkNew<amSyntheticAtlasSource> sheets;
  sheets->SetNumberOfLabels(20);
  sheets->SetDimensions(48, 48, 48);
  sheets->SetSheetWidth(1.0);
  const std::vector<int> s = Values(sheets);
  const double membrane = static_cast<double>(std::count(s.begin(), s.end(), 21)) / s.size();
  EXPECT_GT(membrane, 0.02);
  EXPECT_LT(membrane, 0.15);
  for (size_t i = 0; i < s.size(); ++i)
    ASSERT_TRUE(s[i] == c[i] || s[i] == 21) << i; // sheets only replace, the cells stay where they were
  // Noise: about the fraction asked changes (a voxel may take a neighbour of its own label).
  vtkNew<amSyntheticAtlasSource> noisy;
  noisy->SetNumberOfLabels(20);
  noisy->SetDimensions(48, 48, 48);
  noisy->SetNoiseFraction(0.1);
  const std::vector<int> z = Values(noisy);
  size_t changed = 0;
  for (size_t i = 0; i < z.size(); ++i)
    changed += z[i] != c[i];
  EXPECT_GT(changed, 0u);
  EXPECT_LT(static_cast<double>(changed) / z.size(), 0.1);
  // Anisotropic voxels: the same cells in mm, so a 2x coarser z sees the same seed points.
  vtkNew<amSyntheticAtlasSource> aniso;
  aniso->SetNumberOfLabels(20);
  aniso->SetDimensions(48, 48, 24);
  aniso->SetSpacing(1, 1, 2);
  aniso->Update();
  EXPECT_DOUBLE_EQ(aniso->GetOutput()->GetSpacing()[2], 2.0);
  const std::vector<int> a = Values(aniso);
  size_t agree = 0, inside = 0;
  for (int k = 0; k < 23; ++k) // voxel k of aniso is at z = 2k mm, voxel 2k of clean too (z extents 46 mm)
    for (int j = 0; j < 48; ++j)
      for (int i = 0; i < 48; ++i)
      {
        const int va = a[(static_cast<size_t>(k) * 48 + j) * 48 + i],
                  vc = c[(static_cast<size_t>(2 * k) * 48 + j) * 48 + i];
        inside += va != 0;
        agree += va != 0 && va == vc;
      }
  EXPECT_GT(static_cast<double>(agree) / inside, 0.9);
}

TEST(SyntheticAtlasSource, LabelsThatDoNotFitAreAnError)
{
  vtkNew<amSyntheticAtlasSource> src;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(src);
  errors->Watch(src->GetExecutive());
  src->SetNumberOfLabels(300);
  src->SetOutputScalarType(VTK_UNSIGNED_CHAR);
  src->SetDimensions(16, 16, 16);
  src->Update();
  EXPECT_TRUE(errors->ErrorContains("300 labels do not fit")) << errors->AllErrors();
}
