// The surface -> TetGen chain on synthetic many-label maps nobody tuned for (amSyntheticAtlasSource):
// every label a region, TetGen accepting the remeshed surface, no degenerate surface triangle, the
// Hausdorff bound met on clean and noisy maps and reported (finite) where thin sheets or thick slices
// keep it from being met.
#include "amAtlasChain.h"
#include "amFigures.h"
#include "amImageReader.h"
#include "amMeshQuality.h"
#include "amTestUtilities.h"
#include "amTetraMeshChecks.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <set>
#include <string>
#include <tuple>

namespace
{
/// The worst triangle of a surface by the paper's measure for triangles, (sqrt 3 / 6) h_max / rho
/// (1: equilateral). A tetrahedron on a triangle of quality q has Q >= q / sqrt 2.
double WorstTriangleQuality(vtkPolyData* surface)
{
  double worst = 0;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    surface->GetCellPoints(c, n, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      surface->GetPoint(ids[k], p[k]);
    double l[3], u[3], v[3];
    for (int k = 0; k < 3; ++k)
    {
      double d2 = 0;
      for (int d = 0; d < 3; ++d)
        d2 += (p[(k + 1) % 3][d] - p[k][d]) * (p[(k + 1) % 3][d] - p[k][d]);
      l[k] = std::sqrt(d2);
    }
    for (int d = 0; d < 3; ++d)
    {
      u[d] = p[1][d] - p[0][d];
      v[d] = p[2][d] - p[0][d];
    }
    const double cross[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    const double area = 0.5 * std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double rho = 2 * area / (l[0] + l[1] + l[2]);
    worst = std::max(worst, std::sqrt(3.0) / 6.0 * std::max({ l[0], l[1], l[2] }) / rho);
  }
  return worst;
}

/// The guarantee on the elements: worst Q <= 10 and every dihedral angle >= 10 degrees, the
/// surface moved by at most 'deviation' to get there, the interfaces the mesh's own faces.
void ExpectNoSliver(amTetrahedralize* tetra, double deviation)
{
  vtkNew<amMeshQuality> quality;
  quality->SetInputData(tetra->GetOutput());
  quality->Update();
  std::printf("  worst Q %.2f, smallest dihedral %.2f deg, %lld slivers, surface moved %.3f mm\n",
    quality->GetMaximumQuality(), quality->GetMinimumDihedralAngle(),
    static_cast<long long>(tetra->GetNumberOfSlivers()), tetra->GetSurfaceDeviation());
  EXPECT_EQ(
    amTest::InterfaceProblems(tetra->GetOutput(), vtkPolyData::SafeDownCast(tetra->GetOutputDataObject(1))), "");
  EXPECT_LE(tetra->GetSurfaceDeviation(), deviation);
  EXPECT_EQ(tetra->GetNumberOfSlivers(), 0);
  EXPECT_LE(quality->GetMaximumQuality(), 10.0);
  EXPECT_GE(quality->GetMinimumDihedralAngle(), 10.0);
  amTest::RecordFigure("tetgen.worst_q", quality->GetMaximumQuality(), "", 10.0);
  amTest::RecordFigure("tetgen.smallest_dihedral", quality->GetMinimumDihedralAngle(), "deg", 10.0);
  amTest::RecordFigure("tetgen.surface_moved", tetra->GetSurfaceDeviation(), "mm", deviation);
  amTest::RecordFigure("tetgen.volume_misses", static_cast<double>(tetra->GetNumberOfVolumeMisses()), "", 0);
}

/// The errors of a chain's remeshing and TetGen stages (and their executives), caught.
void WatchRemeshAndTetra(amTest::ErrorCatcher* errors, amTest::AtlasChain& chain)
{
  for (vtkAlgorithm* a : { static_cast<vtkAlgorithm*>(chain.Remesh), static_cast<vtkAlgorithm*>(chain.Tetra) })
  {
    errors->Watch(a);
    errors->Watch(a->GetExecutive());
  }
}

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
  tetra->SetMaximumSurfaceDeviation(0.5 * eps);
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
  const double worstTriangle = WorstTriangleQuality(remesh->GetOutput());
  std::printf("seed %d variant %d: %zu labels, %lld tetrahedra, Hausdorff %.3f mm, worst triangle %.1f\n", seed,
    variant, labels.size(), static_cast<long long>(tetra->GetOutput()->GetNumberOfCells()), h, worstTriangle);
  // No degenerate triangle: where an interface narrows to nothing between two junction curves
  // (Voronoi corners on the voxel grid), the strip is closed, not kept as caps of Q ~ 250-3000.
  EXPECT_LT(worstTriangle, 100);
  ASSERT_TRUE(std::isfinite(h));
  if (variant == Clean || variant == Noise)
    EXPECT_LE(h, eps + 1e-9);
  else
    EXPECT_LT(h, 2 * eps); // thin sheets and 2.5 mm slices: reported, not yet met (see docs/limits.md)
  std::printf("  %lld regions of at least 1 cm3 more than 2 %% off their voxels\n",
    static_cast<long long>(tetra->GetNumberOfVolumeMisses()));
  EXPECT_EQ(tetra->GetNumberOfVolumeMisses(), 0);
  ExpectNoSliver(tetra, 0.5 * eps);
}

// A hundred labels (96^3 voxels, clean and with 5 % label noise), the default surface deviation:
// every label a region, TetGen accepting the remeshed surface, each region of at least 1 cm3 within
// 2 % of its voxels, no sliver; the Hausdorff distance within the tolerance or, where an interface
// is thinner than it allows, every such interface named with its distance (InterfaceHausdorff).
TEST(AtlasChain, HundredLabels)
{
  const double eps = 0.5;
  const int dims[3] = { 96, 96, 96 };
  const double spacing[3] = { 1, 1, 1 };
  for (const double noise : { 0.0, 0.05 })
  {
    amTest::AtlasChain chain(100, 1, dims, spacing, 0.0, noise, eps);
    vtkNew<amTest::ErrorCatcher> errors;
    WatchRemeshAndTetra(errors, chain);
    chain.Tetra->Update();
    ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
    std::set<int> labels = amTest::DistinctValues(chain.Source->GetOutput()->GetPointData()->GetScalars());
    labels.erase(0);
    ASSERT_EQ(labels.size(), 100u);
    EXPECT_EQ(amTest::DistinctValues(chain.Tetra->GetOutput()->GetCellData()->GetArray("Region")), labels);
    const double h = chain.Remesh->GetHausdorff();
    ASSERT_TRUE(std::isfinite(h));
    vtkDataArray* interfaces = chain.Remesh->GetOutput()->GetFieldData()->GetArray("InterfaceHausdorff");
    ASSERT_NE(interfaces, nullptr);
    int above = 0;
    double largest = 0;
    for (vtkIdType r = 0; r < interfaces->GetNumberOfTuples(); ++r)
    {
      above += interfaces->GetComponent(r, 2) > eps;
      largest = std::max(largest, interfaces->GetComponent(r, 2));
    }
    std::printf("noise %.2f: %lld tetrahedra, Hausdorff %.4f mm, %d interface(s) above %.1f mm\n", noise,
      static_cast<long long>(chain.Tetra->GetOutput()->GetNumberOfCells()), h, above, eps);
    EXPECT_EQ(above, chain.Remesh->GetInterfacesAboveTolerance());
    EXPECT_DOUBLE_EQ(largest, h);
    EXPECT_LT(h, 1.1 * eps);
    EXPECT_EQ(chain.Tetra->GetNumberOfVolumeMisses(), 0);
    ExpectNoSliver(chain.Tetra, chain.Tetra->GetSurfaceDeviationUsed());
  }
}

TEST(AtlasChain, SliverFreeingIsDeterministic)
{
  const int dims[3] = { 48, 48, 48 };
  const double spacing[3] = { 1, 1, 1 };
  amTest::AtlasChain chain(20, 2, dims, spacing, 0.0, 0.05, 0.5);
  chain.Tetra->SetMaximumSurfaceDeviation(0.25);
  chain.Tetra->Update();
  vtkNew<vtkUnstructuredGrid> first;
  first->DeepCopy(chain.Tetra->GetOutput());
  ASSERT_GT(chain.Tetra->GetSurfaceDeviation(), 0.0); // the sliver phase acted
  chain.Tetra->Modified();
  chain.Tetra->Update();
  vtkUnstructuredGrid* second = chain.Tetra->GetOutput();
  ASSERT_EQ(first->GetNumberOfPoints(), second->GetNumberOfPoints());
  ASSERT_EQ(first->GetNumberOfCells(), second->GetNumberOfCells());
  for (vtkIdType v = 0; v < first->GetNumberOfPoints(); ++v)
  {
    double p[3], q[3];
    first->GetPoint(v, p);
    second->GetPoint(v, q);
    ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << v;
  }
  for (vtkIdType c = 0; c < first->GetNumberOfCells(); ++c)
  {
    vtkIdType n1, n2;
    const vtkIdType *a, *b;
    first->GetCellPoints(c, n1, a);
    second->GetCellPoints(c, n2, b);
    ASSERT_TRUE(std::equal(a, a + 4, b)) << "cell " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(SyntheticAtlases, AtlasChain,
  ::testing::Combine(::testing::Values(1, 2), ::testing::Values(Clean, Noise, Sheets, Slices)));

namespace
{
struct RealMap
{
  const char* Path;
  double Tolerance, MinimumSize; // mm
  long SliversLeft;              // 0: the no-sliver guarantee holds; else at most this many remain
  long VolumeMissesLeft;         // regions of at least 1 cm3 more than 2 % off their voxels
};
std::string RealMapName(const ::testing::TestParamInfo<RealMap>& info)
{
  static const char* const names[] = { "Frog", "Abdomen", "NiivueTorso" };
  return names[info.index];
}
void PrintTo(const RealMap& map, std::ostream* os)
{
  *os << map.Path << " at " << map.Tolerance << " mm";
}
class RealLabelMaps : public ::testing::TestWithParam<RealMap>
{
};
}

// The real label maps of ../shared/data through the TetGen path: every label a region, TetGen
// accepting the remeshed surface (the frog's used to fold at junction curves: "labels are
// inconsistent"), the Hausdorff distance reported finite.
TEST_P(RealLabelMaps, EveryLabelARegionThroughTetGen)
{
  const RealMap map = GetParam();
  AM_REQUIRE_SHARED(path, map.Path);
  vtkNew<amImageReader> reader;
  reader->SetFileName(path.c_str());
  const int dims[3] = { 8, 8, 8 };
  const double spacing[3] = { 1, 1, 1 };
  amTest::AtlasChain chain(2, 1, dims, spacing, 0.0, 0.0, map.Tolerance);
  chain.Surface->SetInputConnection(reader->GetOutputPort());
  chain.Metric->SetMinimumSize(map.MinimumSize);
  chain.Tetra->SetMaximumSurfaceDeviation(0.5 * map.Tolerance);
  vtkNew<amTest::ErrorCatcher> errors;
  WatchRemeshAndTetra(errors, chain);
  chain.Tetra->Update();
  ASSERT_FALSE(errors->HasError()) << errors->AllErrors();
  std::set<int> labels = amTest::DistinctValues(reader->GetOutput()->GetPointData()->GetScalars());
  labels.erase(0);
  EXPECT_EQ(amTest::DistinctValues(chain.Tetra->GetOutput()->GetCellData()->GetArray("Region")), labels);
  const double h = chain.Remesh->GetHausdorff();
  std::printf("%s: %zu labels, %lld tetrahedra, Hausdorff %.3f mm (tolerance %.1f)\n", map.Path, labels.size(),
    static_cast<long long>(chain.Tetra->GetOutput()->GetNumberOfCells()), h, map.Tolerance);
  EXPECT_TRUE(std::isfinite(h));
  // Each region of at least 1 cm3 within 2 % of its voxels' volume (the remesher gives back what
  // its chords take); the misses left are listed in the RegionVolumes field data.
  std::printf("  %lld regions of at least 1 cm3 more than 2 %% off their voxels\n",
    static_cast<long long>(chain.Tetra->GetNumberOfVolumeMisses()));
  EXPECT_LE(chain.Tetra->GetNumberOfVolumeMisses(), map.VolumeMissesLeft);
  if (map.SliversLeft == 0)
    ExpectNoSliver(chain.Tetra, 0.5 * map.Tolerance);
  else
  {
    // Reported, not met: see docs/limits.md.
    std::printf("  %lld slivers left, surface moved %.3f mm\n",
      static_cast<long long>(chain.Tetra->GetNumberOfSlivers()), chain.Tetra->GetSurfaceDeviation());
    EXPECT_LE(chain.Tetra->GetNumberOfSlivers(), map.SliversLeft);
  }
}

INSTANTIATE_TEST_SUITE_P(SharedData, RealLabelMaps,
  ::testing::Values(RealMap{ amTest::FrogLabels, 2.0, 2.0, 0, 0 },
    RealMap{ "totalseg_abdomen_ct_labels/example_seg.nii.gz", 1.0, 3.0, 0, 0 },
    RealMap{ "niivue_torso_labels/torsoLabel.nii.gz", 2.0, 1.56, 0, 0 }),
  RealMapName);
