#include "amNrrdCheck.h"

#include "amHeaderText.h"

#include "amByteCount.h"
#include "amInflate.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace
{
using amHeaderText::FolderOf;
using amHeaderText::Trim;

std::vector<std::string> Words(const std::string& s)
{
  std::istringstream in(s);
  std::vector<std::string> words;
  std::string w;
  while (in >> w)
    words.push_back(w);
  return words;
}

bool WholeNumber(const std::string& word, long long& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(word.c_str(), &end, 10);
  return !word.empty() && end && *end == '\0' && errno == 0;
}

bool Number(const std::string& word, double& value)
{
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end && *end == '\0';
}

/// Bytes per value of a NRRD type name (its many spellings), 0 when unknown or "block".
long long TypeBytes(const std::string& type)
{
  static const std::map<std::string, long long> sizes = { { "signed char", 1 }, { "int8", 1 }, { "int8_t", 1 },
    { "uchar", 1 }, { "unsigned char", 1 }, { "uint8", 1 }, { "uint8_t", 1 }, { "short", 2 }, { "short int", 2 },
    { "signed short", 2 }, { "signed short int", 2 }, { "int16", 2 }, { "int16_t", 2 }, { "ushort", 2 },
    { "unsigned short", 2 }, { "unsigned short int", 2 }, { "uint16", 2 }, { "uint16_t", 2 }, { "int", 4 },
    { "signed int", 4 }, { "int32", 4 }, { "int32_t", 4 }, { "uint", 4 }, { "unsigned int", 4 }, { "uint32", 4 },
    { "uint32_t", 4 }, { "longlong", 8 }, { "long long", 8 }, { "long long int", 8 }, { "signed long long", 8 },
    { "signed long long int", 8 }, { "int64", 8 }, { "int64_t", 8 }, { "ulonglong", 8 }, { "unsigned long long", 8 },
    { "unsigned long long int", 8 }, { "uint64", 8 }, { "uint64_t", 8 }, { "float", 4 }, { "double", 8 } };
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

/// A "(a,b,c)" vector of 'space directions' or 'space origin'; false when it is not one.
bool Vector(const std::string& word, std::vector<double>& v)
{
  v.clear();
  if (word.size() < 2 || word.front() != '(' || word.back() != ')')
    return false;
  std::istringstream in(word.substr(1, word.size() - 2));
  std::string part;
  while (std::getline(in, part, ','))
  {
    double x;
    if (!Number(Trim(part), x))
      return false;
    v.push_back(x);
  }
  return !v.empty();
}

/// "" when the geometry fields are finite and span a volume; otherwise what is wrong.
std::string CheckGeometry(const std::map<std::string, std::string>& fields)
{
  auto field = fields.find("spacings");
  if (field != fields.end())
  {
    const std::vector<std::string> words = Words(field->second);
    for (size_t axis = 0; axis < words.size(); ++axis)
    {
      double s;
      if (Number(words[axis], s) && !std::isfinite(s))
        return "its 'spacings' field gives " + words[axis] + " for axis " + std::to_string(axis) +
          "; a voxel size must be a finite number";
    }
  }
  field = fields.find("spacedirections");
  if (field != fields.end())
  {
    std::vector<std::vector<double>> axes;
    const std::vector<std::string> words = Words(field->second);
    for (size_t axis = 0; axis < words.size(); ++axis)
    {
      std::vector<double> v;
      if (words[axis] == "none" || !Vector(words[axis], v))
        continue;
      double length = 0;
      for (double x : v)
      {
        if (!std::isfinite(x))
          return "its 'space directions' field holds a non-finite value for axis " + std::to_string(axis);
        length += x * x;
      }
      if (length == 0)
        return "its 'space directions' vector of axis " + std::to_string(axis) +
          " is zero: the voxels have no extent along it";
      axes.push_back(v);
    }
    if (axes.size() == 3 && axes[0].size() == 3 && axes[1].size() == 3 && axes[2].size() == 3)
    {
      const auto& a = axes[0];
      const auto& b = axes[1];
      const auto& c = axes[2];
      const double det =
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
      if (det == 0)
        return "its 'space directions' are degenerate (the three axes lie in a plane)";
    }
  }
  field = fields.find("spaceorigin");
  if (field != fields.end())
  {
    std::vector<double> v;
    if (Vector(Trim(field->second), v))
      for (double x : v)
        if (!std::isfinite(x))
          return "its 'space origin' holds a non-finite value";
  }
  return "";
}

}

std::string amNrrdCheck::Check(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return "it cannot be opened";
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD000", 0) != 0)
    return "it does not start with the NRRD magic (NRRD000N)";
  long long headerBytes = static_cast<long long>(line.size()) + 1;
  std::map<std::string, std::string> fields;
  bool blank = false;
  while (std::getline(in, line))
  {
    headerBytes += static_cast<long long>(line.size()) + 1;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line.empty())
    {
      blank = true;
      break;
    }
    const auto colon = line.find(": ");
    const auto pair = line.find(":=");
    if (line[0] == '#' || colon == std::string::npos || (pair != std::string::npos && pair < colon))
      continue; // comments and key/value pairs; teem judges malformed lines
    std::string key;
    for (char c : line.substr(0, colon))
      if (c != ' ')
        key += c;
    fields[key] = Trim(line.substr(colon + 2));
  }

  const std::string geometry = CheckGeometry(fields);
  if (!geometry.empty())
    return geometry;

  long long dimension = 0;
  const long long typeBytes = TypeBytes(fields["type"]);
  if (typeBytes == 0 || !WholeNumber(fields["dimension"], dimension) || dimension < 1)
    return ""; // teem names a missing or unknown type or dimension
  const std::vector<std::string> sizes = Words(fields["sizes"]);
  if (static_cast<long long>(sizes.size()) != dimension)
    return "its 'sizes' field lists " + std::to_string(sizes.size()) + " sizes for dimension " +
      std::to_string(dimension);
  long long expected = typeBytes;
  for (size_t axis = 0; axis < sizes.size(); ++axis)
  {
    long long n;
    if (!WholeNumber(sizes[axis], n) || n < 1)
      return "its 'sizes' field gives '" + sizes[axis] + "' for axis " + std::to_string(axis) +
        "; every size must be a whole number >= 1";
    if (!amByteCount::Multiply(expected, n))
      return "its 'sizes' (" + fields["sizes"] + ") ask for more voxel data than any file holds";
  }

  const std::string encoding = fields["encoding"];
  const bool gzip = encoding == "gzip" || encoding == "gz";
  long long lineSkip = 0;
  if ((!gzip && encoding != "raw") || (WholeNumber(fields["lineskip"], lineSkip) && lineSkip != 0))
    return ""; // text, hex and bzip2 encodings and skipped lines are read and checked by teem

  std::string where = path;
  long long offset = headerBytes;
  const auto dataFile = fields.find("datafile");
  if (dataFile != fields.end())
  {
    const std::string name = dataFile->second;
    if (name.rfind("LIST", 0) == 0 || name.find('%') != std::string::npos || Words(name).size() != 1)
      return ""; // several data files: teem reads them
    where = name[0] == '/' ? name : FolderOf(path) + "/" + name;
    offset = 0;
    if (amInflate::FileSize(where) < 0)
      return "its data file '" + where + "' does not exist";
    if (!amInflate::IsRegularFile(where))
      return "its data file '" + where + "' is not a regular file";
  }
  else if (!blank)
    return "its header does not end with a blank line, so it holds no voxel data";

  long long skip = 0;
  if (fields.count("byteskip") && !WholeNumber(fields["byteskip"], skip))
    return "its 'byte skip' field is not a whole number ('" + fields["byteskip"] + "')";
  const long long fileBytes = amInflate::FileSize(where);
  if (skip == -1 && !gzip)
    offset = fileBytes - expected; // the data is the file's last bytes
  else if (skip < 0)
    return "its 'byte skip' is " + std::to_string(skip) + "; only -1 (raw data at the end) may be negative";
  else if (skip > amByteCount::Limit - offset)
    return "its 'byte skip' (" + std::to_string(skip) + ") lies past the end of any file";
  else
    offset += skip;

  if (!gzip)
  {
    const long long available = offset < 0 ? fileBytes - headerBytes : fileBytes - offset;
    if (offset < 0 || available < expected)
      return "its voxel data is truncated (" + std::to_string(available < 0 ? 0 : available) + " of " +
        std::to_string(expected) + " bytes in '" + where + "')";
    return "";
  }
  std::vector<unsigned char> none;
  long long produced = 0, consumed = 0;
  std::string message;
  switch (amInflate::Stream(where, offset, 0, none, produced, consumed, message))
  {
    case amInflate::Corrupt:
      return "its gzip voxel data in '" + where + "' is corrupt (" + message + ")";
    case amInflate::Truncated:
      return "its gzip voxel data in '" + where + "' ends before the end of its stream (truncated)";
    default:
      break;
  }
  if (produced < expected)
    return "its gzip voxel data in '" + where + "' inflates to " + std::to_string(produced) + " of the " +
      std::to_string(expected) + " bytes the header announces (truncated)";
  return "";
}
