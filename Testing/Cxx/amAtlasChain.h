// The surface -> TetGen chain on a synthetic atlas, as the atlas tests and BenchmarkAtlas run it:
// label surface, smoothing, isotropic curvature metric and remeshing at one tolerance, TetGen.
#ifndef amAtlasChain_h
#define amAtlasChain_h

#include "amCurvatureMetric.h"
#include "amLabelSurface.h"
#include "amMetricRemeshing.h"
#include "amSurfaceSmoothing.h"
#include "amSyntheticAtlasSource.h"
#include "amTetrahedralize.h"

#include "vtkDataArray.h"
#include "vtkNew.h"

#include <set>

namespace amTest
{
struct AtlasChain
{
  vtkNew<amSyntheticAtlasSource> Source;
  vtkNew<amLabelSurface> Surface;
  vtkNew<amSurfaceSmoothing> Smooth;
  vtkNew<amCurvatureMetric> Metric;
  vtkNew<amMetricRemeshing> Remesh;
  vtkNew<amTetrahedralize> Tetra;
  /// An atlas of 'labels' cells and the given geometry, sheets (mm) and noise, meshed at tolerance eps.
  AtlasChain(
    int labels, int seed, const int dims[3], const double spacing[3], double sheetWidth, double noise, double eps)
  {
    this->Source->SetNumberOfLabels(labels);
    this->Source->SetSeed(seed);
    this->Source->SetDimensions(dims[0], dims[1], dims[2]);
    this->Source->SetSpacing(spacing[0], spacing[1], spacing[2]);
    this->Source->SetSheetWidth(sheetWidth);
    this->Source->SetNoiseFraction(noise);
    this->Surface->SetInputConnection(this->Source->GetOutputPort());
    this->Surface->SetComputeTopology(false);
    this->Smooth->SetInputConnection(this->Surface->GetOutputPort());
    this->Metric->SetInputConnection(this->Smooth->GetOutputPort());
    this->Metric->SetTolerance(eps);
    this->Metric->SetMinimumSize(1.0);
    this->Metric->SetAnisotropic(false);
    this->Remesh->SetInputConnection(this->Metric->GetOutputPort());
    this->Remesh->SetTolerance(eps);
    this->Remesh->SetPreserveVolumes(true);
    this->Tetra->SetInputConnection(this->Remesh->GetOutputPort());
  }
};

/// The distinct values of an array, over all its components.
inline std::set<int> DistinctValues(vtkDataArray* a)
{
  std::set<int> s;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      s.insert(static_cast<int>(a->GetComponent(i, c)));
  return s;
}
}

#endif
