// libFuzzer target: amNiftiCheck on any bytes. Its first byte picks the file's form: 0 a .nii,
// 1 the bytes as a .nii.gz (the inflation's own checks), 2 the bytes gzip-compressed as a .nii.gz
// (the header's checks behind compression), 3 a .hdr (the first 348 bytes) with its .img.
// A check must return (an empty string or a message), never crash, hang or read out of bounds.
#include "amFuzzFiles.h"
#include "amNiftiCheck.h"

#include <zlib.h>

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
    return 0;
  const int form = data[0] % 4;
  ++data;
  --size;
  std::string path;
  switch (form)
  {
    case 0:
      path = amFuzzFiles::Write("image.nii", data, size);
      break;
    case 1:
      path = amFuzzFiles::Write("image.nii.gz", data, size);
      break;
    case 2:
    {
      const std::string gz = amFuzzFiles::Folder() + "/image.nii.gz";
      gzFile f = gzopen(gz.c_str(), "wb");
      if (!f || (size && gzwrite(f, data, static_cast<unsigned>(size)) != static_cast<int>(size)) || gzclose(f) != Z_OK)
        std::abort();
      path = gz;
      break;
    }
    default:
    {
      const size_t header = size < 348 ? size : 348;
      path = amFuzzFiles::Write("image.hdr", data, header);
      amFuzzFiles::Write("image.img", data + header, size - header);
      break;
    }
  }
  const std::string message = amNiftiCheck::Check(path);
  std::remove(path.c_str());
  return 0;
}
