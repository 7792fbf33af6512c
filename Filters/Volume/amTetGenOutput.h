/**
 * @file    amTetGenOutput.h
 * @brief   TetGen's tetrahedra as amTetrahedralize's two outputs (not wrapped): the mesh of the
 *          regions and its boundary and interface triangles on the same points.
 */
#ifndef amTetGenOutput_h
#define amTetGenOutput_h

#include "amTetGenRun.h"

#include <string>

class amSurfaceMesh;
class amTetraRegions;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace amTetGenOutput
{
/// The tetrahedra of 'out' (made from 'mesh', labelled by 'regions') outside the background as
/// 'grid': the input surface's points first, in their order, then the Steiner points used; every
/// tetrahedron positively oriented; cell data "Region", point data "SurfacePointId" (-1 for a
/// Steiner point). TetGen's boundary faces as 'interfaces' on the same points, each oriented as its
/// input triangle, with cell data "Labels" (the input triangle's pair), "SourceTriangle" and
/// "Tetra" (the tetrahedron on each side, -1 for none). False with 'why' when every tetrahedron
/// lies in the background.
bool Build(const amSurfaceMesh& mesh, const amTetGenRun::Result& out, const amTetraRegions& regions, int bg,
  vtkUnstructuredGrid* grid, vtkPolyData* interfaces, std::string& why);
}

#endif
