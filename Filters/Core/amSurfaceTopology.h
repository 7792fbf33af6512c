/**
 * @class   amSurfaceTopology
 * @brief   Per-region topology and measures of a multi-material triangle surface.
 *
 * The surface's triangles carry a 2-component cell array (by default "Labels"): the regions on
 * either side, the triangle's normal pointing from region Labels[0] into region Labels[1]. For
 * every region except the background, its boundary is the set of triangles naming it (reversed
 * where it is Labels[1], so the boundary is oriented outwards). Analyse reports for each region:
 * vertices V, edges E, triangles F, Euler characteristic V - E + F (2 for a sphere, 0 for a
 * torus, summed over components), connected components, boundary edges (one triangle: the region
 * is open there), non-manifold edges (more than two triangles), misoriented edges (two triangles
 * that traverse the edge the same way), non-manifold vertices (where the region's triangles form
 * several fans: a pinch), area and enclosed volume (divergence theorem). A closed, oriented,
 * manifold boundary has zero boundary, non-manifold and misoriented edges and no pinched vertex.
 */
#ifndef amSurfaceTopology_h
#define amSurfaceTopology_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;
class vtkTable;

class ANATOMESHFILTERSCORE_EXPORT amSurfaceTopology
{
public:
  struct Region
  {
    int Label = 0;
    long long Triangles = 0, Vertices = 0, Edges = 0, Euler = 0;
    long long Components = 0, BoundaryEdges = 0, NonManifoldEdges = 0, MisorientedEdges = 0;
    long long NonManifoldVertices = 0; // vertices where the region's triangles form several fans
    double Area = 0.0, Volume = 0.0;
  };

  /// Analyse every region of surface (triangles only). Returns false with 'why' set when the
  /// surface has no such array, non-triangle cells, or NaN coordinates.
  static bool Analyse(vtkPolyData* surface, std::vector<Region>& regions, std::string& why, int background = 0,
    const char* labelsName = "Labels");

  /// One row per region, columns named as the Region fields.
  static vtkSmartPointer<vtkTable> ToTable(const std::vector<Region>& regions);
};

#endif
