#include "amInputCheck.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

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
