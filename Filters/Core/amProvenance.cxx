#include "amProvenance.h"

#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#ifndef ANATOMESH_VERSION
#define ANATOMESH_VERSION "unknown"
#endif

namespace
{
vtkStringArray* FindProvenance(vtkDataObject* obj)
{
  if (!obj || !obj->GetFieldData())
    return nullptr;
  return vtkStringArray::SafeDownCast(obj->GetFieldData()->GetAbstractArray("Provenance"));
}
}

const char* amProvenance::Version()
{
  return ANATOMESH_VERSION;
}

void amProvenance::Record(
  vtkDataObject* output, vtkDataObject* input, const std::string& filter, const std::string& parameters)
{
  if (!output)
    return;
  vtkNew<vtkStringArray> entries;
  entries->SetName("Provenance");
  if (vtkStringArray* previous = FindProvenance(input))
    for (vtkIdType i = 0; i < previous->GetNumberOfValues(); ++i)
      entries->InsertNextValue(previous->GetValue(i));
  entries->InsertNextValue(filter + " " + ANATOMESH_VERSION + ": " + parameters);
  if (!output->GetFieldData())
  {
    vtkNew<vtkFieldData> fd;
    output->SetFieldData(fd);
  }
  output->GetFieldData()->RemoveArray("Provenance");
  output->GetFieldData()->AddArray(entries);
}

std::string amProvenance::Get(vtkDataObject* obj)
{
  std::string text;
  if (vtkStringArray* entries = FindProvenance(obj))
    for (vtkIdType i = 0; i < entries->GetNumberOfValues(); ++i)
    {
      if (i)
        text += "\n";
      text += entries->GetValue(i);
    }
  return text;
}
