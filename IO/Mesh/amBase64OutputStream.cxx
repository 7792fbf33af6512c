#include "amBase64OutputStream.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(amBase64OutputStream);

namespace
{
const char Alphabet[65] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

inline void Triplet(const unsigned char* in, char* out)
{
  out[0] = Alphabet[in[0] >> 2];
  out[1] = Alphabet[((in[0] << 4) & 0x30) | (in[1] >> 4)];
  out[2] = Alphabet[((in[1] << 2) & 0x3c) | (in[2] >> 6)];
  out[3] = Alphabet[in[2] & 0x3f];
}
}

int amBase64OutputStream::StartWriting()
{
  if (!this->Superclass::StartWriting())
    return 0;
  this->PendingLength = 0;
  return 1;
}

int amBase64OutputStream::Write(void const* data, size_t length)
{
  const unsigned char* in = static_cast<const unsigned char*>(data);
  const unsigned char* end = in + length;
  // A triplet begun by the last call, completed first.
  while (this->PendingLength > 0 && this->PendingLength < 3 && in != end)
    this->Pending[this->PendingLength++] = *in++;
  char head[4];
  const bool completed = this->PendingLength == 3;
  if (completed)
  {
    Triplet(this->Pending, head);
    this->PendingLength = 0;
    if (!this->Stream->write(head, 4))
      return 0;
  }
  // Whole triplets in blocks of up to 48 kB in, 64 kB out: one write each.
  const size_t block = 3 << 14;
  while (end - in >= 3)
  {
    const size_t n = std::min(block, static_cast<size_t>(end - in) / 3 * 3);
    this->Encoded.resize(n / 3 * 4);
    char* out = this->Encoded.data();
    for (size_t i = 0; i < n; i += 3, out += 4)
      Triplet(in + i, out);
    if (!this->Stream->write(this->Encoded.data(), static_cast<std::streamsize>(this->Encoded.size())))
      return 0;
    in += n;
  }
  while (in != end)
    this->Pending[this->PendingLength++] = *in++;
  return 1;
}

int amBase64OutputStream::EndWriting()
{
  if (this->PendingLength == 0)
    return 1;
  const unsigned char* p = this->Pending;
  char out[4] = { Alphabet[p[0] >> 2], '=', '=', '=' };
  if (this->PendingLength == 1)
    out[1] = Alphabet[(p[0] << 4) & 0x30];
  else
  {
    out[1] = Alphabet[((p[0] << 4) & 0x30) | (p[1] >> 4)];
    out[2] = Alphabet[(p[1] << 2) & 0x3c];
  }
  this->PendingLength = 0;
  return this->Stream->write(out, 4) ? 1 : 0;
}
