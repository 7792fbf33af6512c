/**
 * @file    amTissueClassTable.h
 * @brief   The field-data table "TissueClasses" of a tissue mixture, as the classifier and the torso
 *          segmentation report it.
 */
#ifndef amTissueClassTable_h
#define amTissueClassTable_h

#include "amTissueMixture.h"

#include "vtkDoubleArray.h"
#include "vtkSmartPointer.h"

/// One row per class (0 air .. 5 bone), components Class, Mean_HU, Sigma_HU, Weight (fraction of
/// the body), Found (1 or 0) and Upper_HU (the class's upper boundary; 1e30 for bone).
vtkSmartPointer<vtkDoubleArray> amTissueClassTable(const amTissueMixture::Result& mixture);

#endif
