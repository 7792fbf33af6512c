/**
 * @class   amSurfaceDistance
 * @brief   Two-sided Hausdorff and mean distances between two triangle surfaces.
 *
 * Input 0 is surface A, input 1 surface B. Every vertex of each surface, and a barycentric grid
 * of points on each of its triangles with spacing at most SamplingDistance (mm), is projected
 * onto the other surface (exact closest point on its triangles, amTriangleLocator). The
 * largest of these distances, A to B and B to A, is the Hausdorff distance as sampled; since the
 * distance to a surface is 1-Lipschitz, the true Hausdorff distance is at most that plus the
 * largest distance from a surface point to its nearest sample (sub-triangle longest edge / sqrt 3),
 * reported as HausdorffUpperBound. SamplingDistance 0 (default) samples vertices, edge midpoints
 * and centroids only.
 *
 * Output: a copy of A with point data "Distance" (each vertex's distance to B, mm) and field data
 * "Hausdorff", "HausdorffUpperBound", "MaximumAToB", "MaximumBToA", "MeanAToB", "MeanBToA"
 * (area-weighted sample means).
 */
#ifndef amSurfaceDistance_h
#define amSurfaceDistance_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class ANATOMESHFILTERSSURFACE_EXPORT amSurfaceDistance : public vtkPolyDataAlgorithm
{
public:
  static amSurfaceDistance* New();
  vtkTypeMacro(amSurfaceDistance, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Surface B (input port 1).
  void SetTargetConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetTargetData(vtkDataObject* data) { this->SetInputData(1, data); }

  ///@{
  /// Largest spacing of the sample points on each triangle, mm (default 0: vertices, edge
  /// midpoints and centroids).
  vtkSetClampMacro(SamplingDistance, double, 0.0, 1e9);
  vtkGetMacro(SamplingDistance, double);
  ///@}

  ///@{
  /// Results of the last run (mm).
  vtkGetMacro(Hausdorff, double);
  vtkGetMacro(HausdorffUpperBound, double);
  vtkGetMacro(MaximumAToB, double);
  vtkGetMacro(MaximumBToA, double);
  vtkGetMacro(MeanAToB, double);
  vtkGetMacro(MeanBToA, double);
  ///@}

protected:
  amSurfaceDistance();
  ~amSurfaceDistance() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double SamplingDistance;
  double Hausdorff, HausdorffUpperBound, MaximumAToB, MaximumBToA, MeanAToB, MeanBToA;

private:
  amSurfaceDistance(const amSurfaceDistance&) = delete;
  void operator=(const amSurfaceDistance&) = delete;
};

#endif
