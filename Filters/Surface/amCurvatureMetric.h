/**
 * @class   amCurvatureMetric
 * @brief   Principal curvatures and directions per vertex, and an anisotropic size metric for a
 *          surface-deviation tolerance, with gradation control.
 *
 * Curvatures: at each vertex a height function h(u,v) = a u^2 + b uv + c v^2 + d u + e v is fitted
 * by least squares to the vertices of its NeighborhoodRings-ring and every vertex within
 * NeighborhoodRadius, in the tangent frame of the area-weighted normal; the shape operator of that graph (first and
 * second fundamental forms, so a tilted normal does not bias it) gives the principal curvatures k1 >= k2 and their
 * directions. The linear terms and the neighbourhood radius (two voxels by default) make it robust on the noisy,
 * staircase-smoothed triangulations of label maps; ScaleAdaptive then fits again over half the size the first fit asks
 * for, so that the curvature is the surface's at the scale of the triangles (a smoothed voxelised sphere of radius 20
 * voxels: the median of max |k| is 1.8x the truth with the two-voxel fit alone, 1.2x after the scale-adaptive fits). On
 * a multi-material surface the fit uses only the triangles of one interface (one label pair); a vertex on a junction
 * curve takes the fit of the interface it belongs to that bends most.
 *
 * Metric: the chord of an arc of radius 1/|k| and length h deviates from it by h^2 |k| / 8, but
 * the centre of an equilateral triangle of edge h with its corners on a sphere of curvature |k|
 * deviates by h^2 |k| / 6 (its circumradius is h / sqrt(3)); a triangle, not only its edges, must
 * stay within the tolerance, so the size along principal direction i is
 * h_i = sqrt(6 Tolerance / |k_i|), clamped to
 * [MinimumSize, MaximumSize]; in the normal direction the size is the smaller of the two. The
 * metric tensor is M = R diag(1/h1^2, 1/h2^2, 1/hn^2) R^T (unit length = the wanted edge). With
 * Anisotropic off, both tangent sizes are the smaller one.
 * Gradation: sizes may grow by at most a factor Gradation over a distance equal to the size,
 * h_j <= h_i + (Gradation - 1) |x_j - x_i| for every pair of neighbours (an exact shortest-path
 * propagation of the smaller principal size, and of the larger one; each principal size is capped
 * by the graded field of its kind, so the anisotropic metric stays anisotropic).
 *
 * Output point data: "Metric" (6 components, VTK symmetric order XX YY ZZ XY YZ XZ), "Size"
 * (smallest size after gradation), "MaximumCurvature", "MinimumCurvature", "MeanCurvature",
 * "GaussianCurvature" (1/mm, signed with the input orientation: positive where the surface bends
 * away from its normal, e.g. on an outward-oriented sphere), "MaximumDirection",
 * "MinimumDirection", "Normals".
 *
 * References: P. J. Frey, YAMS, INRIA RT-0252, 2001 (the geometric metric from curvatures and a
 * tolerance); the CEMRACS 2004 paper.
 *
 * @sa amMetricRemeshing amSurfaceSmoothing
 */
#ifndef amCurvatureMetric_h
#define amCurvatureMetric_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class ANATOMESHFILTERSSURFACE_EXPORT amCurvatureMetric : public vtkPolyDataAlgorithm
{
public:
  static amCurvatureMetric* New();
  vtkTypeMacro(amCurvatureMetric, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Surface-deviation tolerance epsilon, mm (default 0.2).
  vtkSetClampMacro(Tolerance, double, 1e-9, 1e9);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Size bounds, mm (defaults 0.5 and 20).
  vtkSetClampMacro(MinimumSize, double, 1e-9, 1e9);
  vtkGetMacro(MinimumSize, double);
  vtkSetClampMacro(MaximumSize, double, 1e-9, 1e9);
  vtkGetMacro(MaximumSize, double);
  ///@}

  ///@{
  /// Size growth bound per distance equal to the size (default 1.3; 0 or < 1: no gradation).
  vtkSetMacro(Gradation, double);
  vtkGetMacro(Gradation, double);
  ///@}

  ///@{
  /// Anisotropic metric (default on) or isotropic (the smaller principal size everywhere).
  vtkSetMacro(Anisotropic, bool);
  vtkGetMacro(Anisotropic, bool);
  vtkBooleanMacro(Anisotropic, bool);
  ///@}

  ///@{
  /// Rings of neighbours used by the fit at least (default 2).
  vtkSetClampMacro(NeighborhoodRings, int, 1, 5);
  vtkGetMacro(NeighborhoodRings, int);
  ///@}

  ///@{
  /// Radius of the fit's neighbourhood, mm: every vertex of the interface within it (reached
  /// through the interface) joins the fit. Default 0: twice the "VoxelSize" field data of a
  /// surface from a label map (amLabelSurface records it), else the rings alone.
  vtkSetClampMacro(NeighborhoodRadius, double, 0.0, 1e6);
  vtkGetMacro(NeighborhoodRadius, double);
#ifndef __VTK_WRAP__
  [[deprecated("use SetNeighborhoodRings")]] void SetNeighbourhoodRings(int n)
  {
    this->SetNeighborhoodRings(n);
  }
  [[deprecated("use GetNeighborhoodRings")]] int GetNeighbourhoodRings()
  {
    return this->GetNeighborhoodRings();
  }
  [[deprecated("use SetNeighborhoodRadius")]] void SetNeighbourhoodRadius(double r)
  {
    this->SetNeighborhoodRadius(r);
  }
  [[deprecated("use GetNeighborhoodRadius")]] double GetNeighbourhoodRadius()
  {
    return this->GetNeighborhoodRadius();
  }
#endif
  ///@}

  ///@{
  /// Fit a second time over half the smaller size the first fit gives (default on): the
  /// curvature at the scale of the triangles asked for, so ripples shorter than them (the
  /// staircase that smoothing leaves on a label-map surface) do not shrink the sizes.
  vtkSetMacro(ScaleAdaptive, bool);
  vtkGetMacro(ScaleAdaptive, bool);
  vtkBooleanMacro(ScaleAdaptive, bool);
  ///@}

protected:
  amCurvatureMetric();
  ~amCurvatureMetric() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Tolerance;
  double MinimumSize;
  double MaximumSize;
  double Gradation;
  bool Anisotropic;
  int NeighborhoodRings;
  double NeighborhoodRadius;
  bool ScaleAdaptive;

private:
  amCurvatureMetric(const amCurvatureMetric&) = delete;
  void operator=(const amCurvatureMetric&) = delete;
};

#endif
