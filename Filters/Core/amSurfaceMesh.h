/**
 * @class   amSurfaceMesh
 * @brief   Array-based triangle surface with edges, 1-rings and feature curves: the shared data
 *          structure of the surface filters (smoothing, curvature, remeshing, distances).
 *
 * Built from a vtkPolyData of triangles. Edges are unique vertex pairs with their triangles.
 * Feature edges are edges with other than two triangles (junction curves of a multi-material
 * surface, open borders, non-manifold edges) or whose two triangles carry different (unordered)
 * label pairs in the 2-component cell array "Labels". A vertex is a surface vertex (no feature
 * edge), a curve vertex (exactly two) or a corner (one, or three and more).
 */
#ifndef amSurfaceMesh_h
#define amSurfaceMesh_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkPolyData;

class ANATOMESHFILTERSCORE_EXPORT amSurfaceMesh
{
public:
  enum VertexKind : unsigned char
  {
    Surface = 0,
    Curve = 1,
    Corner = 2
  };

  /// Build from surface (triangles only; points must be finite). Returns false with 'why'.
  bool Build(vtkPolyData* surface, std::string& why, const char* labelsName = "Labels");

  /// Rebuild edges, rings and features from Points/Triangles/Labels already filled in.
  void BuildTopology();

  vtkIdType NumberOfPoints() const { return static_cast<vtkIdType>(this->Points.size()); }
  vtkIdType NumberOfTriangles() const { return static_cast<vtkIdType>(this->Triangles.size()); }

  std::vector<std::array<double, 3>> Points;
  std::vector<std::array<vtkIdType, 3>> Triangles;
  std::vector<std::array<int, 2>> Labels; // per triangle, as given (empty when absent)

  std::vector<std::array<vtkIdType, 2>> Edges; // sorted, A < B
  std::vector<vtkIdType> EdgeTriangleStart;    // CSR: triangles of edge e
  std::vector<vtkIdType> EdgeTriangles;
  std::vector<unsigned char> FeatureEdge;

  std::vector<vtkIdType> RingStart; // CSR: neighbours of each vertex (through edges)
  std::vector<vtkIdType> Ring;
  std::vector<vtkIdType> RingEdge;            // the edge to each neighbour
  std::vector<vtkIdType> VertexTriangleStart; // CSR: triangles around each vertex
  std::vector<vtkIdType> VertexTriangles;
  std::vector<unsigned char> Kind; // VertexKind

  /// Index of edge (a, b), or -1.
  vtkIdType FindEdge(vtkIdType a, vtkIdType b) const;
  /// Unnormalised normal (twice the area) of triangle t.
  std::array<double, 3> TriangleNormal(vtkIdType t) const;
};

#endif
