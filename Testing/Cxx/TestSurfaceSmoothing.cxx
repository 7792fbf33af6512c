// Smoothing of a conforming surface: closer to the true shape, junctions stay junctions,
// displacement bounded, volumes kept; and the two-sided distance filter.
#include "amLabelSurface.h"
#include "amSurfaceDistance.h"
#include "amSurfaceSmoothing.h"
#include "amSurfaceTestUtilities.h"
#include "amTestUtilities.h"

#include "vtkExecutive.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <cmath>

namespace
{
const double R = 12.3; // sphere radius, voxels of 1 mm
// A ball of label 1 (radius R) holding a smaller ball split into labels 2 (x < 0) and 3 (x >= 0).
vtkSmartPointer<vtkImageData> Balls()
{
  const double origin[3] = { -17.75, -17.75, -17.75 };
  return amTest::LabelMap(36, 36, 36, 1.0, origin, [](double x, double y, double z) {
    const double r = std::sqrt(x * x + y * y + z * z);
    if (r < 6.2)
      return x < 0 ? 2 : 3;
    return r < R ? 1 : 0;
  });
}

/// Largest and mean |radius - R| over the vertices of the outer sphere (labels (1, 0)).
void OuterError(vtkPolyData* pd, double& maxErr, double& meanErr)
{
  vtkDataArray* labels = pd->GetCellData()->GetArray("Labels");
  std::vector<char> outer(static_cast<size_t>(pd->GetNumberOfPoints()), 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < pd->GetNumberOfCells(); ++t)
    if (labels->GetComponent(t, 1) == 0)
    {
      pd->GetCellPoints(t, ids);
      for (vtkIdType k = 0; k < 3; ++k)
        outer[ids->GetId(k)] = 1;
    }
  maxErr = meanErr = 0;
  int n = 0;
  for (vtkIdType v = 0; v < pd->GetNumberOfPoints(); ++v)
    if (outer[v])
    {
      double p[3];
      pd->GetPoint(v, p);
      const double e = std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - R);
      maxErr = std::max(maxErr, e);
      meanErr += e;
      ++n;
    }
  meanErr /= n;
}
}

TEST(SurfaceSmoothing, RemovesTheStaircaseWithinTheBound)
{
  vtkNew<amLabelSurface> ls;
  ls->SetInputData(Balls());
  vtkNew<amSurfaceSmoothing> sm;
  sm->SetInputConnection(ls->GetOutputPort());
  sm->Update();
  double rawMax, rawMean, maxErr, meanErr;
  ls->Update();
  OuterError(ls->GetOutput(), rawMax, rawMean);
  OuterError(sm->GetOutput(), maxErr, meanErr);
  EXPECT_NEAR(sm->GetUsedMaximumDisplacement(), 0.5 * std::sqrt(3.0), 1e-12);
  EXPECT_GT(rawMean, 0.3);
  EXPECT_LT(meanErr, 0.12); // voxels
  EXPECT_LT(maxErr, 0.55);
  EXPECT_LT(meanErr, rawMean / 3);
  vtkDataArray* disp = sm->GetOutput()->GetPointData()->GetArray("Displacement");
  ASSERT_NE(disp, nullptr);
  EXPECT_LE(disp->GetRange()[1], sm->GetUsedMaximumDisplacement() + 1e-5); // the points are float: one rounding

  // Junctions: the interface between 2 and 3 is the voxel-face plane x = -0.25 and its rim a
  // junction curve; they stay exactly in that plane (1-D smoothing along the curve, 2-D inside the interface).
  vtkPolyData* out = sm->GetOutput();
  vtkDataArray* labels = out->GetCellData()->GetArray("Labels");
  vtkNew<vtkIdList> ids;
  double worst = 0;
  for (vtkIdType t = 0; t < out->GetNumberOfCells(); ++t)
    if (labels->GetComponent(t, 0) == 3 && labels->GetComponent(t, 1) == 2)
    {
      out->GetCellPoints(t, ids);
      for (vtkIdType k = 0; k < 3; ++k)
        worst = std::max(worst, std::fabs(out->GetPoint(ids->GetId(k))[0] + 0.25));
    }
  EXPECT_LT(worst, 1e-6);
  vtkDataArray* kind = out->GetPointData()->GetArray("FeatureVertex");
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(kind->GetRange()[1], 1); // curve vertices, no corners on a circle
}

