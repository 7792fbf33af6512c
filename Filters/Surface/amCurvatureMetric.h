/**
 * @class   amCurvatureMetric
 * @brief   Principal curvatures and directions per vertex, and an anisotropic size metric for a
 *          surface-deviation tolerance, with gradation control.
 *
 * Curvatures: at each vertex a height function h(u,v) = a u^2 + b uv + c v^2 + d u + e v is fitted
 * by least squares to the vertices of its NeighbourhoodRings-ring, in the tangent frame of the
 * area-weighted normal; the shape operator of that graph (first and second fundamental forms, so
 * a tilted normal does not bias it) gives the principal curvatures k1 >= k2 and their directions.
 * The linear terms and the 2-ring make it robust on the noisy, staircase-smoothed triangulations
 * of label maps. On a multi-material surface the fit uses only the triangles of one interface
 * (one label pair); a vertex on a junction curve takes the fit of the interface it belongs to
 * that bends most.
 *
 * Metric: the chord of an arc of radius 1/|k| and length h deviates from it by h^2 |k| / 8, so
 * the size along principal direction i is h_i = sqrt(8 Tolerance / |k_i|), clamped to
 * [MinimumSize, MaximumSize]; in the normal direction the size is the smaller of the two. The
 * metric tensor is M = R diag(1/h1^2, 1/h2^2, 1/hn^2) R^T (unit length = the wanted edge). With
 * Anisotropic off, both tangent sizes are the smaller one.
 * Gradation: sizes may grow by at most a factor Gradation over a distance equal to the size,
 * h_j <= h_i + (Gradation - 1) |x_j - x_i| for every pair of neighbours (an exact shortest-path
 * propagation of the smallest size; each principal size is capped by it).
 *
 * Output point data: "Metric" (6 components, VTK symmetric order XX YY ZZ XY YZ XZ), "Size"
 * (smallest size after gradation), "MaximumCurvature", "MinimumCurvature", "MeanCurvature",
 * "GaussianCurvature" (1/mm, signed with the input orientation: positive where the surface bends
 * away from its normal, e.g. on an outward-oriented sphere), "MaximumDirection",
 * "MinimumDirection", "Normals".
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
  /// Rings of neighbours used by the fit (default 2).
  vtkSetClampMacro(NeighbourhoodRings, int, 1, 5);
  vtkGetMacro(NeighbourhoodRings, int);
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
  int NeighbourhoodRings;

private:
  amCurvatureMetric(const amCurvatureMetric&) = delete;
  void operator=(const amCurvatureMetric&) = delete;
};

#endif
