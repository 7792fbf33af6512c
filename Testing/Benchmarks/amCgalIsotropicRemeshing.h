// CGAL's uniform isotropic remeshing of a closed triangle surface, for the surface benchmark's
// comparison (the reference: 3 iterations on the phantom's outer surface).
#ifndef amCgalIsotropicRemeshing_h
#define amCgalIsotropicRemeshing_h

#include "vtkSmartPointer.h"

class vtkPolyData;

namespace amBench
{
/// CGAL::Polygon_mesh_processing::isotropic_remeshing of every face to edgeLength (mm), the given
/// number of iterations; the surface must be a manifold polygon mesh.
vtkSmartPointer<vtkPolyData> CgalIsotropicRemeshing(vtkPolyData* surface, double edgeLength, int iterations);
}

#endif
