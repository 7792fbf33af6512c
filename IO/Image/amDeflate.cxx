#include "amDeflate.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <vector>

bool amDeflate::GzipFile(const std::string& from, const std::string& to, int level, std::string& why)
{
  FILE* in = std::fopen(from.c_str(), "rb");
  if (!in)
  {
    why = "cannot read '" + from + "'";
    return false;
  }
  const std::string mode = "wb" + std::to_string(std::clamp(level, 1, 9));
  gzFile out = gzopen(to.c_str(), mode.c_str());
  if (!out)
  {
    std::fclose(in);
    why = "cannot create '" + to + "'";
    return false;
  }
  // zlib's own buffer as large as ours: each gzwrite compresses one block.
  gzbuffer(out, 1 << 20);
  std::vector<char> block(1 << 20);
  bool ok = true;
  size_t got;
  while (ok && (got = std::fread(block.data(), 1, block.size(), in)) > 0)
    ok = gzwrite(out, block.data(), static_cast<unsigned>(got)) == static_cast<int>(got);
  ok = ok && !std::ferror(in);
  std::fclose(in);
  // gzclose flushes the last block: a full disk may show only here.
  ok = gzclose(out) == Z_OK && ok;
  if (!ok)
    why = "writing the compressed data failed; is the disk full?";
  return ok;
}
