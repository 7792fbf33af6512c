/**
 * @class   amTetraInterfaceUpdate
 * @brief   The surface of a tetrahedral mesh made anew after elements changed region (not wrapped).
 *
 * When amTetraMeshOptimizer hands a sliver to the region across the surface, the boundary and
 * interface triangles are no longer those the mesh was made from. Rebuild replaces them by the
 * faces where the region changes or the mesh ends (amTetraFaces): a triangle that remains keeps
 * its place, its orientation and its cell data (Labels recomputed from the regions on its two
 * sides); the new ones follow in the order of their sorted nodes, each with -1 in every cell
 * array but Labels, oriented as amTetraFaces does (normal from Labels[0] into Labels[1]).
 */
#ifndef amTetraInterfaceUpdate_h
#define amTetraInterfaceUpdate_h

#include <array>
#include <vector>

class vtkPolyData;

class amTetraInterfaceUpdate
{
public:
  /// surface: triangles on the mesh's points with the 2-component cell array "Labels";
  /// tets/regions: the mesh; background: the label of the outside. Returns the new triangles,
  /// as they are now in 'surface'.
  static std::vector<std::array<int, 3>> Rebuild(vtkPolyData* surface, const std::vector<double>& points,
    const std::vector<std::array<int, 4>>& tets, const std::vector<int>& regions, int background);

  /// The label of the outside as the surface shows it: a label on a triangle that no tetrahedron
  /// has (0 when every triangle lies between two regions of the mesh).
  static int Background(vtkPolyData* surface, const std::vector<int>& regions);
};

#endif
