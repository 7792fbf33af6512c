// The label surface extractor without a pipeline: voxels given as label ranks, the surface
// counted, oriented and closed by hand-checkable numbers.
#include "amLabelSurfaceExtractor.h"

#include <gtest/gtest.h>

#include <array>
#include <map>

namespace
{
/// An n x n x n grid of 1 mm voxels at the origin, labels 0 (background) and up, given as ranks.
amLabelSurfaceExtractor Grid(int n, const std::map<std::array<int, 3>, int>& voxels, int labels)
{
  amLabelSurfaceExtractor x;
  amLabelGrid& g = x.Grid;
  for (int d = 0; d < 3; ++d)
  {
    g.N[d] = n;
    g.Extent[2 * d] = 0;
    g.Extent[2 * d + 1] = n - 1;
    g.Origin[d] = 0;
    g.Spacing[d] = 1;
  }
  for (int k = 0; k < 9; ++k)
    g.Direction[k] = k % 4 == 0 ? 1 : 0;
  g.Labels.assign(static_cast<size_t>(n) * n * n, 0);
  for (const auto& [ijk, label] : voxels)
    g.Labels[(static_cast<size_t>(ijk[2]) * n + ijk[1]) * n + ijk[0]] = static_cast<std::uint16_t>(label);
  for (int l = 0; l < labels; ++l)
    g.Values.push_back(10 * l); // label values 0, 10, 20, ...
  g.Background = 0;
  return x;
}

/// The volume enclosed by the triangles whose front label is 'label' (divergence theorem),
/// counting those with 'label' on the back negatively.
double Volume(const amLabelSurfaceExtractor& x, int label)
{
  double v = 0;
  for (size_t t = 0; t < x.Labels.size() / 2; ++t)
  {
    const float* p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = &x.Points[3 * x.Triangles[3 * t + k]];
    const double det = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
      p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    if (x.Labels[2 * t] == label)
      v += det / 6.0;
    else if (x.Labels[2 * t + 1] == label)
      v -= det / 6.0;
  }
  return v;
}

/// Every directed edge of the triangles of one label's surface is run once and its reverse once.
void ExpectClosed(const amLabelSurfaceExtractor& x, int label)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  for (size_t t = 0; t < x.Labels.size() / 2; ++t)
  {
    const int sign = x.Labels[2 * t] == label ? 1 : (x.Labels[2 * t + 1] == label ? -1 : 0);
    if (!sign)
      continue;
    for (int k = 0; k < 3; ++k)
    {
      vtkIdType a = x.Triangles[3 * t + k], b = x.Triangles[3 * t + (k + 1) % 3];
      if (sign < 0)
        std::swap(a, b);
      ++directed[{ a, b }];
    }
  }
  for (const auto& [e, count] : directed)
  {
    EXPECT_EQ(count, 1) << "label " << label << " edge " << e.first << "-" << e.second;
    EXPECT_EQ(directed.count({ e.second, e.first }), 1u) << "label " << label << " open edge";
  }
}
}

TEST(LabelSurfaceExtractor, OneVoxelIsACubeFacingOut)
{
  amLabelSurfaceExtractor x = Grid(3, { { { 1, 1, 1 }, 1 } }, 2);
  x.Extract(nullptr);
  EXPECT_EQ(x.Points.size(), 8u * 3);
  EXPECT_EQ(x.Triangles.size(), 12u * 3);
  for (size_t t = 0; t < x.Labels.size() / 2; ++t)
  {
    EXPECT_EQ(x.Labels[2 * t], 10); // the label in front, the background behind
    EXPECT_EQ(x.Labels[2 * t + 1], 0);
  }
  EXPECT_NEAR(Volume(x, 10), 1.0, 1e-6);
  ExpectClosed(x, 10);
  EXPECT_EQ(x.SplitCorners, 0);
  EXPECT_EQ(x.ResolvedEdges, 0);
}

TEST(LabelSurfaceExtractor, TwoLabelsShareOneConformingInterface)
{
  amLabelSurfaceExtractor x = Grid(4, { { { 1, 1, 1 }, 1 }, { { 2, 1, 1 }, 2 } }, 3);
  x.Extract(nullptr);
  // 2 x 1 x 1 box: 10 outer faces, 1 shared face, 12 corners.
  EXPECT_EQ(x.Triangles.size(), 22u * 3);
  EXPECT_EQ(x.Points.size(), 12u * 3);
  EXPECT_NEAR(Volume(x, 10), 1.0, 1e-6);
  EXPECT_NEAR(Volume(x, 20), 1.0, 1e-6);
  ExpectClosed(x, 10);
  ExpectClosed(x, 20);
}

TEST(LabelSurfaceExtractor, CornerContactSplitsTheVertex)
{
  // Two voxels of one label touching at a corner only: two copies of that corner's vertex.
  amLabelSurfaceExtractor x = Grid(4, { { { 1, 1, 1 }, 1 }, { { 2, 2, 2 }, 1 } }, 2);
  x.Extract(nullptr);
  EXPECT_EQ(x.SplitCorners, 1);
  EXPECT_EQ(x.Points.size(), (8u + 8u) * 3); // 15 corners, one of them twice
  // Each copy moves 0.3 of the way into its own voxel's corner region: 0.1 mm^3 less per voxel.
  EXPECT_NEAR(Volume(x, 10), 1.8, 1e-5);
  ExpectClosed(x, 10);
}

TEST(LabelSurfaceExtractor, EdgeContactIsResolved)
{
  // Two voxels of one label across the diagonal of an edge: the edge is resolved (fans around
  // the faces on it), the surface stays closed and the volume two voxels.
  amLabelSurfaceExtractor x = Grid(4, { { { 1, 1, 1 }, 1 }, { { 2, 2, 1 }, 1 } }, 2);
  x.Extract(nullptr);
  EXPECT_EQ(x.ResolvedEdges, 1);
  // The resolved edge's midpoints bend a quarter of the way into the voxels the faces wrap: a
  // thin bridge of 1/15 mm^3 joins the two voxels.
  EXPECT_NEAR(Volume(x, 10), 2.0 + 1.0 / 15.0, 1e-5);
  ExpectClosed(x, 10);
}

TEST(LabelSurfaceExtractor, PinchIsRelabelled)
{
  // Label 1 in octants 0 and 7 of a corner, labels 2 and 3 filling the other six: label 1 touches
  // itself only at the corner between other regions; one voxel is relabelled.
  std::map<std::array<int, 3>, int> v;
  for (int o = 0; o < 8; ++o)
  {
    const std::array<int, 3> ijk = { 1 + (o & 1), 1 + ((o >> 1) & 1), 1 + ((o >> 2) & 1) };
    v[ijk] = (o == 0 || o == 7) ? 1 : (o < 4 ? 2 : 3);
  }
  amLabelSurfaceExtractor x = Grid(4, v, 4);
  x.Extract(nullptr);
  EXPECT_EQ(x.RelabeledVoxels, 1);
  for (int label : { 10, 20, 30 })
    ExpectClosed(x, label);
}
