// Builds against the installed Anatomesh: the phantom's label map at 6 mm through LabelSurface.
#include "amLabelSurface.h"
#include "amThoraxPhantomSource.h"

#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cstdio>

int main()
{
  vtkNew<amThoraxPhantomSource> phantom;
  phantom->SetSpacing(6, 6, 6);
  vtkNew<amLabelSurface> surface;
  surface->SetInputConnection(phantom->GetOutputPort(1));
  surface->Update();
  const long long triangles = surface->GetOutput()->GetNumberOfCells();
  std::printf("downstream: %lld triangles\n", triangles);
  return triangles > 0 ? 0 : 1;
}
