/**
 * @class   amTetraRegions
 * @brief   The region of every tetrahedron TetGen made from a labelled surface: a flood fill across
 *          the faces that are not surface triangles, each part taking the label that its bounding
 *          surface triangles give the side it lies on. A part whose triangles disagree makes the
 *          surface's labels inconsistent, and the triangles are named.
 *
 * @sa amTetrahedralize amTetGenRun
 */
#ifndef amTetraRegions_h
#define amTetraRegions_h

#include "AnatomeshFiltersVolumeModule.h" // export macro

#include "amTetGenRun.h"

#include <array>
#include <string>
#include <vector>

class amSurfaceMesh;

class ANATOMESHFILTERSVOLUME_EXPORT amTetraRegions
{
public:
  /// Labels the tetrahedra of 'out' (made from 'mesh'); false with 'why' when TetGen's faces name
  /// no source triangle or the labels disagree.
  bool Assign(const amSurfaceMesh& mesh, const amTetGenRun::Result& out, int background, std::string& why);

  /// Per tetrahedron: its region's label (the background's outside every region).
  std::vector<int> Label;
  /// Per boundary face of 'out': the tetrahedra on its source triangle's back (0) and front (1)
  /// sides (-1: none).
  std::vector<std::array<vtkIdType, 2>> SubfaceTet;
  /// The source triangle of boundary face s.
  static vtkIdType SourceOf(const amTetGenRun::Result& out, vtkIdType s)
  {
    return static_cast<vtkIdType>(out.FaceMarkers[s]) - 1;
  }
};

#endif
