/**
 * @class   amLabelSurfaceExtractor
 * @brief   LabelSurface's algorithm without the pipeline: one conforming multi-material triangle
 *          surface of a label map (discrete marching cubes on the voxel faces).
 *
 * Every voxel face between two labels becomes two triangles on the face's four corners, oriented
 * from the higher-ranked label (the background ranks lowest). A corner where several fans of
 * faces meet only at the corner gets one vertex copy per fan, moved a little into its own side,
 * so every region's surface is a closed manifold; an edge where one label meets itself across
 * the diagonal of four voxels is resolved by a fan around each face on it, bent towards the
 * voxel the face wraps. A label touching itself only at a voxel corner between other regions
 * (which no vertex split can make manifold) has one voxel relabelled there (the most frequent
 * other label around it), and the corners around it are analysed again.
 *
 * The filter fills Grid (the voxels' label ranks and the geometry) and reads the result. Passes
 * run slab by slab on the threads; the output does not depend on the thread count.
 *
 * @sa amLabelSurface amLabelCorners
 */
#ifndef amLabelSurfaceExtractor_h
#define amLabelSurfaceExtractor_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "amLabelGrid.h"

#include <array>
#include <functional>
#include <limits>
#include <vector>

class ANATOMESHFILTERSSURFACE_EXPORT amLabelSurfaceExtractor
{
public:
  amLabelGrid Grid;
  /// Whether the image's direction matrix mirrors (negative determinant): triangles then turn.
  bool Mirrored = false;

  /// Extracts the surface; progress (may be empty) is told the fraction of the filter's work.
  void Extract(const std::function<void(double)>& progress);

  std::vector<float> Points;        // 3 per vertex
  std::vector<vtkIdType> Triangles; // 3 per triangle
  std::vector<int> Labels;          // 2 per triangle: the labels on its front and back
  vtkIdType ResolvedEdges = 0, SplitCorners = 0, RelabeledVoxels = 0;

private:
  /// The corners on the surface and how many copies of each one's vertex, row by row; relabels
  /// pinched voxels (at most 20 rounds).
  void FindCorners();
  /// Corner vertex positions; a split corner's copies move a little into their own side.
  void PlaceCorners();
  /// The faces between labels, slab by slab (those on resolved edges set apart).
  void Faces();
  /// The faces on resolved edges: a centre vertex and a fan each (serial, in slab order).
  void ResolvedEdgeFaces();
  /// The triangles of every slab in order, then the fans.
  void Assemble();

  /// The vertex of the face at p (normal along axis) at its corner (a, b): the corner's copy
  /// that owns this face.
  vtkIdType CornerVertex(int axis, const int p[3], int a, int b) const;
  /// The four voxels around the edge of a face from local corner (a0, b0) to (a1, b1), cyclic.
  struct EdgeInfo
  {
    int Axis;
    int Lo[3];       // corner at the lower end
    int Voxel[4][3]; // cyclic
    int Q[4];
  };
  EdgeInfo EdgeAround(int axis, const int p[3], int a0, int b0, int a1, int b1) const;
  /// Orientation order of label ranks: the background below every label.
  long long Rank(int l) const
  {
    return l == this->Grid.Background ? std::numeric_limits<long long>::min() : static_cast<long long>(l);
  }

  struct Slab
  {
    std::vector<vtkIdType> Triangles;        // 3 per triangle
    std::vector<int> Labels;                 // 2 per triangle
    std::vector<std::array<int, 4>> Special; // axis, lower voxel (i, j, k) of faces on resolved edges
  };
  std::vector<Slab> Slabs;
  vtkIdType BasePoints = 0; // corner vertices (before the fans' centres and bent edges)
  std::vector<vtkIdType> SpecialTriangles;
  std::vector<int> SpecialLabels;
};

#endif
