#include "amSelfIntersection.h"

#include "amSurfaceMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <map>

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
