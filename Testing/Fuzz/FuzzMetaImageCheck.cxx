// libFuzzer target: amMetaImageCheck on any bytes. Its first byte picks the form: even, a .mha (the
// bytes as they are); odd, a .mhd header (the bytes up to the first NUL) beside the data file
// "image.raw" (the bytes after it), which the header may or may not name.
// A check must return, never crash, hang or read out of bounds; a repaired header it writes is
// removed.
#include "amFuzzFiles.h"
#include "amMetaImageCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
    return 0;
  const bool detached = data[0] % 2;
  ++data;
  --size;
  std::string path;
  if (detached)
  {
    const size_t header = amFuzzFiles::HeaderLength(data, size);
    path = amFuzzFiles::Write("image.mhd", data, header);
    const size_t rest = header < size ? header + 1 : size;
    amFuzzFiles::Write("image.raw", data + rest, size - rest);
  }
  else
    path = amFuzzFiles::Write("image.mha", data, size);
  std::string repaired;
  const std::string message = amMetaImageCheck::Check(path, repaired);
  if (!repaired.empty())
    std::remove(repaired.c_str());
  std::remove(path.c_str());
  return 0;
}
