// The thorax phantom source: geometry, exact label volumes, HU statistics, determinism, errors.
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"

#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkShortArray.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstring>
#include <vector>

namespace
{
std::vector<long> CountLabels(vtkImageData* labels)
{
  std::vector<long> counts(amThoraxPhantomSource::GetNumberOfLabels(), 0);
  auto* a = vtkUnsignedCharArray::SafeDownCast(labels->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    ++counts[a->GetValue(i)];
  return counts;
}

// Mean and standard deviation of the CT in a cube of half-width r voxels around a point.
void CubeStats(vtkImageData* ct, const double p[3], int r, double& mean, double& sd)
{
  int ijk[3];
  double pc[3];
  ct->ComputeStructuredCoordinates(p, ijk, pc);
  double s = 0, s2 = 0;
  int n = 0;
  for (int k = -r; k <= r; ++k)
    for (int j = -r; j <= r; ++j)
      for (int i = -r; i <= r; ++i)
      {
        const double v = ct->GetScalarComponentAsDouble(ijk[0] + i, ijk[1] + j, ijk[2] + k, 0);
        s += v;
        s2 += v * v;
        ++n;
      }
  mean = s / n;
  sd = std::sqrt(std::max(0.0, s2 / n - mean * mean));
}
}

TEST(ThoraxPhantomSource, GeometryIsCentredAndShared)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(2, 2, 2);
  src->Update();
  vtkImageData* ct = vtkImageData::SafeDownCast(src->GetOutputDataObject(0));
  vtkImageData* labels = vtkImageData::SafeDownCast(src->GetOutputDataObject(1));
  int dims[3];
  ct->GetDimensions(dims);
  EXPECT_EQ(dims[0], 160);
  EXPECT_EQ(dims[1], 120);
  EXPECT_EQ(dims[2], 105);
  double b[6];
  ct->GetBounds(b);
  EXPECT_NEAR(b[0], -b[1], 1e-9);
  EXPECT_NEAR(b[4], -b[5], 1e-9);
  EXPECT_EQ(ct->GetScalarType(), VTK_SHORT);
  EXPECT_EQ(labels->GetScalarType(), VTK_UNSIGNED_CHAR);
  EXPECT_STREQ(labels->GetPointData()->GetScalars()->GetName(), "Labels");
  EXPECT_STREQ(ct->GetPointData()->GetScalars()->GetName(), "CT");
  EXPECT_EQ(labels->GetNumberOfPoints(), ct->GetNumberOfPoints());
  auto* names = vtkStringArray::SafeDownCast(labels->GetFieldData()->GetAbstractArray("LabelNames"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(5), "Myocardium");
  ASSERT_NE(labels->GetFieldData()->GetAbstractArray("Provenance"), nullptr);
  const auto counts = CountLabels(labels);
  for (int l = 0; l < amThoraxPhantomSource::GetNumberOfLabels(); ++l)
    EXPECT_GT(counts[l], 0) << "label " << l << " missing at 2 mm";
}

TEST(ThoraxPhantomSource, LabelVolumesMatchAnalyticVolumesAt1mm)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetNoiseStandardDeviation(0); // labels do not depend on noise; skip the work
  src->SetPartialVolumeSamples(1);
  src->SetBlurSigma(0);
  src->Update();
  vtkImageData* labels = vtkImageData::SafeDownCast(src->GetOutputDataObject(1));
  const auto counts = CountLabels(labels);
  long body = 0;
  for (int l = 1; l < amThoraxPhantomSource::GetNumberOfLabels(); ++l)
  {
    body += counts[l];
    const double exact = src->GetExactVolume(l);
    if (exact > 0)
      EXPECT_NEAR(counts[l] / exact, 1.0, 0.01) << src->GetLabelName(l) << ": " << counts[l] << " mm3 vs " << exact;
  }
  EXPECT_NEAR(body / src->GetBodyVolume(), 1.0, 0.001);
}

TEST(ThoraxPhantomSource, HounsfieldUnitsAndNoise)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(1.5, 1.5, 1.5);
  src->Update();
  vtkImageData* ct = vtkImageData::SafeDownCast(src->GetOutputDataObject(0));
  struct Probe
  {
    int Label;
    double HU;
  };
  for (const Probe& p : { Probe{ 3, -850 }, Probe{ 6, 300 }, Probe{ 9, 700 } })
  {
    double c[3], mean, sd;
    src->GetOrganCenter(p.Label, c);
    CubeStats(ct, c, 3, mean, sd);
    EXPECT_NEAR(mean, p.HU, 8.0) << src->GetLabelName(p.Label);
    EXPECT_NEAR(sd, 20.0, 4.0) << src->GetLabelName(p.Label);
  }
  // Partial volume + blur: the CT changes smoothly across the LV blood/myocardium boundary.
  double lv[3];
  src->GetOrganCenter(6, lv);
  src->SetNoiseStandardDeviation(0);
  src->Update();
  ct = vtkImageData::SafeDownCast(src->GetOutputDataObject(0));
  double mean, sd;
  CubeStats(ct, lv, 2, mean, sd);
  EXPECT_NEAR(mean, 300.0, 0.5);
  EXPECT_LT(sd, 0.5);
}

TEST(ThoraxPhantomSource, SameSeedSameBytesWhateverTheThreads)
{
  auto run = [](int seed) {
    vtkNew<amThoraxPhantomSource> src;
    src->SetSpacing(3, 3, 3);
    src->SetSeed(seed);
    src->Update();
    auto* a = vtkShortArray::SafeDownCast(
      vtkImageData::SafeDownCast(src->GetOutputDataObject(0))->GetPointData()->GetScalars());
    return std::vector<short>(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfTuples());
  };
  const auto a = run(7);
  vtkSMPTools::Initialize(1);
  const auto b = run(7);
  vtkSMPTools::Initialize(2);
  const auto c = run(8);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(a == b) << "same seed must give the same bytes with 1 or 2 threads";
  EXPECT_FALSE(a == c) << "another seed must give other noise";
}

TEST(ThoraxPhantomSource, HalfMillimetreWorks)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(0.5, 0.5, 0.5);
  src->SetFieldOfView(60, 60, 40); // the heart region only, to keep the test short
  src->Update();
  vtkImageData* labels = vtkImageData::SafeDownCast(src->GetOutputDataObject(1));
  int dims[3];
  labels->GetDimensions(dims);
  EXPECT_EQ(dims[0], 120);
  EXPECT_EQ(dims[2], 80);
  const auto counts = CountLabels(labels);
  EXPECT_GT(counts[5], 0);
  EXPECT_GT(counts[6], 0);
}

TEST(ThoraxPhantomSource, BadParametersGiveAnErrorNotACrash)
{
  vtkNew<amThoraxPhantomSource> src;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(src);
  src->SetSpacing(0, 1, 1);
  src->Update();
  EXPECT_TRUE(errors->ErrorContains("Spacing must be positive")) << errors->AllErrors();
  errors->Errors.clear();
  src->SetSpacing(1, 1, 1);
  src->SetFieldOfView(-5, 100, 100);
  src->Update();
  EXPECT_TRUE(errors->ErrorContains("FieldOfView")) << errors->AllErrors();
  errors->Errors.clear();
  src->SetFieldOfView(1e9, 100, 100);
  src->Update();
  EXPECT_TRUE(errors->ErrorContains("at most 8192")) << errors->AllErrors();
}
