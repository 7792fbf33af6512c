#include "amMetaImageCheck.h"

#include "amInflate.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace
{
std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::string FolderOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}
}

std::string amMetaImageCheck::Check(const std::string& path, std::string& repairedHeader)
{
  repairedHeader.clear();
  std::ifstream in(path, std::ios::binary);
  std::string line, dataFile;
  std::vector<long long> dims;
  long long elementBytes = 0, channels = 1, compressedSize = -1, headerBytes = 0;
  bool compressed = false;
  while (std::getline(in, line))
  {
    headerBytes += static_cast<long long>(line.size()) + 1;
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      continue;
    const std::string key = Trim(line.substr(0, eq)), value = Trim(line.substr(eq + 1));
    std::istringstream v(value);
    if (key == "DimSize")
    {
      long long d;
      while (v >> d)
        dims.push_back(d);
    }
    else if (key == "ElementNumberOfChannels")
      v >> channels;
    else if (key == "CompressedData")
      compressed = value == "True" || value == "true";
    else if (key == "CompressedDataSize")
      v >> compressedSize;
    else if (key == "ElementType")
    {
      static const std::pair<const char*, int> sizes[] = { { "MET_UCHAR", 1 }, { "MET_CHAR", 1 }, { "MET_USHORT", 2 },
        { "MET_SHORT", 2 }, { "MET_UINT", 4 }, { "MET_INT", 4 }, { "MET_FLOAT", 4 }, { "MET_ULONG_LONG", 8 },
        { "MET_LONG_LONG", 8 }, { "MET_DOUBLE", 8 } };
      for (const auto& sz : sizes)
        if (value == sz.first)
          elementBytes = sz.second;
    }
    else if (key == "ElementDataFile")
    {
      dataFile = value;
      break;
    }
  }
  if (dims.empty() || elementBytes == 0 || dataFile.empty() || dataFile == "LIST" ||
    dataFile.find('%') != std::string::npos || dataFile.find(' ') != std::string::npos)
    return std::string();
  long long expected = elementBytes * channels;
  for (long long d : dims)
    expected *= d;
  long long available;
  std::string where;
  if (dataFile == "LOCAL")
  {
    available = amInflate::FileSize(path) - headerBytes;
    where = path;
  }
  else
  {
    where = dataFile[0] == '/' ? dataFile : FolderOf(path) + "/" + dataFile;
    available = amInflate::FileSize(where);
    if (available < 0)
      return "its data file '" + where + "' does not exist";
  }
  if (compressed)
  {
    if (compressedSize > 0 && available < compressedSize)
      return "the compressed voxel data is truncated (" + std::to_string(available) + " of " +
        std::to_string(compressedSize) + " bytes in '" + where + "')";
    std::vector<unsigned char> none;
    long long produced = 0, consumed = 0;
    std::string message;
    const amInflate::Status status =
      amInflate::Stream(where, dataFile == "LOCAL" ? headerBytes : 0, 0, none, produced, consumed, message);
    if (status == amInflate::Corrupt)
      return "the compressed voxel data in '" + where + "' is corrupt (" + message + ")";
    if (produced < expected)
      return "the compressed voxel data in '" + where + "' inflates to " + std::to_string(produced) + " of the " +
        std::to_string(expected) + " bytes the header announces (truncated)";
    if (compressedSize > 0 && compressedSize != consumed && dataFile != "LOCAL")
    {
      std::ifstream header(path);
      std::string text, l;
      while (std::getline(header, l))
      {
        const std::string key = Trim(l.substr(0, l.find('=')));
        if (key == "CompressedDataSize")
          l = "CompressedDataSize = " + std::to_string(consumed);
        else if (key == "ElementDataFile")
        {
          // The repaired header lives in the temporary folder: name the data by its absolute path.
          text += "ElementDataFile = " + std::filesystem::absolute(where).string() + "\n";
          break;
        }
        text += l + "\n";
      }
      char tmpl[] = "/tmp/anatomesh-meta-XXXXXX.mhd";
      const int fd = ::mkstemps(tmpl, 4);
      if (fd >= 0)
      {
        const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
        ::close(fd);
        if (ok)
          repairedHeader = tmpl;
        else
          std::remove(tmpl);
      }
      if (repairedHeader.empty())
        return "its header gives CompressedDataSize " + std::to_string(compressedSize) + " but the stream has " +
          std::to_string(consumed) + " bytes, and no corrected copy could be written";
    }
    return std::string();
  }
  if (available < expected)
    return "the voxel data is truncated (" + std::to_string(available) + " of " + std::to_string(expected) +
      " bytes in '" + where + "')";
  return std::string();
}
