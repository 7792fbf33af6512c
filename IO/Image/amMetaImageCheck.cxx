#include "amMetaImageCheck.h"

#include "amHeaderText.h"

#include "amByteCount.h"
#include "amInflate.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace
{
using amHeaderText::FolderOf;
using amHeaderText::Trim;

/// The numbers of a header value, parsed as C does ("nan" and "inf" included, which the stream
/// operators refuse); 'bad' gets the first word that is not a number.
std::vector<double> Numbers(const std::string& value, std::string& bad)
{
  std::istringstream in(value);
  std::vector<double> numbers;
  std::string word;
  while (in >> word)
  {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if (!end || *end != '\0')
    {
      bad = word;
      break;
    }
    numbers.push_back(x);
  }
  return numbers;
}

/// "" when a geometry field is finite (and, for a voxel size, positive); otherwise what is wrong.
std::string CheckGeometry(const std::string& key, const std::string& value)
{
  std::string bad;
  const std::vector<double> v = Numbers(value, bad);
  const bool size = key == "ElementSpacing" || key == "ElementSize";
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || (size && v[i] <= 0))
      return "its " + key + " gives " + std::to_string(v[i]) + " for axis " + std::to_string(i) +
        (size ? "; a voxel size must be a finite number > 0" : "; it must be finite");
  if ((key == "TransformMatrix" || key == "Rotation" || key == "Orientation") && v.size() == 9)
  {
    const double det =
      v[0] * (v[4] * v[8] - v[5] * v[7]) - v[1] * (v[3] * v[8] - v[5] * v[6]) + v[2] * (v[3] * v[7] - v[4] * v[6]);
    if (det == 0)
      return "its " + key + " is degenerate (determinant 0): it maps the voxels to a plane";
  }
  return "";
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
    else if (key == "ElementSpacing" || key == "ElementSize" || key == "Offset" || key == "Position" ||
      key == "Origin" || key == "TransformMatrix" || key == "Rotation" || key == "Orientation")
    {
      const std::string problem = CheckGeometry(key, value);
      if (!problem.empty())
        return problem;
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
  // ElementDataFile ends every MetaImage header: without it the header is cut short (MetaIO would
  // only print "DimSize required" and ITK add a stale system error).
  if (dataFile.empty())
    return "its MetaImage header ends without ElementDataFile: it is cut short, or not a MetaImage header";
  if (dims.empty())
    return "its MetaImage header has no DimSize (the image's size)";
  if (elementBytes == 0 || dataFile == "LIST" || dataFile.find('%') != std::string::npos ||
    dataFile.find(' ') != std::string::npos)
    return std::string();
  long long expected = elementBytes;
  if (!amByteCount::Multiply(expected, channels) || channels < 1)
    return "its ElementNumberOfChannels is " + std::to_string(channels) + "; it must be >= 1";
  for (long long d : dims)
  {
    if (d < 1)
      return "its DimSize gives " + std::to_string(d) + "; every size must be >= 1";
    if (!amByteCount::Multiply(expected, d))
      return "its DimSize asks for more voxel data than any file holds";
  }
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
    if (!amInflate::IsRegularFile(where))
      return "its data file '" + where + "' is not a regular file";
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
