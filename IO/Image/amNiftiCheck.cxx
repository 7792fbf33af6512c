#include "amNiftiCheck.h"

#include "amByteCount.h"
#include "amInflate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace
{
bool EndsWith(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

/// The start of the decompressed content of a gzip file (at most 'limit' bytes) and its total size;
/// the stream is inflated to its end all the same (that checks its CRC).
std::string Inflate(const std::string& path, size_t limit, std::vector<unsigned char>& kept, long long& total)
{
  long long consumed = 0;
  std::string message;
  switch (amInflate::Stream(path, 0, limit, kept, total, consumed, message))
  {
    case amInflate::Complete:
      return "";
    case amInflate::Truncated:
      return "its compressed data ends before the end of the stream (truncated)";
    default:
      return "its compressed data is corrupt (" + message + ")";
  }
}

struct Header
{
  const unsigned char* Bytes;
  bool Swap;
  template<typename T>
  T Get(size_t offset) const
  {
    T v;
    std::memcpy(&v, this->Bytes + offset, sizeof(T));
    if (this->Swap)
    {
      unsigned char* p = reinterpret_cast<unsigned char*>(&v);
      std::reverse(p, p + sizeof(T));
    }
    return v;
  }
};

/// Counts the NaN and infinite values among a stream's float32 or float64 voxels (the bytes from
/// Start to End), fed in chunks of any size: ITK's NIfTI reader sets them to 0 without a word.
struct NonFiniteCounter
{
  long long Start, End;
  int Bytes;
  bool Swap;
  long long Position = 0, Count = 0;
  unsigned char Value[8];
  int Filled = 0;

  void Feed(const unsigned char* p, size_t n)
  {
    for (size_t i = 0; i < n; ++i, ++this->Position)
    {
      if (this->Position < this->Start || this->Position >= this->End)
        continue;
      this->Value[this->Filled++] = p[i];
      if (this->Filled < this->Bytes)
        continue;
      this->Filled = 0;
      if (this->Swap)
        std::reverse(this->Value, this->Value + this->Bytes);
      double v;
      if (this->Bytes == 4)
      {
        float f;
        std::memcpy(&f, this->Value, 4);
        v = f;
      }
      else
        std::memcpy(&v, this->Value, 8);
      this->Count += std::isfinite(v) ? 0 : 1;
    }
  }
};

/// The number of non-finite voxels of a float32 (datatype 16) or float64 (64) image, 0 otherwise.
long long CountNonFinite(
  const std::string& path, bool compressed, int16_t datatype, bool swap, long long start, long long bytes)
{
  if (datatype != 16 && datatype != 64)
    return 0;
  NonFiniteCounter counter{ start, start + bytes, datatype == 16 ? 4 : 8, swap };
  if (compressed)
  {
    std::vector<unsigned char> none;
    long long produced = 0, consumed = 0;
    std::string message;
    amInflate::Stream(
      path, 0, 0, none, produced, consumed, message, [&](const unsigned char* p, size_t n) { counter.Feed(p, n); });
    return counter.Count;
  }
  std::ifstream in(path, std::ios::binary);
  in.seekg(start);
  counter.Position = start;
  std::vector<unsigned char> chunk(1 << 20);
  while (in && counter.Position < counter.End)
  {
    in.read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(chunk.size()));
    counter.Feed(chunk.data(), static_cast<size_t>(in.gcount()));
  }
  return counter.Count;
}

std::string NonFiniteMessage(long long count)
{
  return "it holds " + std::to_string(count) +
    " voxel(s) that are NaN or infinite, which ITK would read as 0 (a masked or failed computation?); "
    "replace them with a number before meshing or segmenting";
}

std::string Describe(double v)
{
  std::ostringstream os;
  os << v;
  return os.str();
}

/// The sform and the qform, when their codes say they are used; the problem, or "".
std::string CheckOrientation(const Header& h)
{
  const int16_t qcode = h.Get<int16_t>(252), scode = h.Get<int16_t>(254);
  if (scode > 0)
  {
    static const char* rows[3] = { "srow_x", "srow_y", "srow_z" };
    double m[3][4];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c)
      {
        m[r][c] = h.Get<float>(280 + 16 * r + 4 * c);
        if (!std::isfinite(m[r][c]))
          return std::string("its sform row ") + rows[r] + " holds a non-finite value (" + Describe(m[r][c]) + ")";
      }
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (det == 0)
      return "its sform (srow_x, srow_y, srow_z) is degenerate (determinant 0): it maps the voxels to a plane";
  }
  if (qcode > 0)
  {
    static const char* names[6] = { "quatern_b", "quatern_c", "quatern_d", "qoffset_x", "qoffset_y", "qoffset_z" };
    double q[6];
    for (int k = 0; k < 6; ++k)
    {
      q[k] = h.Get<float>(256 + 4 * k);
      if (!std::isfinite(q[k]))
        return std::string("its qform field ") + names[k] + " is non-finite (" + Describe(q[k]) + ")";
    }
    if (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] > 1.0 + 1e-4)
      return "its qform quaternion (quatern_b, quatern_c, quatern_d) has a norm above 1: not a rotation";
    if (!std::isfinite(h.Get<float>(76)))
      return "its qform factor (pixdim[0]) is non-finite";
  }
  return "";
}

