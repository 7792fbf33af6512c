// Internal to the fuzz targets: the checks under test read files, so each input is written to a
// private folder (in /dev/shm when there is one: memory, not disk) and removed after the call.
#ifndef amFuzzFiles_h
#define amFuzzFiles_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace amFuzzFiles
{
/// The process's folder for its inputs, made once.
inline const std::string& Folder()
{
  static const std::string folder = [] {
    std::string tmpl = (access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") + std::string("/anatomesh-fuzz-XXXXXX");
    if (!mkdtemp(&tmpl[0]))
      std::abort();
    return tmpl;
  }();
  return folder;
}

/// Writes 'size' bytes to Folder()/name and returns the path.
inline std::string Write(const std::string& name, const uint8_t* data, size_t size)
{
  const std::string path = Folder() + "/" + name;
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || (size && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0)
    std::abort();
  return path;
}

/// The input as an image of a format whose header is attached or detached, its first byte picking
/// which: even, the file 'attached' holds the rest of the bytes; odd, the file 'detached' holds
/// them up to the first NUL (the header), beside "image.raw" with the bytes after it (a data file
/// the header may or may not name). Returns the path to check, "" for an empty input.
inline std::string WriteImage(
  const uint8_t* data, size_t size, const std::string& attached, const std::string& detached)
{
  if (size < 1)
    return "";
  const bool isDetached = data[0] % 2;
  ++data;
  --size;
  if (!isDetached)
    return Write(attached, data, size);
  size_t header = 0;
  while (header < size && data[header] != 0)
    ++header;
  const size_t rest = header < size ? header + 1 : size;
  Write("image.raw", data + rest, size - rest);
  return Write(detached, data, header);
}
}

#endif
