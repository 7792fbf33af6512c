#include "amSelfIntersection.h"

#include "amSurfaceMesh.h"
#include "vtkSMPTools.h"

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_set>

std::vector<vtkIdType> amSelfIntersection::Vertices(
  const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, int background)
{
  std::vector<vtkIdType> result;
  for (vtkIdType t : amSelfIntersection::Triangles(mesh, points, background))
    for (vtkIdType v : mesh.Triangles[t])
      result.push_back(v);
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

std::vector<vtkIdType> amSelfIntersection::Triangles(
  const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, int background)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  std::vector<vtkIdType> result;
  std::map<int, std::vector<vtkIdType>> byRegion; // triangle index, -t-1 when reversed
  const vtkIdType nt = mesh.NumberOfTriangles();
  if (mesh.Labels.size() != static_cast<size_t>(nt))
    return result;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (mesh.Labels[t][0] != background)
      byRegion[mesh.Labels[t][0]].push_back(t);
    if (mesh.Labels[t][1] != background && mesh.Labels[t][1] != mesh.Labels[t][0])
      byRegion[mesh.Labels[t][1]].push_back(-t - 1);
  }
  for (const auto& kv : byRegion)
  {
    std::vector<K::Point_3> pts;
    std::vector<vtkIdType> global;
    std::vector<std::vector<std::size_t>> polygons;
    std::map<vtkIdType, std::size_t> local;
    auto vertex = [&](vtkIdType id) {
      auto it = local.find(id);
      if (it != local.end())
        return it->second;
      pts.emplace_back(points[id][0], points[id][1], points[id][2]);
      global.push_back(id);
      return local[id] = pts.size() - 1;
    };
    std::vector<vtkIdType> triOf;
    for (vtkIdType code : kv.second)
    {
      const bool reversed = code < 0;
      const vtkIdType t = reversed ? -code - 1 : code;
      const auto& tri = mesh.Triangles[t];
      polygons.push_back({ vertex(tri[0]), vertex(tri[reversed ? 2 : 1]), vertex(tri[reversed ? 1 : 2]) });
      triOf.push_back(t);
    }
    if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
      continue;
    Mesh m;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polygons, m);
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    CGAL::Polygon_mesh_processing::self_intersections(m, std::back_inserter(pairs));
    for (const auto& p : pairs)
      for (Mesh::Face_index f : { p.first, p.second })
        result.push_back(triOf[static_cast<std::size_t>(f)]);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

