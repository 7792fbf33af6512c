/**
 * @class   amSurfaceSmoothing
 * @brief   Non-shrinking (Taubin lambda|mu) smoothing of a multi-material surface that keeps
 *          junction curves on junctions and bounds how far any vertex moves.
 *
 * Removes the staircase of amLabelSurface without moving interfaces off the label boundaries.
 * Each iteration is a pair of umbrella (uniform Laplacian) steps, +lambda then mu < 0, with
 * lambda = 0.5 and 1/lambda + 1/mu = PassBand (Taubin 1995, "A signal processing approach to fair
 * surface design"): low frequencies (the anatomy) pass, the voxel-scale staircase is removed, and
 * the surface does not shrink as plain Laplacian smoothing does. The pair is a discrete
 * bilaplacian filter.
 *
 * Feature edges are edges with other than two triangles (junction curves where three or more
 * regions meet, open borders) or whose two triangles carry different "Labels" pairs. A vertex on
 * exactly two feature edges moves only along its curve (1-D smoothing with its two curve
 * neighbours); a vertex on one or three or more (a curve end, where junction curves meet) does not
 * move. So junction curves stay shared and stay junctions. A closed junction curve of fewer than
 * 12 vertices (a loop around a voxel corner where three regions meet in a saddle) does not move
 * either: smoothed along itself it would shrink to a point, leaving edges of micrometres that no
 * remeshing can remove.
 *
 * After every step each vertex is pulled back into the ball of radius MaximumDisplacement around
 * its input position, so the surface stays within that distance of the voxel boundary it came
 * from. The default (-1) is half the diagonal of the voxel whose size amLabelSurface records in
 * field data "VoxelSize" (sqrt(3)/2 voxel: a corner vertex stays in the ball around the 2x2x2
 * voxel block it stands for; unbounded when the field data is absent); 0 means unbounded.
 * On a voxelised sphere of radius 20 voxels the defaults bring the largest distance to the true
 * sphere from 0.84 to 0.41 voxel and the mean from 0.38 to 0.08 voxel.
 *
 * A step that would flip a triangle is refused. Finally, with PreventSelfIntersections (default
 * on), the vertices of triangles that cross any other triangle of the surface (of the same region
 * or of another: two interfaces a voxel apart can be smoothed into each other) are put back at
 * their input positions until nothing crosses (the input, a voxel surface, has no crossing), so
 * TetGen accepts the result.
 *
 * Output: the same triangles and cell data, new point positions, point data "Displacement" (mm)
 * and "FeatureVertex" (0 surface, 1 on a feature curve, 2 fixed corner).
 */
#ifndef amSurfaceSmoothing_h
#define amSurfaceSmoothing_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class ANATOMESHFILTERSSURFACE_EXPORT amSurfaceSmoothing : public vtkPolyDataAlgorithm
{
public:
  static amSurfaceSmoothing* New();
  vtkTypeMacro(amSurfaceSmoothing, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of lambda|mu iteration pairs (default 20).
  vtkSetClampMacro(NumberOfIterations, int, 0, 100000);
  vtkGetMacro(NumberOfIterations, int);
  ///@}

  ///@{
  /// Taubin pass band k_PB = 1/lambda + 1/mu (default 0.1; smaller removes more).
  vtkSetClampMacro(PassBand, double, 0.001, 1.9);
  vtkGetMacro(PassBand, double);
  ///@}

  ///@{
  /// Bound on each vertex's displacement in mm (default -1: sqrt(3)/2 of the "VoxelSize" field
  /// data; 0: unbounded).
  vtkSetMacro(MaximumDisplacement, double);
  vtkGetMacro(MaximumDisplacement, double);
  ///@}

  ///@{
  /// Keep feature curves (junctions, borders, label changes) as curves (default on).
  vtkSetMacro(PreserveFeatures, bool);
  vtkGetMacro(PreserveFeatures, bool);
  vtkBooleanMacro(PreserveFeatures, bool);
  ///@}

  ///@{
  /// After smoothing, put the vertices of crossing triangles (CGAL's exact test, per region)
  /// back at their input positions until no region's boundary crosses itself (default on).
  vtkSetMacro(PreventSelfIntersections, bool);
  vtkGetMacro(PreventSelfIntersections, bool);
  vtkBooleanMacro(PreventSelfIntersections, bool);
  ///@}

  /// Vertex moves made by the untangling of the last run.
  vtkGetMacro(UntangledVertices, vtkIdType);

  /// The displacement bound used by the last run, mm (0: unbounded).
  vtkGetMacro(UsedMaximumDisplacement, double);

protected:
  amSurfaceSmoothing();
  ~amSurfaceSmoothing() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfIterations;
  double PassBand;
  double MaximumDisplacement;
  bool PreserveFeatures;
  bool PreventSelfIntersections;
  double UsedMaximumDisplacement;
  vtkIdType UntangledVertices;

private:
  amSurfaceSmoothing(const amSurfaceSmoothing&) = delete;
  void operator=(const amSurfaceSmoothing&) = delete;
};

#endif
