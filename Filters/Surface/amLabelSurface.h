/**
 * @class   amLabelSurface
 * @brief   One conforming, oriented, manifold triangle surface for every label of a label map
 *          (multi-material discrete surface extraction).
 *
 * Every voxel face that separates two different labels becomes two triangles, and every such
 * face is emitted once, so an interface between two regions (including a region and the
 * background) appears exactly once and all regions share its vertices; junction curves (where
 * three or more regions meet) are shared edges by construction. This is the surface-nets /
 * cuberille topology (the vertices sit at voxel corners, the centres of the dual cells of the
 * voxel-centre lattice); amSurfaceSmoothing then removes the staircase.
 *
 * Plain voxel-face surfaces are not manifold where a label touches itself only along a voxel edge
 * (a "checkerboard" of four voxels around an edge) or only at a voxel corner. Such places are
 * resolved, not left broken:
 * - around an edge whose four voxels repeat a label on a diagonal (a b a b, a b a c), the
 *   repeated label stays connected through the edge (for a b a b, the larger label); the
 *   edge is split in two, each copy bending slightly (a quarter voxel) towards the voxel it wraps,
 *   and the faces on it get a centre vertex;
 * - at a voxel corner, the incident faces are grouped by the connectivity of the surface around
 *   the corner; each group gets its own copy of the vertex, moved slightly into its side.
 * - one configuration cannot be split: a label whose voxels touch only at a corner while the other
 *   labels around that corner are connected across it (e.g. octants 0 and 7 of one label, the
 *   rest two other labels). There one of the two voxels takes the most frequent other label of
 *   its neighbours in the corner's block (a warning gives the count: RelabeledVoxels), and the
 *   topology table's VoxelVolume counts the repaired map. It is rare (2 voxels in the 2 mm
 *   phantom).
 * The result: every region's boundary is a closed, consistently oriented 2-manifold, the
 * interfaces conform, and no triangle is degenerate. The voxels outside the image count as
 * BackgroundLabel, so regions touching the image border are closed too.
 *
 * Output: triangles with cell data "Labels" (2 components: Labels[0] > Labels[1]; the triangle's
 * normal points from region Labels[0] into region Labels[1], so organ/background faces point
 * outwards). Field data: "VoxelSize" (the smallest spacing, mm; amSurfaceSmoothing uses it to
 * bound displacements), "LabelVoxelVolumes" (label, mm^3 of its voxels, for every label but the
 * background; amTetrahedralize compares its regions' volumes with them), "Provenance". Output port 1 is a vtkTable with
 * one row per region (label, triangles, vertices, edges, Euler characteristic, components, boundary edges, non-manifold
 * edges, wrongly oriented edges, area mm^2, enclosed volume mm^3, voxel volume mm^3): boundary, non-manifold and
 * wrongly oriented edges are zero when the surface is right, and the enclosed volume equals the label's voxel volume.
 *
 * Labels must be whole numbers (any scalar type), at most amInputCheck::MaximumLabels (1000) of them
 * besides the background: an image with more distinct values is a scan given where its label map
 * belongs, and is refused. The image may carry a direction matrix (vertex
 * positions follow it, and orientation is kept when it mirrors).
 *
 * References: W. E. Lorensen and H. E. Cline, Marching cubes, SIGGRAPH 1987; Z. Wu and J. M.
 * Sullivan, Multiple material marching cubes algorithm, IJNME 58, 2003 (VTK's discrete flying edges
 * makes one surface per label; this filter makes one conforming surface of them all).
 *
 * @sa amSurfaceSmoothing amMetricRemeshing amTetrahedralize
 */
#ifndef amLabelSurface_h
#define amLabelSurface_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class ANATOMESHFILTERSSURFACE_EXPORT amLabelSurface : public vtkPolyDataAlgorithm
{
public:
  static amLabelSurface* New();
  vtkTypeMacro(amLabelSurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The label that is not a region (default 0). Voxels outside the image count as this label.
  vtkSetMacro(BackgroundLabel, int);
  vtkGetMacro(BackgroundLabel, int);
  ///@}

  ///@{
  /// Compute the per-region topology table on output port 1 (default on; costs ~10 % of the run).
  vtkSetMacro(ComputeTopology, bool);
  vtkGetMacro(ComputeTopology, bool);
  vtkBooleanMacro(ComputeTopology, bool);
  ///@}

  /// Number of voxel edges and corners whose self-touching label was resolved in the last run.
  vtkGetMacro(ResolvedEdges, vtkIdType);
  vtkGetMacro(SplitCorners, vtkIdType);
  /// Voxels relabelled in the last run (see the class documentation).
  vtkGetMacro(RelabeledVoxels, vtkIdType);
#ifndef __VTK_WRAP__
  [[deprecated("use GetRelabeledVoxels")]] vtkIdType GetRelabelledVoxels()
  {
    return this->GetRelabeledVoxels();
  }
#endif

protected:
  amLabelSurface();
  ~amLabelSurface() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int BackgroundLabel;
  bool ComputeTopology;
  vtkIdType ResolvedEdges;
  vtkIdType SplitCorners;
  vtkIdType RelabeledVoxels;

private:
  amLabelSurface(const amLabelSurface&) = delete;
  void operator=(const amLabelSurface&) = delete;
};

#endif
