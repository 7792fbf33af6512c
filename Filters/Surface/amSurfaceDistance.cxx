#include "amSurfaceDistance.h"

#include "amProvenance.h"
#include "amSurfaceMesh.h"
#include "amThreading.h"
#include "amTriangleLocator.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(amSurfaceDistance);

namespace
{
struct OneSided
{
  double Maximum = 0, Mean = 0, Gap = 0;
};

/// Distances from samples of 'from' to surface 'to' (its locator). vertexDistance gets each
/// vertex's distance when non-null.
OneSided Measure(
  const amSurfaceMesh& from, const amTriangleLocator& locator, double sampling, std::vector<double>* vertexDistance)
{
  const vtkIdType nt = from.NumberOfTriangles(), np = from.NumberOfPoints();
  auto distance = [&](const double x[3]) {
    double closest[3];
    vtkIdType t;
    return std::sqrt(locator.ClosestPoint(x, closest, t));
  };
  std::vector<double> vd(static_cast<size_t>(np));
  vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
      vd[v] = distance(from.Points[v].data());
  });
  // Per triangle: the largest sample distance, the area-weighted mean, and the sampling gap.
  std::vector<double> triMax(static_cast<size_t>(nt)), triSum(static_cast<size_t>(nt)),
    triArea(static_cast<size_t>(nt)), triGap(static_cast<size_t>(nt));
  vtkSMPTools::For(0, nt, [&](vtkIdType t0, vtkIdType t1) {
    for (vtkIdType t = t0; t < t1; ++t)
    {
      const auto& tri = from.Triangles[t];
      const auto &a = from.Points[tri[0]], &b = from.Points[tri[1]], &c = from.Points[tri[2]];
      double longest = 0;
      for (int k = 0; k < 3; ++k)
      {
        const auto &p = from.Points[tri[k]], &q = from.Points[tri[(k + 1) % 3]];
        longest = std::max(longest,
          std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2])));
      }
      const int n = sampling > 0 ? std::max(2, static_cast<int>(std::ceil(longest / sampling))) : 2;
      double mx = std::max({ vd[tri[0]], vd[tri[1]], vd[tri[2]] }), sum = 0;
      int count = 0;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
        {
          const double u = static_cast<double>(i) / n, w = static_cast<double>(j) / n, s = 1 - u - w;
          double x[3];
          for (int d = 0; d < 3; ++d)
            x[d] = s * a[d] + u * b[d] + w * c[d];
          double dist;
          if (i == 0 && j == 0)
            dist = vd[tri[0]];
          else if (i == n)
            dist = vd[tri[1]];
          else if (j == n)
            dist = vd[tri[2]];
          else
            dist = distance(x);
          mx = std::max(mx, dist);
          sum += dist;
          ++count;
        }
      // Centroid too (the grid for n = 2 does not contain it).
      if (n == 2)
      {
        double x[3];
        for (int d = 0; d < 3; ++d)
          x[d] = (a[d] + b[d] + c[d]) / 3.0;
        const double dist = distance(x);
        mx = std::max(mx, dist);
        sum += dist;
        ++count;
      }
      const auto nrm = from.TriangleNormal(t);
      triArea[t] = 0.5 * std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
      triMax[t] = mx;
      triSum[t] = sum / count;
      triGap[t] = longest / n / std::sqrt(3.0);
    }
  });
  OneSided r;
  double area = 0;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    r.Maximum = std::max(r.Maximum, triMax[t]);
    r.Gap = std::max(r.Gap, triGap[t]);
    r.Mean += triSum[t] * triArea[t];
    area += triArea[t];
  }
  r.Mean = area > 0 ? r.Mean / area : 0.0;
  if (vertexDistance)
    vertexDistance->swap(vd);
  return r;
}
}

amSurfaceDistance::amSurfaceDistance()
  : SamplingDistance(0.0)
  , Hausdorff(0)
  , HausdorffUpperBound(0)
  , MaximumAToB(0)
  , MaximumBToA(0)
  , MeanAToB(0)
  , MeanBToA(0)
{
  amThreading::Initialize();
  this->SetNumberOfInputPorts(2);
}

amSurfaceDistance::~amSurfaceDistance() = default;

int amSurfaceDistance::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int amSurfaceDistance::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* a = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* b = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!b)
  {
    vtkErrorMacro("No target surface (input port 1) is connected.");
    return 0;
  }
  amSurfaceMesh ma, mb;
  std::string why;
  if (!ma.Build(a, why))
  {
    vtkErrorMacro("Surface A: " << why);
    return 0;
  }
  if (!mb.Build(b, why))
  {
    vtkErrorMacro("Surface B: " << why);
    return 0;
  }
  amTriangleLocator la, lb;
  la.Build(ma.Points, ma.Triangles);
  lb.Build(mb.Points, mb.Triangles);
  this->UpdateProgress(0.1);
  std::vector<double> vd;
  const OneSided ab = Measure(ma, lb, this->SamplingDistance, &vd);
  this->UpdateProgress(0.55);
  const OneSided ba = Measure(mb, la, this->SamplingDistance, nullptr);
  this->MaximumAToB = ab.Maximum;
  this->MaximumBToA = ba.Maximum;
  this->MeanAToB = ab.Mean;
  this->MeanBToA = ba.Mean;
  this->Hausdorff = std::max(ab.Maximum, ba.Maximum);
  this->HausdorffUpperBound = std::max(ab.Maximum + ab.Gap, ba.Maximum + ba.Gap);

  output->ShallowCopy(a);
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("Distance");
  distance->SetNumberOfTuples(ma.NumberOfPoints());
  std::copy(vd.begin(), vd.end(), distance->GetPointer(0));
  output->GetPointData()->AddArray(distance);
  const std::pair<const char*, double> fields[] = { { "Hausdorff", this->Hausdorff },
    { "HausdorffUpperBound", this->HausdorffUpperBound }, { "MaximumAToB", this->MaximumAToB },
    { "MaximumBToA", this->MaximumBToA }, { "MeanAToB", this->MeanAToB }, { "MeanBToA", this->MeanBToA } };
  for (const auto& f : fields)
  {
    vtkNew<vtkDoubleArray> arr;
    arr->SetName(f.first);
    arr->InsertNextValue(f.second);
    output->GetFieldData()->AddArray(arr);
  }
  std::ostringstream params;
  params << "SamplingDistance=" << this->SamplingDistance << " Hausdorff=" << this->Hausdorff;
  amProvenance::Record(output, a, "amSurfaceDistance", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amSurfaceDistance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplingDistance: " << this->SamplingDistance << "\n";
}
