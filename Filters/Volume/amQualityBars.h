/**
 * @file    amQualityBars.h
 * @brief   The tetrahedra's bars checked on every run: no element above the paper's quality Q 10 and
 *          none with a dihedral angle under 10 degrees, whatever the parameters that made the mesh.
 *
 * A miss is a warning with its counts and the worst element's place (centroid, region), so a run
 * with coarse settings says so instead of writing a mesh with slivers silently.
 */
#ifndef amQualityBars_h
#define amQualityBars_h

#include "vtkType.h"

#include <string>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace amQualityBars
{
struct Result
{
  vtkIdType AboveQuality = 0;    // tetrahedra with Q above the bar
  vtkIdType BelowDihedral = 0;   // tetrahedra with a dihedral angle under the bar
  vtkIdType Poor = 0;            // tetrahedra that miss either bar
  double WorstQuality = 0;       // the largest Q
  double SmallestDihedral = 180; // degrees
  vtkIdType WorstCell = -1;      // the element of the smallest dihedral angle (or the largest Q)
};

/// The mesh's tetrahedra against the bars (Q at most maximumQuality, every dihedral angle at least
/// minimumDihedral degrees).
Result Check(vtkUnstructuredGrid* mesh, double maximumQuality = 10.0, double minimumDihedral = 10.0);

/// The tetrahedralizers' last step: the points no tetrahedron uses removed (amUnusedPoints), the
/// bars checked; returns the warning ("" when the bars hold), ending with 'remedy' (the calling
/// filter's properties that free such elements), and sets 'poor' to the elements that miss them.
std::string Finish(vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, vtkIdType& poor, const std::string& remedy);

/// The warning for a result that misses a bar ("" when both hold), naming the worst element's
/// centroid and region, then 'remedy'.
std::string Warning(vtkUnstructuredGrid* mesh, const Result& result, const std::string& remedy,
  double maximumQuality = 10.0, double minimumDihedral = 10.0);
}

#endif
