/**
 * @file    amUnits.h
 * @brief   The unit of an array's values, kept on the array (vtkDataArray::UNITS_LABEL) so that
 *          every file that can say it does: the CSV tables' headers ("Volume_mm3", "Time_ms").
 */
#ifndef amUnits_h
#define amUnits_h

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"

namespace amUnits
{
/// Records 'unit' (e.g. "mm3", "deg", "ms", "mV") as the array's unit.
inline void Set(vtkAbstractArray* array, const char* unit)
{
  array->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), unit);
}
}

#endif
