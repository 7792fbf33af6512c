// libFuzzer target: amMetaImageCheck on any bytes, as a .mha or as a .mhd header beside its data
// file (amFuzzFiles::WriteImage). A check must return, never crash, hang or read out of bounds; a
// repaired header it writes is removed.
#include "amFuzzFiles.h"
#include "amMetaImageCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string path = amFuzzFiles::WriteImage(data, size, "image.mha", "image.mhd");
  if (path.empty())
    return 0;
  std::string repaired;
  const std::string message = amMetaImageCheck::Check(path, repaired);
  if (!repaired.empty())
    std::remove(repaired.c_str());
  std::remove(path.c_str());
  return 0;
}
