// The surface -> TetGen chain on synthetic many-label maps nobody tuned for (amSyntheticAtlasSource):
// every label a region, TetGen accepting the remeshed surface, the Hausdorff bound met on clean and
// noisy maps and reported (finite) where thin sheets or thick slices keep it from being met.
#include "amCurvatureMetric.h"
#include "amLabelSurface.h"
#include "amMetricRemeshing.h"
#include "amSurfaceSmoothing.h"
#include "amSyntheticAtlasSource.h"
#include "amTestUtilities.h"
#include "amTetrahedralize.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <set>
#include <tuple>

namespace
{
enum Variant
{
  Clean,
  Noise,
  Sheets,
  Slices
};

std::set<int> Values(vtkDataArray* a)
{
  std::set<int> s;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    s.insert(static_cast<int>(a->GetTuple1(i)));
  return s;
}

class AtlasChain : public ::testing::TestWithParam<std::tuple<int, int>>
{
};
}

TEST_P(AtlasChain, EveryLabelARegionAndTheBound)
{
  const int seed = std::get<0>(GetParam()), variant = std::get<1>(GetParam());
  const double eps = 0.5;
  vtkNew<amSyntheticAtlasSource> src;
  src->SetNumberOfLabels(20);
  src->SetSeed(seed);
  src->SetDimensions(48, 48, variant == Slices ? 20 : 48);
  if (variant == Slices)
    src->SetSpacing(1, 1, 2.5);
  if (variant == Noise)
    src->SetNoiseFraction(0.05);
  if (variant == Sheets)
    src->SetSheetWidth(1.0);
  vtkNew<amLabelSurface> surface;
  surface->SetInputConnection(src->GetOutputPort());
  surface->SetComputeTopology(false);
  vtkNew<amSurfaceSmoothing> smooth;
  smooth->SetInputConnection(surface->GetOutputPort());
  vtkNew<amCurvatureMetric> metric;
  metric->SetInputConnection(smooth->GetOutputPort());
  metric->SetTolerance(eps);
  metric->SetMinimumSize(1.0);
  metric->SetAnisotropic(false);
  vtkNew<amMetricRemeshing> remesh;
  remesh->SetInputConnection(metric->GetOutputPort());
  remesh->SetTolerance(eps);
  vtkNew<amTetrahedralize> tetra;
  tetra->SetInputConnection(remesh->GetOutputPort());
  vtkNew<amTest::ErrorCatcher> errors;
  for (vtkAlgorithm* a : { static_cast<vtkAlgorithm*>(surface), static_cast<vtkAlgorithm*>(smooth),
         static_cast<vtkAlgorithm*>(metric), static_cast<vtkAlgorithm*>(remesh), static_cast<vtkAlgorithm*>(tetra) })
  {
    errors->Watch(a);
    errors->Watch(a->GetExecutive());
  }
  tetra->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors(); // TetGen accepts what the remesher made
  std::set<int> labels = Values(src->GetOutput()->GetPointData()->GetScalars());
  labels.erase(0);
  const std::set<int> regions = Values(tetra->GetOutput()->GetCellData()->GetArray("Region"));
  EXPECT_EQ(regions, labels);
  const double h = remesh->GetHausdorff();
  std::printf("seed %d variant %d: %zu labels, %lld tetrahedra, Hausdorff %.3f mm\n", seed, variant, labels.size(),
    static_cast<long long>(tetra->GetOutput()->GetNumberOfCells()), h);
  ASSERT_TRUE(std::isfinite(h));
  if (variant == Clean || variant == Noise)
    EXPECT_LE(h, eps + 1e-9);
  else
    EXPECT_LT(h, 2 * eps); // thin sheets and 2.5 mm slices: reported, not yet met (see docs/limits.md)
}

INSTANTIATE_TEST_SUITE_P(SyntheticAtlases, AtlasChain,
  ::testing::Combine(::testing::Values(1, 2), ::testing::Values(Clean, Noise, Sheets, Slices)));
