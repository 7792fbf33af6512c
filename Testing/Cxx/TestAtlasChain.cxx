// The surface -> TetGen chain on synthetic many-label maps nobody tuned for (amSyntheticAtlasSource):
// every label a region, TetGen accepting the remeshed surface, the Hausdorff bound met on clean and
// noisy maps and reported (finite) where thin sheets or thick slices keep it from being met.
#include "amAtlasChain.h"
#include "amTestUtilities.h"

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

class AtlasChain : public ::testing::TestWithParam<std::tuple<int, int>>
{
};
}

TEST_P(AtlasChain, EveryLabelARegionAndTheBound)
{
  const int seed = std::get<0>(GetParam()), variant = std::get<1>(GetParam());
  const double eps = 0.5;
  const int dims[3] = { 48, 48, variant == Slices ? 20 : 48 };
  const double spacing[3] = { 1, 1, variant == Slices ? 2.5 : 1.0 };
  amTest::AtlasChain chain(20, seed, dims, spacing, variant == Sheets ? 1.0 : 0.0, variant == Noise ? 0.05 : 0.0, eps);
  amSyntheticAtlasSource* src = chain.Source;
  amMetricRemeshing* remesh = chain.Remesh;
  amTetrahedralize* tetra = chain.Tetra;
  vtkNew<amTest::ErrorCatcher> errors;
  for (vtkAlgorithm* a :
    { static_cast<vtkAlgorithm*>(chain.Surface), static_cast<vtkAlgorithm*>(chain.Smooth),
      static_cast<vtkAlgorithm*>(chain.Metric), static_cast<vtkAlgorithm*>(remesh), static_cast<vtkAlgorithm*>(tetra) })
  {
    errors->Watch(a);
    errors->Watch(a->GetExecutive());
  }
  tetra->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors(); // TetGen accepts what the remesher made
  std::set<int> labels = amTest::DistinctValues(src->GetOutput()->GetPointData()->GetScalars());
  labels.erase(0);
  const std::set<int> regions = amTest::DistinctValues(tetra->GetOutput()->GetCellData()->GetArray("Region"));
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