/// The voxel data of a header and image pair (.hdr and .img, either compressed): all of it after
/// vox_offset; the problem, or "".
std::string CheckPairData(
  const std::string& path, bool compressed, const Header& h, bool swap, long long dataBytes, bool finiteVoxels)
{
  std::string img = path.substr(0, path.size() - (compressed ? 7 : 4)) + ".img";
  // A pipe or a device would block the reading (or never end).
  for (const std::string& data : { img, img + ".gz" })
    if (amInflate::FileSize(data) >= 0 && !amInflate::IsRegularFile(data))
      return "its data file '" + data + "' is not a regular file";
  long long bytes = amInflate::FileSize(img);
  if (bytes < 0 && amInflate::FileSize(img + ".gz") >= 0)
  {
    std::vector<unsigned char> none;
    const std::string why = Inflate(img + ".gz", 0, none, bytes);
    if (!why.empty())
      return "its data file '" + img + ".gz': " + why;
  }
  if (bytes < 0)
    return "its data file '" + img + "' does not exist";
  const float offset = h.Get<float>(108);
  if (std::isfinite(offset) && offset >= static_cast<float>(amByteCount::Limit - dataBytes))
    return "its voxel data offset (vox_offset) is " + Describe(offset) + ", past the end of any file";
  const long long start = std::isfinite(offset) && offset > 0 ? static_cast<long long>(offset) : 0;
  if (bytes < start + dataBytes)
    return "its data file '" + img + "' is truncated (" + std::to_string(bytes) + " bytes for the " +
      std::to_string(start + dataBytes) + " the header announces)";
  const bool imgCompressed = amInflate::FileSize(img) < 0;
  const long long nonFinite = !finiteVoxels
    ? 0
    : CountNonFinite(imgCompressed ? img + ".gz" : img, imgCompressed, h.Get<int16_t>(70), swap, start, dataBytes);
  if (nonFinite > 0)
    return NonFiniteMessage(nonFinite);
  return "";
}

}

bool amNiftiCheck::IsNifti(const std::string& path)
{
  return EndsWith(path, ".nii") || EndsWith(path, ".nii.gz") || EndsWith(path, ".hdr") || EndsWith(path, ".hdr.gz");
}

