/**
 * @class   amTetGenRun
 * @brief   TetGen 1.5 on a labelled triangle surface, in a child process: the constrained Delaunay
 *          tetrahedra of the piecewise linear complex the triangles make, refined to a size field.
 *
 * TetGen 1.5.0 frees its memory twice when it stops on an error in library mode
 * (terminatetetgen, then the mesh destructor), which crashes the caller: in a child process an
 * error or a crash of TetGen becomes a message. Each input triangle is a facet whose marker is
 * its index + 1, so every boundary triangle of the result names its source. RunEach runs several
 * surfaces in as many child processes at once (amTetGenParts: groups of regions).
 *
 * Reference: H. Si, TetGen, a Delaunay-based quality tetrahedral mesh generator, ACM TOMS 41(2),
 * 2015.
 *
 * @sa amTetrahedralize amTetraRegions amTetGenParts
 */
#ifndef amTetGenRun_h
#define amTetGenRun_h

#include "AnatomeshFiltersVolumeModule.h" // export macro

#include "vtkType.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

class amGradedSizeField;
class amSurfaceMesh;

class ANATOMESHFILTERSVOLUME_EXPORT amTetGenRun
{
public:
  /// What TetGen returns (or why it failed).
  struct Result
  {
    int Code = 0; // TetGen's error code, 0 on success
    vtkIdType NumberOfPoints = 0, NumberOfTetrahedra = 0, NumberOfFaces = 0;
    std::vector<double> Points;                                 // 3 per point; the input's first, in order
    std::vector<int> Tetrahedra, Neighbors, Faces, FaceMarkers; // 4, 4 (-1: none), 3, 1 per item
  };
  /// Tetrahedralizes the surface with TetGen's switches; a tetrahedron whose circumradius
  /// exceeds 0.75 times the size field at its centroid is refined. Returns "" on success, else
  /// why it failed (TetGen's own words included).
  static std::string Run(
    const amSurfaceMesh& mesh, const amGradedSizeField& field, const std::string& switches, Result& result);

  /// A surface to tetrahedralize, and points inside the parts of its volume to leave empty
  /// (TetGen's holes: the tetrahedra around each are removed up to the surface).
  struct Input
  {
    const amSurfaceMesh* Mesh = nullptr;
    std::vector<std::array<double, 3>> Holes;
  };
  /// Run on each input, all in child processes at once; per input "" or why it failed.
  /// 'meanwhile' (may be empty) runs on the calling thread while the children work.
  static std::vector<std::string> RunEach(const std::vector<Input>& inputs, const amGradedSizeField& field,
    const std::string& switches, std::vector<Result>& results, const std::function<void()>& meanwhile = nullptr);
};

#endif
