/**
 * @class   amTetraSubset
 * @brief   Some tetrahedra of a mesh (the heart's, the torso's) as a compact finite-element mesh:
 *          nodes numbered in input point order, and back to a vtkUnstructuredGrid with the
 *          cells' region labels and each point's "InputPointId". Shared by the simulation filters.
 */
#ifndef amTetraSubset_h
#define amTetraSubset_h

#include "amP1Assembly.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkDataArray;
class vtkUnstructuredGrid;

class amTetraSubset
{
public:
  /// The cells of the given regions (every cell where 'regions' is null), each checked to be a
  /// tetrahedron; the problem naming the regions the mesh has, or "" when there is at least one.
  static std::string SelectRegions(vtkUnstructuredGrid* input, vtkDataArray* regions, const char* regionArrayName,
    const std::vector<int>& wanted, std::vector<vtkIdType>& cells);

  /// Take the given tetrahedra (cell ids of input) and their points.
  void Build(vtkUnstructuredGrid* input, const std::vector<vtkIdType>& cells);

  /// The nodes within 'radius' (mm) of 'centre', in node order.
  std::vector<vtkIdType> NodesWithin(const double centre[3], double radius) const;

  /// The subset as a grid: points, tetrahedra, a copy of 'regions' for its cells (if given), and
  /// point data InputPointId.
  vtkSmartPointer<vtkUnstructuredGrid> MakeGrid(vtkDataArray* regions) const;

  std::vector<vtkIdType> Cells;  // input cell of each tetrahedron
  std::vector<vtkIdType> Global; // input point of each node
  std::vector<vtkIdType> Local;  // node of each input point, or -1
  amP1Assembly Fem;
};

#endif
