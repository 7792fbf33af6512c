#include "amTissueClassTable.h"

vtkSmartPointer<vtkDoubleArray> amTissueClassTable(const amTissueMixture::Result& mixture)
{
  auto table = vtkSmartPointer<vtkDoubleArray>::New();
  table->SetName("TissueClasses");
  table->SetNumberOfComponents(6);
  const char* columns[] = { "Class", "Mean_HU", "Sigma_HU", "Weight", "Found", "Upper_HU" };
  for (int c = 0; c < 6; ++c)
    table->SetComponentName(c, columns[c]);
  for (int c = 0; c < amTissueMixture::NumberOfClasses; ++c)
  {
    const auto& k = mixture.Classes[c];
    const double row[6] = { static_cast<double>(c), k.Mean, k.Sigma, k.Weight, k.Found ? 1.0 : 0.0,
      c + 1 < amTissueMixture::NumberOfClasses ? mixture.Upper[c] : 1e30 };
    table->InsertNextTuple(row);
  }
  return table;
}
