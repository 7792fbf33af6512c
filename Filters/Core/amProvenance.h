/**
 * @class   amProvenance
 * @brief   Records how a data object was made, in its field data "Provenance".
 *
 * Every Anatomesh filter appends one entry ("<filter> <version>: <parameters> [input: ...]")
 * to a vtkStringArray named "Provenance" in the output's field data, after copying the entries of
 * its input, so a mesh written at the end of a pipeline says every step that made it.
 */
#ifndef amProvenance_h
#define amProvenance_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <string>

class vtkDataObject;

class ANATOMESHFILTERSCORE_EXPORT amProvenance
{
public:
  /// The Anatomesh version string ("0.1.0").
  static const char* Version();

  /// Append "<filter> <version>: <parameters>" to output's Provenance, after the entries
  /// carried by input (may be null).
  static void Record(
    vtkDataObject* output, vtkDataObject* input, const std::string& filter, const std::string& parameters);

  /// All entries of obj's Provenance joined by newlines (empty if none).
  static std::string Get(vtkDataObject* obj);
};

#endif
