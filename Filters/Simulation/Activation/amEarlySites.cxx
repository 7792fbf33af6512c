#include "amEarlySites.h"

#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>

namespace
{
// The nodes of 'from' nearest 'to' (the given fraction of them) within the apico-basal band.
std::vector<vtkIdType> Facing(const std::vector<std::array<double, 3>>& points, const std::vector<vtkIdType>& from,
  const std::vector<vtkIdType>& to, const std::vector<double>& apicoBasal, double fraction, double lowest,
  double highest)
{
  if (from.empty() || to.empty())
    return {};
  vtkNew<vtkPoints> targets;
  targets->SetDataTypeToDouble();
  for (vtkIdType v : to)
    targets->InsertNextPoint(points[v].data());
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(targets);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  std::vector<std::pair<double, vtkIdType>> distance;
  for (vtkIdType v : from)
  {
    const vtkIdType nearest = locator->FindClosestPoint(points[v].data());
    double x[3];
    targets->GetPoint(nearest, x);
    const double d2 = (x[0] - points[v][0]) * (x[0] - points[v][0]) + (x[1] - points[v][1]) * (x[1] - points[v][1]) +
      (x[2] - points[v][2]) * (x[2] - points[v][2]);
    distance.push_back({ d2, v });
  }
  std::sort(distance.begin(), distance.end());
  const std::size_t keep = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(fraction * distance.size())));
  std::vector<vtkIdType> out;
  for (std::size_t k = 0; k < keep && k < distance.size(); ++k)
  {
    const double h = apicoBasal[distance[k].second];
    if (h >= lowest && h <= highest)
      out.push_back(distance[k].second);
  }
  std::sort(out.begin(), out.end());
  return out;
}
}

std::vector<std::pair<vtkIdType, double>> amEarlySites::Find(const std::vector<std::array<double, 3>>& points,
  const std::vector<vtkIdType>& lv, const std::vector<vtkIdType>& rv, const std::vector<double>& apicoBasal) const
{
  std::vector<std::pair<vtkIdType, double>> sites;
  for (vtkIdType v : Facing(points, lv, rv, apicoBasal, this->SeptalFraction, this->Lowest, this->Highest))
    sites.push_back({ v, 0.0 });
  for (vtkIdType v : Facing(points, rv, lv, apicoBasal, this->SeptalFraction, this->Lowest, this->Highest))
    sites.push_back({ v, this->RightDelay });
  return sites;
}
