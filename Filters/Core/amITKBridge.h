// Header-only: copy images between ITK and VTK with origin, spacing and direction (Debian has no
// ITKVtkGlue), and dispatch on a runtime component type.
#ifndef amITKBridge_h
#define amITKBridge_h

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTypeTraits.h"

#include <itkImage.h>
#include <itkImageIOBase.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace amITK
{
template<typename T>
using Image3 = itk::Image<T, 3>;

template<typename T>
vtkSmartPointer<vtkImageData> ToVTK(const Image3<T>* image, const char* scalarName)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  const auto region = image->GetLargestPossibleRegion();
  const auto size = region.GetSize();
  out->SetDimensions(static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]));
  double origin[3], spacing[3], direction[9];
  for (int r = 0; r < 3; ++r)
  {
    origin[r] = image->GetOrigin()[r];
    spacing[r] = image->GetSpacing()[r];
    for (int c = 0; c < 3; ++c)
      direction[3 * r + c] = image->GetDirection()(r, c);
  }
  out->SetOrigin(origin);
  out->SetSpacing(spacing);
  out->SetDirectionMatrix(direction);
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(vtkTypeTraits<T>::VTKTypeID()));
  const vtkIdType n = static_cast<vtkIdType>(size[0]) * size[1] * size[2];
  array->SetNumberOfComponents(1);
  array->SetNumberOfTuples(n);
  array->SetName(scalarName);
  std::memcpy(array->GetVoidPointer(0), image->GetBufferPointer(), sizeof(T) * n);
  out->GetPointData()->SetScalars(array);
  return out;
}

template<typename T>
typename Image3<T>::Pointer FromVTK(vtkImageData* in)
{
  auto image = Image3<T>::New();
  int dims[3];
  in->GetDimensions(dims);
  typename Image3<T>::RegionType region;
  typename Image3<T>::SizeType size;
  for (int i = 0; i < 3; ++i)
    size[i] = static_cast<itk::SizeValueType>(dims[i]);
  region.SetSize(size);
  image->SetRegions(region);
  typename Image3<T>::PointType origin;
  typename Image3<T>::SpacingType spacing;
  typename Image3<T>::DirectionType direction;
  // vtkImageData origin is the position of point (0,0,0) of the whole extent only when the
  // extent starts at 0; use the physical position of the first point to be safe.
  int extent[6];
  in->GetExtent(extent);
  double first[3];
  const int ijk[3] = { extent[0], extent[2], extent[4] };
  in->TransformContinuousIndexToPhysicalPoint(ijk[0], ijk[1], ijk[2], first);
  for (int r = 0; r < 3; ++r)
  {
    origin[r] = first[r];
    spacing[r] = in->GetSpacing()[r];
    for (int c = 0; c < 3; ++c)
      direction(r, c) = in->GetDirectionMatrix()->GetElement(r, c);
  }
  image->SetOrigin(origin);
  image->SetSpacing(spacing);
  image->SetDirection(direction);
  image->Allocate();
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  vtkDataArray* scalars = in->GetPointData()->GetScalars();
  if (scalars->GetDataType() == vtkTypeTraits<T>::VTKTypeID())
    std::memcpy(image->GetBufferPointer(), scalars->GetVoidPointer(0), sizeof(T) * n);
  else
    for (vtkIdType i = 0; i < n; ++i)
      image->GetBufferPointer()[i] = static_cast<T>(scalars->GetComponent(i, 0));
  return image;
}

/// Calls f.template operator()<T>() for the C++ type of an ITK component type; false if unsupported.
template<typename F>
bool DispatchComponent(itk::IOComponentEnum type, F&& f)
{
  using C = itk::IOComponentEnum;
  switch (type)
  {
    case C::UCHAR:
      f(static_cast<unsigned char*>(nullptr));
      return true;
    case C::CHAR:
      f(static_cast<signed char*>(nullptr));
      return true;
    case C::USHORT:
      f(static_cast<unsigned short*>(nullptr));
      return true;
    case C::SHORT:
      f(static_cast<short*>(nullptr));
      return true;
    case C::UINT:
      f(static_cast<unsigned int*>(nullptr));
      return true;
    case C::INT:
      f(static_cast<int*>(nullptr));
      return true;
    case C::ULONG:
      f(static_cast<unsigned long*>(nullptr));
      return true;
    case C::LONG:
      f(static_cast<long*>(nullptr));
      return true;
    case C::ULONGLONG:
      f(static_cast<unsigned long long*>(nullptr));
      return true;
    case C::LONGLONG:
      f(static_cast<long long*>(nullptr));
      return true;
    case C::FLOAT:
      f(static_cast<float*>(nullptr));
      return true;
    case C::DOUBLE:
      f(static_cast<double*>(nullptr));
      return true;
    default:
      return false;
  }
}

/// Three letters naming where the index axes point in the patient (LPS world: +x L, +y P, +z S).
inline std::string OrientationCode(const double direction[9])
{
  std::string code;
  for (int c = 0; c < 3; ++c)
  {
    int best = 0;
    for (int r = 1; r < 3; ++r)
      if (std::abs(direction[3 * r + c]) > std::abs(direction[3 * best + c]))
        best = r;
    const bool positive = direction[3 * best + c] > 0;
    const char letters[3][2] = { { 'R', 'L' }, { 'A', 'P' }, { 'I', 'S' } };
    code += letters[best][positive ? 1 : 0];
  }
  return code;
}

/// An ITK exception's text without its "file.cxx:309: ITK ERROR: ClassIO(0x...): " prefix (the
/// source location and object address mean nothing to a user); the rest, its lines included, kept.
inline std::string WithoutLocation(const std::string& text)
{
  const auto itk = text.find("ITK ERROR: ");
  const auto end = itk == std::string::npos ? std::string::npos : text.find("): ", itk);
  if (end == std::string::npos)
    return text;
  const auto start = text.rfind('\n', itk);
  return text.substr(0, start == std::string::npos ? 0 : start + 1) + text.substr(end + 3);
}

/// An ITK exception's description on one line, without its source location.
inline std::string Description(const std::string& what)
{
  std::string t = what;
  const auto desc = t.find("Description: ");
  if (desc != std::string::npos)
    t = t.substr(desc + 13);
  t = WithoutLocation(t);
  std::replace(t.begin(), t.end(), '\n', ' ');
  return t;
}
}

#endif
