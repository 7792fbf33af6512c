#include "amTetraFaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

namespace
{
// Faces of tetrahedron (0 1 2 3), each outward when the tetrahedron is positive (amTetraFaces').
const int FaceOf[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

/// The six tetrahedra of the cube at (i, j, k), each the path from its lowest corner to its
/// highest along the three axes in one order (Kuhn's split: neighbouring cubes share diagonals).
template<typename Id, typename Node>
std::vector<std::array<Id, 4>> CubeTetrahedra(int i, int j, int k, Node&& node)
{
  static const int axes[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  std::vector<std::array<Id, 4>> tets;
  for (const auto& ax : axes)
  {
    int c[3] = { i, j, k };
    std::array<Id, 4> t;
    t[0] = static_cast<Id>(node(c[0], c[1], c[2]));
    for (int s = 0; s < 3; ++s)
    {
      ++c[ax[s]];
      t[s + 1] = static_cast<Id>(node(c[0], c[1], c[2]));
    }
    tets.push_back(t);
  }
  return tets;
}

double Orientation(const double* p, vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d)
{
  double e[3][3];
  for (int k = 0; k < 3; ++k)
  {
    e[0][k] = p[3 * b + k] - p[3 * a + k];
    e[1][k] = p[3 * c + k] - p[3 * a + k];
    e[2][k] = p[3 * d + k] - p[3 * a + k];
  }
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
    e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}
}

// A block of n^3 cubes, six tetrahedra each, with shuffled node numbers, tetrahedra of both
// handedness and random labels: Find gives every face met once or between two labels, once, in
// the order of the sorted node triples, with the higher label first and its normal pointing out
// of the First tetrahedron; what a map of every face says, face for face.
TEST(TetraFaces, EveryBoundaryAndInterfaceFaceOnceInOrder)
{
  const int n = 7;
  std::mt19937 random(3);
  std::vector<vtkIdType> number((n + 1) * (n + 1) * (n + 1));
  for (size_t i = 0; i < number.size(); ++i)
    number[i] = static_cast<vtkIdType>(i);
  std::shuffle(number.begin(), number.end(), random);
  std::vector<double> points(3 * number.size());
  auto node = [&](int i, int j, int k) { return number[(k * (n + 1) + j) * (n + 1) + i]; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        const vtkIdType v = node(i, j, k);
        points[3 * v] = i;
        points[3 * v + 1] = j;
        points[3 * v + 2] = k;
      }
  std::vector<std::array<vtkIdType, 4>> tets;
  std::vector<int> labels;
  std::uniform_int_distribution<int> label(1, 3);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (std::array<vtkIdType, 4> t : CubeTetrahedra<vtkIdType>(i, j, k, node))
        {
          if (random() % 2)
            std::swap(t[2], t[3]); // either handedness
          tets.push_back(t);
          labels.push_back(label(random));
        }
  const std::vector<amTetraFaces::Face> faces = amTetraFaces::Find(points.data(), tets, labels.data());

  std::map<std::array<vtkIdType, 3>, std::vector<vtkIdType>> all; // sorted face -> its tetrahedra
  for (size_t t = 0; t < tets.size(); ++t)
    for (const auto& f : FaceOf)
    {
      std::array<vtkIdType, 3> key = { tets[t][f[0]], tets[t][f[1]], tets[t][f[2]] };
      std::sort(key.begin(), key.end());
      all[key].push_back(static_cast<vtkIdType>(t));
    }
  std::vector<std::array<vtkIdType, 3>> expected;
  for (const auto& [key, ts] : all)
    if (ts.size() == 1 || labels[ts[0]] != labels[ts[1]])
      expected.push_back(key);
  ASSERT_EQ(faces.size(), expected.size());
  size_t boundary = 0;
  for (size_t i = 0; i < faces.size(); ++i)
  {
    const amTetraFaces::Face& f = faces[i];
    std::array<vtkIdType, 3> key = f.Points;
    std::sort(key.begin(), key.end());
    ASSERT_EQ(key, expected[i]) << "face " << i;
    const std::vector<vtkIdType>& ts = all[key];
    boundary += ts.size() == 1;
    if (ts.size() == 1)
    {
      EXPECT_EQ(f.Second, amTetraFaces::Outside());
      EXPECT_EQ(f.SecondTetra, -1);
    }
    else
    {
      EXPECT_GT(f.First, f.Second);
      EXPECT_EQ(f.SecondTetra, f.FirstTetra == ts[0] ? ts[1] : ts[0]);
    }
    EXPECT_EQ(f.First, labels[f.FirstTetra]);
    // The normal points away from the First tetrahedron's fourth node.
    const auto& t = tets[f.FirstTetra];
    vtkIdType apex = -1;
    for (vtkIdType v : t)
      if (v != f.Points[0] && v != f.Points[1] && v != f.Points[2])
        apex = v;
    EXPECT_LT(Orientation(points.data(), f.Points[0], f.Points[1], f.Points[2], apex), 0) << "face " << i;
  }
  EXPECT_EQ(boundary, static_cast<size_t>(6 * 2 * n * n)); // the block's six sides, two triangles a square
  // Without labels: the boundary alone.
  EXPECT_EQ(amTetraFaces::Find(points.data(), tets, nullptr).size(), boundary);
}

// Boundary: the faces of one tetrahedron only, as sorted triples in their order; the same as
// Find without labels.
TEST(TetraFaces, BoundaryIsTheFacesOfOneTetrahedron)
{
  // Two cubes side by side, six tetrahedra each (Kuhn's split: the same diagonal on the shared side).
  std::vector<double> points;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        points.insert(points.end(), { double(i), double(j), double(k) });
  auto node = [](int i, int j, int k) { return (k * 2 + j) * 3 + i; };
  std::vector<std::array<int, 4>> tets;
  std::vector<std::array<vtkIdType, 4>> wide;
  for (int i = 0; i < 2; ++i)
    for (const std::array<int, 4>& t : CubeTetrahedra<int>(i, 0, 0, node))
    {
      tets.push_back(t);
      wide.push_back({ t[0], t[1], t[2], t[3] });
    }
  const std::vector<std::array<int, 3>> boundary = amTetraFaces::Boundary(tets);
  EXPECT_EQ(boundary.size(), 20u); // the box's ten squares, two triangles each
  EXPECT_TRUE(std::is_sorted(boundary.begin(), boundary.end()));
  const std::vector<amTetraFaces::Face> faces = amTetraFaces::Find(points.data(), wide, nullptr);
  ASSERT_EQ(faces.size(), boundary.size());
  for (size_t i = 0; i < faces.size(); ++i)
  {
    std::array<vtkIdType, 3> key = faces[i].Points;
    std::sort(key.begin(), key.end());
    EXPECT_EQ(key[0], boundary[i][0]);
    EXPECT_EQ(key[1], boundary[i][1]);
    EXPECT_EQ(key[2], boundary[i][2]);
  }
}
