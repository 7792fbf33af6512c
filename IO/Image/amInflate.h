/**
 * @class   amInflate
 * @brief   A compressed voxel stream (zlib or gzip) inflated to its end, to count its bytes and
 *          check it; and a file's size. Shared by the reader's MetaImage and NIfTI checks.
 */
#ifndef amInflate_h
#define amInflate_h

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
  static Status Stream(const std::string& path, long long offset, size_t keep, std::vector<unsigned char>& kept,
    long long& produced, long long& consumed, std::string& message);
  /// The size of a file in bytes, -1 when it does not exist.
  static long long FileSize(const std::string& path);
};

#endif
