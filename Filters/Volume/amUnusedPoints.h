/**
 * @file    amUnusedPoints.h
 * @brief   Removes the points no cell of a mesh uses, renumbering the rest in their order, in the
 *          mesh and in a surface that shares its points (the tetrahedralizers' interfaces).
 *
 * Collapses and relabelling in the element improvement leave points behind that no tetrahedron
 * uses; solvers that assemble over every point (FEniCSx, openCARP) then get empty rows or fail. Point
 * data follows the points; cells keep their order and types.
 */
#ifndef amUnusedPoints_h
#define amUnusedPoints_h

#include "vtkType.h"

class vtkPolyData;
class vtkUnstructuredGrid;

namespace amUnusedPoints
{
/// Removes the unused points of 'mesh' (and renumbers 'surface', which must use only the mesh's
/// used points and share its vtkPoints, when given). Returns the number of points removed.
vtkIdType Remove(vtkUnstructuredGrid* mesh, vtkPolyData* surface);
}

#endif
