#include "amThreading.h"

#include "vtkSMPTools.h"

#include <cstdlib>
#include <mutex>
#include <string>

void amThreading::Initialize()
{
  static std::once_flag once;
  std::call_once(once, [] {
    if (std::getenv("VTK_SMP_BACKEND_IN_USE"))
      return;
    if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
      vtkSMPTools::SetBackend("STDThread");
  });
}
