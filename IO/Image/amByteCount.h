// Internal: byte counts from the fields of an image header, without overflow. A header's
// dimensions are whatever its bytes say; their product must not wrap before it is compared with
// the data there is.
#ifndef amByteCount_h
#define amByteCount_h

namespace amByteCount
{
/// Beyond any file this reader takes (2^62 bytes).
constexpr long long Limit = 1LL << 62;

/// value *= factor when both are >= 0 and the product stays within Limit; false otherwise
/// (value unchanged).
inline bool Multiply(long long& value, long long factor)
{
  if (value < 0 || factor < 0)
    return false;
  if (factor != 0 && value > Limit / factor)
    return false;
  value *= factor;
  return true;
}
}

#endif
