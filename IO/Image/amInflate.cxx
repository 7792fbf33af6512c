#include "amInflate.h"

#include <zlib.h>

#include <algorithm>
#include <fstream>
#include <sys/stat.h>

amInflate::Status amInflate::Stream(const std::string& path, long long offset, size_t keep,
  std::vector<unsigned char>& kept, long long& produced, long long& consumed, std::string& message,
  const std::function<void(const unsigned char*, size_t)>& sink)
{
  produced = consumed = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    message = "it cannot be opened";
    return Corrupt;
  }
  in.seekg(offset);
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 32) != Z_OK) // zlib or gzip header
  {
    message = "zlib cannot start";
    return Corrupt;
  }
  std::vector<unsigned char> inBuf(1 << 16), outBuf(1 << 20);
  int status = Z_OK;
  while (status == Z_OK)
  {
    if (zs.avail_in == 0)
    {
      in.read(reinterpret_cast<char*>(inBuf.data()), static_cast<std::streamsize>(inBuf.size()));
      zs.avail_in = static_cast<uInt>(in.gcount());
      zs.next_in = inBuf.data();
      if (zs.avail_in == 0)
        break; // the file ended first
    }
    zs.next_out = outBuf.data();
    zs.avail_out = static_cast<uInt>(outBuf.size());
    status = inflate(&zs, Z_NO_FLUSH);
    const size_t out = outBuf.size() - zs.avail_out;
    if (kept.size() < keep)
      kept.insert(kept.end(), outBuf.begin(), outBuf.begin() + std::min(out, keep - kept.size()));
    if (sink && out > 0)
      sink(outBuf.data(), out);
    produced += static_cast<long long>(out);
    if (status == Z_BUF_ERROR)
      status = Z_OK; // no progress this round: read more
  }
  consumed = static_cast<long long>(zs.total_in);
  if (status != Z_OK && status != Z_STREAM_END)
    message = zs.msg ? zs.msg : "zlib error " + std::to_string(status);
  inflateEnd(&zs);
  if (status == Z_STREAM_END)
    return Complete;
  return status == Z_OK ? Truncated : Corrupt;
}

long long amInflate::FileSize(const std::string& path)
{
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 ? static_cast<long long>(st.st_size) : -1;
}

bool amInflate::IsRegularFile(const std::string& path)
{
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}