namespace
{
// Below this many boxes the sweep scans instead of splitting further (CGAL's default is 10): a
// surface's triangle boxes are small and evenly spread, and a long scan of a thin slab costs less
// than the deep recursion (a third of the time on a million triangles, measured over 10-30000).
constexpr std::ptrdiff_t Cutoff = 5000;

// Float boxes, rounded outwards: a box holds its triangle, in a little over half the memory the
// sweep sorts.
using TriangleBox = CGAL::Box_intersection_d::Box_with_info_d<float, 3, vtkIdType>;

TriangleBox BoxOf(const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, vtkIdType t)
{
  float lo[3], hi[3];
  for (int d = 0; d < 3; ++d)
  {
    double l = points[mesh.Triangles[t][0]][d], h = l;
    for (int k = 1; k < 3; ++k)
    {
      l = std::min(l, points[mesh.Triangles[t][k]][d]);
      h = std::max(h, points[mesh.Triangles[t][k]][d]);
    }
    lo[d] = static_cast<float>(l);
    if (static_cast<double>(lo[d]) > l)
      lo[d] = std::nextafter(lo[d], -std::numeric_limits<float>::infinity());
    hi[d] = static_cast<float>(h);
    if (static_cast<double>(hi[d]) < h)
      hi[d] = std::nextafter(hi[d], std::numeric_limits<float>::infinity());
  }
  return TriangleBox(lo, hi, t);
}

/// The boxes of 'all' that may meet one of 'few': those reaching a cell of a grid (cells about
/// four of few's boxes wide) that one of few's boxes reaches. Two closed boxes that meet share a
/// point, and its cell is in both boxes' ranges.
std::vector<TriangleBox> Near(const std::vector<TriangleBox>& few, const std::vector<TriangleBox>& all)
{
  if (few.empty())
    return {};
  double lo[3] = { 1e300, 1e300, 1e300 }, size = 0;
  for (const TriangleBox& b : few)
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::min(lo[d], static_cast<double>(b.min_coord(d)));
      size = std::max(size, static_cast<double>(b.max_coord(d)) - b.min_coord(d));
    }
  const double h = std::max(4.0 * size, 1e-6);
  auto cell = [&](double x, int d) { return static_cast<long long>(std::floor((x - lo[d]) / h)); };
  auto key = [](long long i, long long j, long long k) {
    return (static_cast<unsigned long long>(i) * 73856093ULL) ^ (static_cast<unsigned long long>(j) * 19349663ULL) ^
      (static_cast<unsigned long long>(k) * 83492791ULL);
  };
  std::unordered_set<unsigned long long> cells;
  for (const TriangleBox& b : few)
    for (long long k = cell(b.min_coord(2), 2); k <= cell(b.max_coord(2), 2); ++k)
      for (long long j = cell(b.min_coord(1), 1); j <= cell(b.max_coord(1), 1); ++j)
        for (long long i = cell(b.min_coord(0), 0); i <= cell(b.max_coord(0), 0); ++i)
          cells.insert(key(i, j, k));
  // A hash collision only keeps a box that could have gone: the sweep decides. So does a box
  // over more than 64 cells (a long sliver of a triangle), kept without a look-up per cell.
  std::vector<TriangleBox> near;
  for (const TriangleBox& b : all)
  {
    double cellsOf = 1;
    for (int d = 0; d < 3; ++d)
      cellsOf *= static_cast<double>(cell(b.max_coord(d), d) - cell(b.min_coord(d), d) + 1);
    bool reaches = !(cellsOf <= 64);
    for (long long k = cell(b.min_coord(2), 2); k <= cell(b.max_coord(2), 2) && !reaches; ++k)
      for (long long j = cell(b.min_coord(1), 1); j <= cell(b.max_coord(1), 1) && !reaches; ++j)
        for (long long i = cell(b.min_coord(0), 0); i <= cell(b.max_coord(0), 0) && !reaches; ++i)
          reaches = cells.count(key(i, j, k)) > 0;
    if (reaches)
      near.push_back(b);
  }
  return near;
}
}

std::vector<vtkIdType> amSelfIntersection::AllTriangles(
  const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points)
{
  return amSelfIntersection::AllTriangles(mesh, points, nullptr);
}