std::string amNiftiCheck::Check(const std::string& path, bool finiteVoxels)
{
  const bool compressed = EndsWith(path, ".gz");
  std::vector<unsigned char> head;
  long long total = -1;
  if (compressed)
  {
    const std::string why = Inflate(path, 352, head, total);
    if (!why.empty())
      return why;
  }
  else
  {
    std::ifstream in(path, std::ios::binary);
    head.resize(352);
    in.read(reinterpret_cast<char*>(head.data()), 352);
    head.resize(static_cast<size_t>(in.gcount()));
    total = amInflate::FileSize(path);
  }
  if (head.size() < 348)
    return "it is shorter than a NIfTI header (" + std::to_string(head.size()) + " of 348 bytes)";
  int32_t size;
  std::memcpy(&size, head.data(), 4);
  bool swap = false;
  if (size != 348)
  {
    int32_t swapped = size;
    unsigned char* p = reinterpret_cast<unsigned char*>(&swapped);
    std::reverse(p, p + 4);
    if (swapped == 540 || size == 540)
      return ""; // NIfTI-2: left to ITK
    if (swapped != 348)
      return "its header does not start with a NIfTI-1 size (348)";
    swap = true;
  }
  const Header h{ head.data(), swap };
  const bool single = std::memcmp(head.data() + 344, "n+1", 4) == 0;
  if (!single && std::memcmp(head.data() + 344, "ni1", 4) != 0)
    return "its header has no NIfTI-1 magic ('n+1' or 'ni1')";

  // Dimensions and voxel size.
  const int16_t rank = h.Get<int16_t>(40);
  if (rank < 1 || rank > 7)
    return "its header gives " + std::to_string(rank) + " dimensions (dim[0]); NIfTI allows 1 to 7";
  long long voxels = 1;
  for (int d = 1; d <= rank; ++d)
  {
    const int16_t n = h.Get<int16_t>(40 + 2 * d);
    if (n < 1)
      return "its header gives dim[" + std::to_string(d) + "] = " + std::to_string(n) +
        "; every dimension must be >= 1";
    if (!amByteCount::Multiply(voxels, n))
      return "its dimensions (dim) ask for more voxels than any file holds";
  }
  const int16_t bitpix = h.Get<int16_t>(72);
  if (bitpix <= 0 || bitpix % 8 != 0)
    return "its header gives " + std::to_string(bitpix) + " bits per voxel (bitpix)";
  long long dataBytes = voxels;
  if (!amByteCount::Multiply(dataBytes, bitpix / 8))
    return "its dimensions (dim) and bitpix ask for more voxel data than any file holds";
  static const char* axes[3] = { "x", "y", "z" };
  for (int d = 1; d <= std::min<int>(rank, 3); ++d)
  {
    const float s = h.Get<float>(76 + 4 * d);
    if (!std::isfinite(s) || s == 0)
      return std::string("its voxel size along ") + axes[d - 1] + " (pixdim[" + std::to_string(d) + "]) is " +
        Describe(s) + "; it must be a finite non-zero length";
  }

  const std::string orientation = CheckOrientation(h);
  if (!orientation.empty())
    return orientation;

  // The voxel data: all of it after vox_offset, in this file or in the .img beside the .hdr.
  if (single)
  {
    const float offset = h.Get<float>(108);
    if (!std::isfinite(offset) || offset < 348 || offset > static_cast<float>(amByteCount::Limit - dataBytes))
      return "its voxel data offset (vox_offset) is " + Describe(offset) +
        "; a single-file NIfTI needs at least 352 and at most the file's size";
    const long long need = static_cast<long long>(offset) + dataBytes;
    if (total < need)
      return "its voxel data is truncated: the header announces " + std::to_string(dataBytes) +
        " bytes of voxels from offset " + std::to_string(static_cast<long long>(offset)) + ", the " +
        std::string(compressed ? "decompressed " : "") + "file holds " +
        std::to_string(std::max(0LL, total - static_cast<long long>(offset))) +
        (offset > total ? " (the offset lies past its end)" : "");
    const long long nonFinite = !finiteVoxels
      ? 0
      : CountNonFinite(path, compressed, h.Get<int16_t>(70), swap, static_cast<long long>(offset), dataBytes);
    if (nonFinite > 0)
      return NonFiniteMessage(nonFinite);
  }
  else
    return CheckPairData(path, compressed, h, swap, dataBytes, finiteVoxels);

  return "";
}
