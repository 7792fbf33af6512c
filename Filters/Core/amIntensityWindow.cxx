#include "amIntensityWindow.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"

#include <cmath>

namespace
{
const char* const Name = "IntensityWindow";
}

bool amIntensityWindow::Of(vtkDataObject* image, double window[2])
{
  vtkFieldData* fd = image ? image->GetFieldData() : nullptr;
  vtkDataArray* a = fd ? fd->GetArray(Name) : nullptr;
  if (!a || a->GetNumberOfTuples() < 1 || a->GetNumberOfComponents() != 2)
    return false;
  const double width = a->GetComponent(0, 0), level = a->GetComponent(0, 1);
  if (!std::isfinite(width) || !std::isfinite(level) || width <= 0.0)
    return false;
  window[0] = width;
  window[1] = level;
  return true;
}

void amIntensityWindow::Record(vtkDataObject* image, const double window[2])
{
  vtkFieldData* fd = image->GetFieldData();
  fd->RemoveArray(Name);
  if (!(window[0] > 0.0))
    return;
  vtkNew<vtkDoubleArray> a;
  a->SetName(Name);
  a->SetNumberOfComponents(2);
  a->SetComponentName(0, "Width");
  a->SetComponentName(1, "Level");
  a->InsertNextTuple2(window[0], window[1]);
  fd->AddArray(a);
}

double amIntensityWindow::Level(const double window[2], double hu)
{
  return (hu - (window[1] - 0.5 * window[0])) * 255.0 / window[0];
}

double amIntensityWindow::Width(const double window[2], double hu)
{
  return hu * 255.0 / window[0];
}
