#include "amLandmarkPoints.h"

#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

bool amLandmarkPoints::Named(
  vtkPolyData* landmarks, const std::vector<std::string>& names, std::vector<double>& xyz, std::string& why)
{
  auto* labels = vtkStringArray::SafeDownCast(landmarks->GetPointData()->GetAbstractArray("Name"));
  if (!labels || labels->GetNumberOfValues() != landmarks->GetNumberOfPoints())
  {
    why = "the landmarks have no point data \"Name\" (amCardiacLandmarks' output has)";
    return false;
  }
  xyz.clear();
  for (const auto& name : names)
  {
    const vtkIdType i = labels->LookupValue(name);
    if (i < 0)
    {
      why = "the landmarks have no point named " + name;
      return false;
    }
    double x[3];
    landmarks->GetPoint(i, x);
    xyz.insert(xyz.end(), x, x + 3);
  }
  return true;
}
