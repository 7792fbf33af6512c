// CGAL's uniform isotropic remeshing (Polygon_mesh_processing), the reference a user of CGAL would
// reach for, for BenchmarkSurface. Its own translation unit: CGAL is heavy to compile.
#include "amCgalIsotropicRemeshing.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <vector>

vtkSmartPointer<vtkPolyData> amBench::CgalIsotropicRemeshing(vtkPolyData* surface, double edgeLength, int iterations)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    points.emplace_back(p[0], p[1], p[2]);
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    if (n == 3)
      triangles.push_back(
        { static_cast<std::size_t>(ids[0]), static_cast<std::size_t>(ids[1]), static_cast<std::size_t>(ids[2]) });
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  PMP::isotropic_remeshing(faces(mesh), edgeLength, mesh, CGAL::parameters::number_of_iterations(iterations));
  mesh.collect_garbage();

  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (Mesh::Vertex_index v : mesh.vertices())
  {
    const K::Point_3& p = mesh.point(v);
    pts->InsertNextPoint(p.x(), p.y(), p.z());
  }
  vtkNew<vtkCellArray> cells;
  for (Mesh::Face_index f : mesh.faces())
  {
    vtkIdType tri[3], k = 0;
    for (Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      if (k < 3)
        tri[k++] = static_cast<vtkIdType>(v);
    cells->InsertNextCell(3, tri);
  }
  out->SetPoints(pts);
  out->SetPolys(cells);
  return out;
}
