#include "amCachedZLibCompressor.h"

#include "vtkObjectFactory.h"

#include <cstdint>
#include <cstring>
#include <mutex>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(amCachedZLibCompressor);

class amCachedZLibCompressor::Cache
{
public:
  explicit Cache(std::size_t most)
    : Most(most)
  {
  }

  /// The compressed bytes of 'raw' at 'level' into 'out' (at most 'space'): their size, 0 if unknown.
  std::size_t Find(
    std::uint64_t key, const unsigned char* raw, std::size_t n, int level, unsigned char* out, std::size_t space)
  {
    std::lock_guard<std::mutex> lock(this->Lock);
    const auto range = this->Blocks.equal_range(key);
    for (auto it = range.first; it != range.second; ++it)
    {
      const Block& b = it->second;
      if (b.Level == level && b.Raw.size() == n && b.Packed.size() <= space && std::memcmp(b.Raw.data(), raw, n) == 0)
      {
        std::memcpy(out, b.Packed.data(), b.Packed.size());
        return b.Packed.size();
      }
    }
    return 0;
  }

  void Add(
    std::uint64_t key, const unsigned char* raw, std::size_t n, int level, const unsigned char* packed, std::size_t m)
  {
    std::lock_guard<std::mutex> lock(this->Lock);
    if (this->Bytes + n > this->Most)
    {
      this->Blocks.clear();
      this->Bytes = 0;
    }
    Block b;
    b.Level = level;
    b.Raw.assign(raw, raw + n);
    b.Packed.assign(packed, packed + m);
    this->Blocks.emplace(key, std::move(b));
    this->Bytes += n;
  }

private:
  struct Block
  {
    int Level = 0;
    std::vector<unsigned char> Raw, Packed;
  };
  std::mutex Lock;
  std::unordered_multimap<std::uint64_t, Block> Blocks;
  std::size_t Bytes = 0, Most;
};

std::shared_ptr<amCachedZLibCompressor::Cache> amCachedZLibCompressor::NewCache(std::size_t maximumBytes)
{
  return std::make_shared<Cache>(maximumBytes);
}

void amCachedZLibCompressor::SetCache(std::shared_ptr<Cache> cache)
{
  this->Blocks = std::move(cache);
}

namespace
{
/// A 64-bit hash of the block, eight bytes at a step (a key only: equal blocks are compared).
std::uint64_t Hash(const unsigned char* data, std::size_t n)
{
  std::uint64_t h = 1469598103934665603ull ^ n;
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8)
  {
    std::uint64_t w;
    std::memcpy(&w, data + i, 8);
    h = (h ^ w) * 1099511628211ull;
    h ^= h >> 29;
  }
  for (; i < n; ++i)
    h = (h ^ data[i]) * 1099511628211ull;
  return h;
}
}

std::size_t amCachedZLibCompressor::CompressBuffer(unsigned char const* uncompressedData, std::size_t uncompressedSize,
  unsigned char* compressedData, std::size_t compressionSpace)
{
  // Small blocks (the last of an array, small arrays) are cheaper to deflate than to keep.
  if (!this->Blocks || uncompressedSize < 4096)
    return this->Superclass::CompressBuffer(uncompressedData, uncompressedSize, compressedData, compressionSpace);
  const int level = this->GetCompressionLevel();
  const std::uint64_t key = Hash(uncompressedData, uncompressedSize);
  if (const std::size_t found =
        this->Blocks->Find(key, uncompressedData, uncompressedSize, level, compressedData, compressionSpace))
    return found;
  const std::size_t m =
    this->Superclass::CompressBuffer(uncompressedData, uncompressedSize, compressedData, compressionSpace);
  if (m > 0)
    this->Blocks->Add(key, uncompressedData, uncompressedSize, level, compressedData, m);
  return m;
}
