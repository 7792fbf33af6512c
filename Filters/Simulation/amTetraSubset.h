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

#include <vector>

class vtkDataArray;
class vtkUnstructuredGrid;

class amTetraSubset
{
public:
  /// Take the given tetrahedra (cell ids of input) and their points.
  void Build(vtkUnstructuredGrid* input, const std::vector<vtkIdType>& cells);

  /// The subset as a grid: points, tetrahedra, a copy of 'regions' for its cells (if given), and
  /// point data InputPointId.
  vtkSmartPointer<vtkUnstructuredGrid> MakeGrid(vtkDataArray* regions) const;

  std::vector<vtkIdType> Cells;  // input cell of each tetrahedron
  std::vector<vtkIdType> Global; // input point of each node
  std::vector<vtkIdType> Local;  // node of each input point, or -1
  amP1Assembly Fem;
};

#endif
