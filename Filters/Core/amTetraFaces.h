/**
 * @class   amTetraFaces
 * @brief   The faces of a tetrahedral mesh where the region label changes (interfaces) or the
 *          mesh ends (boundary), each once and consistently oriented.
 *
 * Every face of every tetrahedron is sorted by its nodes; a face met once lies on the mesh
 * boundary, a face met twice with two different labels is an interface, a face met twice with
 * one label is interior and skipped. Each kept face is oriented by the project's convention
 * (that of amLabelSurface and both tetrahedralisers): First is the higher label, the outside of
 * the mesh (label Outside()) always second, and the triangle's normal points from First into
 * Second. Orientation follows each tetrahedron's own sign, so tetrahedra of either handedness
 * give the same faces. Faces come out in the order of their sorted node triples: the result does
 * not depend on the order of the tetrahedra. Plain C++ (no VTK objects).
 */
#ifndef amTetraFaces_h
#define amTetraFaces_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkType.h"

#include <array>
#include <climits>
#include <vector>

class ANATOMESHFILTERSCORE_EXPORT amTetraFaces
{
public:
  struct Face
  {
    std::array<vtkIdType, 3> Points; // normal from First into Second
    vtkIdType FirstTetra;            // the tetrahedron on the First side
    vtkIdType SecondTetra;           // on the Second side, -1 outside the mesh
    int First;                       // the higher label
    int Second;                      // the lower label, Outside() outside the mesh
  };

  /// Label given to the outside of the mesh.
  static constexpr int Outside() { return INT_MIN; }

  /// points: x y z of every node (3 doubles each); tetrahedra: node indices; labels: one per
  /// tetrahedron, or null (all equal: only the boundary is returned).
  static std::vector<Face> Find(
    const double* points, const std::vector<std::array<vtkIdType, 4>>& tetrahedra, const int* labels);

  /// The faces of one tetrahedron only (the mesh's boundary), each as its sorted node triple, in
  /// the order of those triples.
  static std::vector<std::array<int, 3>> Boundary(const std::vector<std::array<int, 4>>& tetrahedra);
};

#endif
