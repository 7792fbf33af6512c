// libFuzzer target: amNrrdCheck on any bytes, as a .nrrd or as a .nhdr header beside its data file
// (amFuzzFiles::WriteImage). A check must return, never crash, hang or read out of bounds.
#include "amFuzzFiles.h"
#include "amNrrdCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = amFuzzFiles::WriteImage(data, size, "image.nrrd", "image.nhdr");
  if (path.empty())
    return 0;
  const std::string message = amNrrdCheck::Check(path);
  std::remove(path.c_str());
  return 0;
}