std::vector<vtkIdType> amSelfIntersection::AllTriangles(
  const amSurfaceMesh& mesh, const std::vector<std::array<double, 3>>& points, const std::vector<vtkIdType>* among)
{
  const vtkIdType nt = mesh.NumberOfTriangles();
  std::vector<TriangleBox> boxes;
  boxes.reserve(static_cast<size_t>(nt));
  for (vtkIdType t = 0; t < nt; ++t)
    boxes.push_back(BoxOf(mesh, points, t));
  auto checker = [&](std::vector<vtkIdType>& found) {
    return [&](const TriangleBox& a, const TriangleBox& b) {
      if (a.info() == b.info())
        return; // one triangle in both sets of a partial check
      const auto& ta = mesh.Triangles[a.info()];
      const auto& tb = mesh.Triangles[b.info()];
      const double* pa[3] = { points[ta[0]].data(), points[ta[1]].data(), points[ta[2]].data() };
      const double* pb[3] = { points[tb[0]].data(), points[tb[1]].data(), points[tb[2]].data() };
      const vtkIdType ia[3] = { ta[0], ta[1], ta[2] }, ib[3] = { tb[0], tb[1], tb[2] };
      if (amSelfIntersection::Cross(pa, ia, pb, ib))
      {
        found.push_back(a.info());
        found.push_back(b.info());
      }
    };
  };
  std::vector<vtkIdType> result;
  if (among)
  {
    // A few triangles against the whole surface: the sweep ends early in every part of space
    // where none of them is.
    std::vector<TriangleBox> few;
    few.reserve(among->size());
    for (vtkIdType t : *among)
      few.push_back(BoxOf(mesh, points, t));
    std::vector<TriangleBox> near = Near(few, boxes);
    CGAL::box_intersection_d(few.begin(), few.end(), near.begin(), near.end(), checker(result), Cutoff);
  }
  else if (nt < 100000)
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), checker(result), Cutoff);
  else
  {
    // Two halves at once, cut across the longest axis at the median box: a box goes to each half
    // it reaches, so two boxes that meet share a half (where their overlap begins, or beyond the
    // cut when it begins there), and the pairs found twice are merged below.
    double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
    for (const TriangleBox& b : boxes)
      for (int d = 0; d < 3; ++d)
      {
        lo[d] = std::min(lo[d], static_cast<double>(b.min_coord(d)));
        hi[d] = std::max(hi[d], static_cast<double>(b.max_coord(d)));
      }
    const int axis = hi[0] - lo[0] >= std::max(hi[1] - lo[1], hi[2] - lo[2]) ? 0
      : hi[1] - lo[1] >= hi[2] - lo[2]                                       ? 1
                                                                             : 2;
    std::vector<double> lows(boxes.size());
    for (size_t i = 0; i < boxes.size(); ++i)
      lows[i] = boxes[i].min_coord(axis);
    std::nth_element(lows.begin(), lows.begin() + lows.size() / 2, lows.end());
    const double cut = lows[lows.size() / 2];
    std::vector<TriangleBox> halves[2];
    for (const TriangleBox& b : boxes)
    {
      if (b.min_coord(axis) <= cut)
        halves[0].push_back(b);
      if (b.max_coord(axis) >= cut)
        halves[1].push_back(b);
    }
    std::vector<vtkIdType> found[2];
    vtkSMPTools::For(0, 2, 1, [&](vtkIdType h0, vtkIdType h1) {
      for (vtkIdType h = h0; h < h1; ++h)
        CGAL::box_self_intersection_d(halves[h].begin(), halves[h].end(), checker(found[h]), Cutoff);
    });
    result = std::move(found[0]);
    result.insert(result.end(), found[1].begin(), found[1].end());
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

bool amSelfIntersection::Cross(
  const double* const a[3], const vtkIdType ia[3], const double* const b[3], const vtkIdType ib[3])
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using P = K::Point_3;
  const P pa[3] = { P(a[0][0], a[0][1], a[0][2]), P(a[1][0], a[1][1], a[1][2]), P(a[2][0], a[2][1], a[2][2]) };
  const P pb[3] = { P(b[0][0], b[0][1], b[0][2]), P(b[1][0], b[1][1], b[1][2]), P(b[2][0], b[2][1], b[2][2]) };
  int sa[3], sb[3], shared = 0; // positions of the shared vertices in a and b
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j])
      {
        sa[shared] = i;
        sb[shared] = j;
        ++shared;
      }
  if (shared == 3)
    return true;
  if (shared == 0)
    return CGAL::do_intersect(K::Triangle_3(pa[0], pa[1], pa[2]), K::Triangle_3(pb[0], pb[1], pb[2]));
  if (shared == 1)
  {
    // They cross beyond the shared vertex iff the opposite edge of one meets the other.
    const P& p1 = pa[(sa[0] + 1) % 3];
    const P& p2 = pa[(sa[0] + 2) % 3];
    const P& q1 = pb[(sb[0] + 1) % 3];
    const P& q2 = pb[(sb[0] + 2) % 3];
    return CGAL::do_intersect(K::Segment_3(p1, p2), K::Triangle_3(pb[0], pb[1], pb[2])) ||
      CGAL::do_intersect(K::Segment_3(q1, q2), K::Triangle_3(pa[0], pa[1], pa[2]));
  }
  // Shared edge: they overlap iff coplanar with the other two vertices on the same side.
  const P& s0 = pa[sa[0]];
  const P& s1 = pa[sa[1]];
  const P& p = pa[3 - sa[0] - sa[1]];
  const P& q = pb[3 - sb[0] - sb[1]];
  return CGAL::coplanar(s0, s1, p, q) && CGAL::coplanar_orientation(s0, s1, p, q) == CGAL::POSITIVE;
}
