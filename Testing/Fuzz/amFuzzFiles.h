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

/// The input split at its first NUL byte: a header, then the data of a detached data file.
inline size_t HeaderLength(const uint8_t* data, size_t size)
{
  for (size_t i = 0; i < size; ++i)
    if (data[i] == 0)
      return i;
  return size;
}
}

#endif
