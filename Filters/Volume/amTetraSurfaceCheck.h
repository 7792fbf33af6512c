/**
 * @class   amTetraSurfaceCheck
 * @brief   Whether a labelled triangle surface can be tetrahedralized region by region: labels on
 *          both sides of every triangle and different, no degenerate triangle, every region closed
 *          (no edge where a region's triangles occur an odd number of times), every region
 *          enclosing a volume. Each refusal names the triangles or the region.
 *
 * @sa amTetrahedralize
 */
#ifndef amTetraSurfaceCheck_h
#define amTetraSurfaceCheck_h

#include "AnatomeshFiltersVolumeModule.h" // export macro

#include "vtkType.h"

#include <string>
#include <vector>

class amSurfaceMesh;
class vtkPolyData;

class ANATOMESHFILTERSVOLUME_EXPORT amTetraSurfaceCheck
{
public:
  /// Checks the surface (input, and mesh built from it); false with 'why' at the first problem.
  static bool Check(vtkPolyData* input, const amSurfaceMesh& mesh, int background, std::string& why);
  /// At most ten triangle ids, and how many more.
  static std::string List(const std::vector<vtkIdType>& triangles);
};

#endif
