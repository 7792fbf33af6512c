/**
 * @class   amInflate
 * @brief   A compressed voxel stream (zlib or gzip) inflated to its end, to count its bytes and
 *          check it; and a file's size. Shared by the reader's MetaImage and NIfTI checks.
 */
#ifndef amInflate_h
#define amInflate_h

#include <functional>
#include <string>
#include <vector>

class amInflate
{
public:
  enum Status
  {
    Complete,  // the stream reached its end (a gzip CRC checked)
    Truncated, // the file ended before the stream
    Corrupt    // zlib refused the data; 'message' says why
  };
  /// Inflates the stream of 'path' from byte 'offset'. 'produced' and 'consumed' count the bytes
  /// out and in; the first 'keep' bytes out go to 'kept' (appended).
  /// Every byte out also goes to 'sink', when given, in order.
  static Status Stream(const std::string& path, long long offset, size_t keep, std::vector<unsigned char>& kept,
    long long& produced, long long& consumed, std::string& message,
    const std::function<void(const unsigned char*, size_t)>& sink = nullptr);
  /// The size of a file in bytes, -1 when it does not exist.
  static long long FileSize(const std::string& path);
  /// Whether the path names a regular file (not a folder, a pipe or a device, which a header's
  /// data file field may name and which would block or never end).
  static bool IsRegularFile(const std::string& path);
};

#endif
