/**
 * @class   amCachedZLibCompressor
 * @brief   vtkZLibDataCompressor that hands back the compressed bytes of a block it has compressed
 *          before (the same bytes, level and size), for time series whose frames share geometry.
 *
 * A time series writes the same points and cells in every frame: each of their 32 kB blocks
 * deflated once, then found again by a 64-bit hash and compared byte for byte. The cache is
 * shared between compressors (one per file, on several threads) and holds up to a set amount of
 * input bytes; past that it starts anew. It reports the class name of VTK's zlib compressor, so
 * the files name the format they are in, bit for bit what vtkZLibDataCompressor writes.
 * Not wrapped: amConcurrentXMLWriter's helper.
 */
#ifndef amCachedZLibCompressor_h
#define amCachedZLibCompressor_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkZLibDataCompressor.h"

#include <cstddef>
#include <memory>

class ANATOMESHIOMESH_EXPORT amCachedZLibCompressor : public vtkZLibDataCompressor
{
public:
  using Superclass = vtkZLibDataCompressor; // no vtkTypeMacro: the class name stays VTK's

  /// The blocks met so far, shared by compressors on any thread.
  class Cache;
  static std::shared_ptr<Cache> NewCache(std::size_t maximumBytes = 32u << 20);

  static amCachedZLibCompressor* New();
  void SetCache(std::shared_ptr<Cache> cache);

protected:
  amCachedZLibCompressor() = default;
  ~amCachedZLibCompressor() override = default;
  const char* GetClassNameInternal() const override { return "vtkZLibDataCompressor"; }
  std::size_t CompressBuffer(unsigned char const* uncompressedData, std::size_t uncompressedSize,
    unsigned char* compressedData, std::size_t compressionSpace) override;

private:
  amCachedZLibCompressor(const amCachedZLibCompressor&) = delete;
  void operator=(const amCachedZLibCompressor&) = delete;

  std::shared_ptr<Cache> Blocks;
};

#endif
