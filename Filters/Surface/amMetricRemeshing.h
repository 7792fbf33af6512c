/**
 * @class   amMetricRemeshing
 * @brief   Remeshes a (multi-material) triangle surface to unit edge length in a size metric,
 *          keeping junction curves and labels, within a two-sided Hausdorff bound of the input.
 *
 * The CEMRACS paper's "Yams" stage. Sizes come from the point-data tensor "Metric"
 * (amCurvatureMetric; the length of an edge e is sqrt(e^T M e), averaged over its two ends) or,
 * when TargetSize > 0, from a uniform edge length in mm. Each iteration:
 * 1. collapses the edges shorter than 4/5, shortest first (into either end, or into the input
 *    point nearest the edge's middle); a junction-curve vertex moves only along its curve,
 *    corners never;
 * 2. flips edges inside an interface where that raises the smaller minimum angle;
 * 3. relaxes surface vertices towards the centroid of their ring, back onto the input.
 * Every operation first passes the guards and changes nothing when refused: the link condition
 * (every region stays a manifold), no flipped triangle, no new angle under 10 degrees, no edge
 * longer than 4/3, every new triangle within Tolerance of its interface's input (on the side it
 * faces), every input vertex within Tolerance of the triangles of the vertex that stands for it,
 * and no new triangle crossing or folding onto a live one (CGAL's exact predicates). The output
 * is therefore as free of self-intersections as the input, which a tetrahedral mesher needs.
 *
 * With PreserveVolumes (on by default), each region then gets back the volume it has in the input:
 * the vertices inside each interface move along their normals by one offset per interface, the
 * smallest that restores every region's volume to first order (label 0, the outside, takes up the
 * rest), under the same guards, three rounds. Then the two-sided Hausdorff distance to the input is
 * measured per interface (amSurfaceDistance's sampling), and wherever it exceeds Tolerance the
 * offending triangle is bisected towards the input (a junction edge at the input curve vertex
 * halfway along the curve), or the far point inserted; an insertion refused because something is
 * in the way refines that instead, up to 30 rounds. Last, triangles with an angle under 10 degrees
 * that the insertions left are flipped or collapsed away under the same guards, kept only if the
 * bound and the angles end no worse. Where the bound is still missed, the input's own triangles are
 * kept there: the remeshing runs again with the input vertices near the far triangles (within a
 * far triangle's longest edge and the tolerance of its corners) held, so that no operation moves
 * or removes them or changes a triangle of three of them (those stay the input's own); each run
 * holds the far triangles' vertices of every run before it and rounds each interface's volume
 * offset to a fiftieth of the tolerance (so that the runs move the rest of the surface alike), up
 * to eight times, until a run keeps the bound (taken; InputVerticesKept counts the vertices held)
 * — else the closest run is taken and the warning says so.
 *
 * The achieved distance is in field data "Hausdorff" (and "HausdorffUpperBound", with the
 * sampling gap); per triangle in cell data "HausdorffDistance" (the largest distance measured on
 * it: its samples to the input and the input samples nearest to it, mm); per interface in field
 * data "InterfaceHausdorff" (lower label, higher label, largest distance; with "Labels"). A
 * warning names the interfaces where the bound could not be reached (two interfaces meeting at a
 * small angle, a part thinner than the tolerance) with their achieved distance.
 *
 * The passes run on two workers, one on each side of a plane through the median vertex; the
 * output does not depend on the thread count. The algorithm lives in Remeshing/ (amRemesher and
 * its parts), this filter converts and calls it.
 *
 * References: P. J. Frey, YAMS: a fully automatic adaptive isotropic surface remeshing procedure,
 * INRIA RT-0252, 2001; P. J. Frey and H. Borouchaki, Geometric surface mesh optimization,
 * Computing and Visualization in Science 1, 1998; the CEMRACS 2004 paper (Generation of
 * computational meshes from MRI and CT-scan data).
 *
 * @sa amCurvatureMetric amSurfaceDistance amTetrahedralize
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
  /// Give each region the volume it has in the input (default on): before the bound is
  /// enforced, the vertices of each interface move along their normals by one offset per
  /// interface (the smallest that restores every region's volume, junction curves kept, within
  /// the tolerance and without crossings or passing through another part of the surface). A
  /// coarser triangulation of a convex part lies inside it: without this, a thin part (a rib)
  /// loses several per cent of its volume. Off keeps the surface the remeshing left (a few
  /// seconds less).
  vtkSetMacro(PreserveVolumes, vtkTypeBool);
  vtkGetMacro(PreserveVolumes, vtkTypeBool);
  vtkBooleanMacro(PreserveVolumes, vtkTypeBool);
  ///@}

  ///@{
  /// Results of the last run.
  vtkGetMacro(Hausdorff, double);
  vtkGetMacro(HausdorffUpperBound, double);
  vtkGetMacro(InsertedPoints, vtkIdType);
  /// Interfaces (label pairs) whose largest distance is above Tolerance.
  vtkGetMacro(InterfacesAboveTolerance, int);
  /// Input vertices whose triangles were kept where the remeshing could not keep the bound.
  vtkGetMacro(InputVerticesKept, vtkIdType);
  ///@}

protected:
  amMetricRemeshing();
  ~amMetricRemeshing() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Tolerance;
  double TargetSize;
  int NumberOfIterations;
  vtkTypeBool PreserveVolumes;
  double Hausdorff;
  double HausdorffUpperBound;
  vtkIdType InsertedPoints;
  int InterfacesAboveTolerance;
  vtkIdType InputVerticesKept;

private:
  amMetricRemeshing(const amMetricRemeshing&) = delete;
  void operator=(const amMetricRemeshing&) = delete;
};

#endif
