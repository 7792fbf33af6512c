/**
 * @class   amMetricRemeshing
 * @brief   Remeshes a (multi-material) triangle surface to unit edge length in a size metric,
 *          keeping junction curves and labels, with a guaranteed two-sided Hausdorff bound.
 *
 * The paper's "Yams" stage. Sizes come from the point-data tensor "Metric" (amCurvatureMetric;
 * edge length in the metric: sqrt(e^T M e), averaged over the two ends) or, when absent or
 * TargetSize > 0, from a uniform TargetSize in mm. Each iteration:
 * 1. half-edge collapses of the edges shorter than 4/5, shortest first: a surface vertex
 *    collapses along a surface edge, a junction-curve vertex only along its curve, curve ends
 *    (corners) never; a collapse is refused when it would break the link condition (the surface
 *    of some region would become non-manifold), flip a triangle or give it an angle under 10
 *    degrees (on the exact organs at 1 mm, 5 degrees let caps through that no flip could mend
 *    later: the smallest dihedral of their tetrahedra fell to 7.6 degrees), make an edge
 *    longer than 4/3, or put a point of a new triangle (edge midpoints and quarter points,
 *    centroid) farther than Tolerance from the input surface of the same interface (its input
 *    triangles facing the same way), or leave an input vertex farther
 *    than Tolerance from the triangles of its interface around the vertex that stands for it
 *    (each input vertex is assigned to the vertex it collapsed into; flips and relaxation keep
 *    this too, so the input cannot drift away from the result between the distance checks);
 *    where neither end of an edge can take the other's triangles, the edge is collapsed into the
 *    input point nearest its middle (two surface vertices, not beside a junction curve). The
 *    collapse passes (and the flip and relaxation passes below) run on two workers, one on each
 *    side of a plane through the median vertex: a worker carries out an operation only where the
 *    stars it changes lie on its side, so neither reads what the other changes; the rest follow
 *    serially. The result does not depend on the threads;
 * 2. edge flips inside an interface that raise the smaller of the two triangles' minimum angles,
 *    between nearly coplanar triangles, under the same distance check;
 * 3. tangential relaxation of surface vertices towards the centroid of their ring, projected back
 *    onto the input surface of their interface (exact closest point among the input triangles
 *    facing the same way), under the same checks.
 * Every point put on the input (relaxation, bisection, insertion) is the closest point on the
 * side facing the way the remeshed triangles face: in a thin part (a fat layer a voxel thick) the
 * nearest input point can lie on the other side, and refining towards it crumpled the surface
 * into flat tetrahedra (2 mm phantom, ε 0.5: the bound then stalled at 0.72 mm; now met).
 * Junction curves therefore stay exactly on input vertices, and every triangle keeps its
 * "Labels" pair and orientation.
 *
 * No operation may make triangles cross: each collapse, flip, relaxation, insertion and split is
 * refused when one of its new triangles would meet a live triangle other than at their shared
 * vertices or edge (CGAL's exact predicates, on bins of the live triangles), or fold flat onto a
 * neighbour across an edge (dihedral under 1 degree). The output is therefore as free of
 * self-intersections as the input, which a tetrahedral mesher needs.
 *
 * Then the two-sided Hausdorff distance to the input is computed (amSurfaceDistance's sampling,
 * per interface: every input vertex, edge midpoint and centroid against the remeshed triangles of
 * its interface, and a grid of points on each remeshed triangle against the input), and wherever
 * it exceeds Tolerance the offending triangle (or the one nearest the offending input sample) is
 * bisected: its longest edge split at the point of the input nearest the edge's midpoint (a
 * junction edge at the input curve vertex halfway along the input curve), then flips around the
 * new vertex; where that is refused, a junction edge of the triangle is split instead. Where
 * that is refused too, the offending point itself is inserted (on an edge: that edge split
 * there, else inserted into the triangle); an insertion refused because it would cross something refines the triangles in the way
 * instead, up to 30 rounds. (Bisection keeps the angles; inserting the far points themselves left
 * slivers: 12 triangles under 8 degrees on the exact organs at 1 mm, 3 with bisection first.) The achieved value is stored in field data "Hausdorff" (and
 * "HausdorffUpperBound" with the sampling gap); a warning says so if the bound could not be
 * reached: where two interfaces meet at a small angle, the crossing-free rule can stop a few
 * insertions (2 mm phantom, eps 0.5 mm: 0.57 mm).
 *
 * Last, triangles with an angle under 10 degrees that the insertions left (caps along creases of
 * the input, needles) are flipped or collapsed away under the same checks as above, and the bound
 * is enforced again; the result is kept only if the distance ends no worse (or within Tolerance),
 * fewer such triangles remain and no edge became much shorter — otherwise the surface before the
 * cleanup is output. A tetrahedron standing on a triangle with a 3-degree angle cannot be good.
 */
#ifndef amMetricRemeshing_h
#define amMetricRemeshing_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class ANATOMESHFILTERSSURFACE_EXPORT amMetricRemeshing : public vtkPolyDataAlgorithm
{
public:
  static amMetricRemeshing* New();
  vtkTypeMacro(amMetricRemeshing, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Two-sided Hausdorff bound to the input, mm (default 0.2).
  vtkSetClampMacro(Tolerance, double, 1e-6, 1e6);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Uniform target edge length, mm (default 0: use the "Metric" point data).
  vtkSetClampMacro(TargetSize, double, 0.0, 1e6);
  vtkGetMacro(TargetSize, double);
  ///@}

  ///@{
  /// Collapse/flip/relax iterations (default 3).
  vtkSetClampMacro(NumberOfIterations, int, 1, 100);
  vtkGetMacro(NumberOfIterations, int);
  ///@}

  ///@{
  /// Results of the last run.
  vtkGetMacro(Hausdorff, double);
  vtkGetMacro(HausdorffUpperBound, double);
  vtkGetMacro(InsertedPoints, vtkIdType);
  ///@}

protected:
  amMetricRemeshing();
  ~amMetricRemeshing() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Tolerance;
  double TargetSize;
  int NumberOfIterations;
  double Hausdorff;
  double HausdorffUpperBound;
  vtkIdType InsertedPoints;

private:
  amMetricRemeshing(const amMetricRemeshing&) = delete;
  void operator=(const amMetricRemeshing&) = delete;
};

#endif
