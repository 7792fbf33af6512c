#include "amDescriptorIO.h"

#include <cerrno>
#include <unistd.h>

namespace
{
/// Calls 'call' (read or write) until 'bytes' have passed, retrying interrupted calls.
template<typename Byte, typename Call>
bool Transfer(int fd, Byte* p, std::size_t bytes, Call call)
{
  while (bytes > 0)
  {
    const ssize_t n = call(fd, p, bytes);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return true;
}
}

namespace amDescriptorIO
{
bool WriteAll(int fd, const void* data, std::size_t bytes)
{
  return Transfer(
    fd, static_cast<const char*>(data), bytes, [](int f, const char* p, std::size_t n) { return ::write(f, p, n); });
}

bool ReadAll(int fd, void* data, std::size_t bytes)
{
  return Transfer(fd, static_cast<char*>(data), bytes, [](int f, char* p, std::size_t n) { return ::read(f, p, n); });
}
}
