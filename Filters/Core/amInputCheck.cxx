#include "amInputCheck.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <cmath>

vtkDataArray* amInputCheck::ScalarImage(vtkImageData* image, std::string& why)
{
  if (!image || image->GetNumberOfPoints() == 0)
  {
    why = "The input image is empty.";
    return nullptr;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    why = "The input image has no scalars.";
    return nullptr;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    why = "The input scalars '" + std::string(scalars->GetName() ? scalars->GetName() : "") + "' have " +
      std::to_string(scalars->GetNumberOfComponents()) + " components; a one-component image is needed.";
    return nullptr;
  }
  return scalars;
}

bool amInputCheck::LabelBytes(vtkDataArray* scalars, int maximum, std::vector<unsigned char>& out, std::string& why)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  out.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    if (!(v >= 0 && v <= maximum) || v != std::floor(v))
    {
      why = "Voxel " + std::to_string(i) + " has value " + std::to_string(v) + ": a label map holds whole numbers 0.." +
        std::to_string(maximum) + ".";
      return false;
    }
    out[i] = static_cast<unsigned char>(v);
  }
  return true;
}

long long amInputCheck::NonFinite(vtkDataArray* scalars)
{
  long long count = 0;
  const vtkIdType n = scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
    count += std::isfinite(scalars->GetComponent(i, 0)) ? 0 : 1;
  return count;
}
