#include "amSimulationRun.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"

#include <atomic>

namespace
{
std::atomic<long long> Counter{ 0 };
}

long long amSimulationRun::Next()
{
  return ++Counter;
}

void amSimulationRun::Stamp(vtkDataObject* output, long long id)
{
  vtkNew<vtkIdTypeArray> run;
  run->SetName("SimulationRun");
  run->InsertNextValue(static_cast<vtkIdType>(id));
  output->GetFieldData()->AddArray(run);
}

long long amSimulationRun::Of(vtkDataObject* heart)
{
  vtkDataArray* run = heart->GetFieldData()->GetArray("SimulationRun");
  if (run && run->GetNumberOfTuples() > 0)
    return static_cast<long long>(run->GetComponent(0, 0));
  return static_cast<long long>(heart->GetMTime()) + (1LL << 40);
}
