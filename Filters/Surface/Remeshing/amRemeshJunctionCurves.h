/**
 * @file    amRemeshJunctionCurves.h
 * @brief   The input's junction curves (where three or more regions meet) as the remesher keeps
 *          them: every curve vertex of the result sits on an input curve vertex, its anchor.
 *
 * A result vertex's triangles may only belong to its anchor's interfaces, and a junction edge is
 * split at the input curve vertex halfway along the input curve between its two anchors, so the
 * curves of the result visit the input's curve vertices in their order (splitting at the curve
 * vertex nearest the edge's midpoint could pick one from a neighbouring stretch of the curve
 * and fold it back).
 */
#ifndef amRemeshJunctionCurves_h
#define amRemeshJunctionCurves_h

#include "amRemeshSurface.h"

#include <utility>
#include <vector>

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT JunctionCurves
{
public:
  /// Per input vertex on a junction curve or corner: the interfaces around it (sorted).
  std::vector<std::vector<int>> InputSheets;
  /// Per input curve vertex: its neighbours along the curves, with the edge lengths.
  std::vector<std::vector<std::pair<int, double>>> CurveNeighbours;

  /// From the input surface (its topology built) and its triangles with their sheets; sets
  /// the surface's anchors (each input curve vertex is its own).
  void Build(const amSurfaceMesh& mesh, Surface& surface);
  /// Whether vertex v may have a triangle of interface 'sheet' (its anchor's, or a merged one's).
  bool Allowed(const Surface& surface, int v, int sheet) const
  {
    if (surface.Kind[v] == amSurfaceMesh::Surface || surface.Anchor[v] < 0)
      return true;
    const auto& sheets = this->InputSheets[surface.Anchor[v]];
    const auto& merged = surface.Merged[v];
    return std::binary_search(sheets.begin(), sheets.end(), sheet) ||
      std::binary_search(merged.begin(), merged.end(), sheet);
  }
  /// The input curve vertex halfway (by length) along the shortest input curve path from a to b
  /// no longer than maxLength, not a or b themselves (-1: no such path, or no vertex between).
  int CurveMiddle(int a, int b, double maxLength) const;
};
}

#endif
