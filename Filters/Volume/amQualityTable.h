/**
 * @file    amQualityTable.h
 * @brief   The paper's Table 1 per region of a tetrahedral mesh (not wrapped): the plain core of
 *          amMeshQuality.
 *
 * Per region (and for the whole mesh): np the vertices with a tetrahedron in the region, nt the
 * boundary triangles of the region (faces with one tetrahedron of the region), ne the
 * tetrahedra, and the mean, smallest and largest quality, the smallest and largest dihedral angle,
 * the volume and the tetrahedra that are inverted or flat. For the whole mesh, nt counts faces
 * with one tetrahedron or two of different regions.
 */
#ifndef amQualityTable_h
#define amQualityTable_h

#include "vtkType.h"

#include <array>
#include <limits>
#include <map>
#include <vector>

namespace amQualityTable
{
struct Row
{
  long long np = 0, nt = 0, ne = 0, inverted = 0;
  double sumQ = 0, minQ = std::numeric_limits<double>::infinity(), maxQ = 0;
  double minD = 180, maxD = 0, volume = 0; // degrees, mm^3
};

/// tets: 4 point ids each; region: one label each; q, dmin, dmax, vol: one value each (amMeshQuality::
/// TetraQuality's). rows: per region, in increasing label order; all: the whole mesh.
void Count(const std::vector<std::array<vtkIdType, 4>>& tets, const std::vector<int>& region, vtkIdType npoints,
  const double* q, const double* dmin, const double* dmax, const double* vol, std::map<int, Row>& rows, Row& all);
}

#endif