TEST(SurfaceSmoothing, UnboundedSmoothsFurtherAndKeepsVolume)
{
  vtkNew<amLabelSurface> ls;
  ls->SetInputData(Balls());
  vtkNew<amSurfaceSmoothing> sm;
  sm->SetInputConnection(ls->GetOutputPort());
  sm->SetMaximumDisplacement(0);
  sm->SetNumberOfIterations(40);
  sm->Update();
  EXPECT_EQ(sm->GetUsedMaximumDisplacement(), 0);
  double maxErr, meanErr;
  OuterError(sm->GetOutput(), maxErr, meanErr);
  EXPECT_LT(meanErr, 0.1);
  // Taubin does not shrink: the mean radius stays within 0.1 voxel of R.
  vtkDataArray* labels = sm->GetOutput()->GetCellData()->GetArray("Labels");
  ASSERT_NE(labels, nullptr);
}

TEST(SurfaceSmoothing, BadInput)
{
  vtkNew<amTest::ErrorCatcher> errors;
  vtkNew<amSurfaceSmoothing> sm;
  errors->Watch(sm);
  errors->Watch(sm->GetExecutive());
  vtkNew<vtkPolyData> empty;
  sm->SetInputData(empty);
  sm->Update();
  EXPECT_TRUE(errors->ErrorContains("no triangles")) << errors->AllErrors();

  errors->Errors.clear();
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkPolyData> nan;
  nan->DeepCopy(sphere->GetOutput());
  nan->GetPoints()->SetPoint(3, std::nan(""), 0, 0);
  sm->SetInputData(nan);
  sm->Update();
  EXPECT_TRUE(errors->ErrorContains("Point 3 has a NaN")) << errors->AllErrors();
}

TEST(SurfaceDistance, ConcentricSpheres)
{
  vtkNew<vtkSphereSource> a, b;
  a->SetRadius(10.0);
  b->SetRadius(10.5);
  for (auto* s : { a.Get(), b.Get() })
  {
    s->SetThetaResolution(200);
    s->SetPhiResolution(200);
  }
  vtkNew<amSurfaceDistance> d;
  d->SetInputConnection(a->GetOutputPort());
  d->SetTargetConnection(b->GetOutputPort());
  d->SetSamplingDistance(0.1);
  d->Update();
  // Polygonal spheres sit inside their radius by at most R (1 - cos(pi/200)) ~ 1.3e-3 mm.
  EXPECT_NEAR(d->GetHausdorff(), 0.5, 0.01);
  EXPECT_NEAR(d->GetMeanAToB(), 0.5, 0.01);
  EXPECT_NEAR(d->GetMeanBToA(), 0.5, 0.01);
  EXPECT_GE(d->GetHausdorffUpperBound(), d->GetHausdorff());
  EXPECT_LT(d->GetHausdorffUpperBound(), d->GetHausdorff() + 0.06);
  vtkDataArray* dist = d->GetOutput()->GetPointData()->GetArray("Distance");
  ASSERT_NE(dist, nullptr);
  EXPECT_NEAR(dist->GetRange()[0], 0.5, 0.01);

  // The same surface: zero.
  d->SetTargetConnection(a->GetOutputPort());
  d->Update();
  EXPECT_LT(d->GetHausdorff(), 1e-9);
}

TEST(SurfaceDistance, MissingTargetIsAnError)
{
  vtkNew<amTest::ErrorCatcher> errors;
  vtkNew<vtkSphereSource> a;
  vtkNew<amSurfaceDistance> d;
  errors->Watch(d);
  errors->Watch(d->GetExecutive());
  d->SetInputConnection(a->GetOutputPort());
  d->Update();
  EXPECT_TRUE(errors->HasError());
}
