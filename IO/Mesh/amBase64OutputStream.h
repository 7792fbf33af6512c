/**
 * @class   amBase64OutputStream
 * @brief   The base64 stream of VTK's XML writers in "binary" mode, encoding whole blocks into
 *          one write each: the same bytes as vtkBase64OutputStream, which writes every four
 *          characters through the ostream on their own.
 *
 * amConcurrentXMLWriter's writers use it (VTK's XML writers take it through their protected
 * SetDataStream). Not wrapped.
 */
#ifndef amBase64OutputStream_h
#define amBase64OutputStream_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkOutputStream.h"

#include <vector>

class ANATOMESHIOMESH_EXPORT amBase64OutputStream : public vtkOutputStream
{
public:
  static amBase64OutputStream* New();
  vtkTypeMacro(amBase64OutputStream, vtkOutputStream);

  int StartWriting() override;
  /// Encodes 'data', keeping up to two bytes for the next call (base64 encodes triplets).
  int Write(void const* data, size_t length) override;
  /// The last one or two bytes, padded with '='.
  int EndWriting() override;

protected:
  amBase64OutputStream() = default;
  ~amBase64OutputStream() override = default;

private:
  unsigned char Pending[3] = { 0, 0, 0 };
  unsigned int PendingLength = 0;
  std::vector<char> Encoded;
  amBase64OutputStream(const amBase64OutputStream&) = delete;
  void operator=(const amBase64OutputStream&) = delete;
};

#endif
