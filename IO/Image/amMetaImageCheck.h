/**
 * @class   amMetaImageCheck
 * @brief   Checks a MetaImage file (.mha, .mhd with its data file) before ITK reads it: the voxel
 *          data all there, a compressed stream inflated to count its bytes.
 *
 * ITK's MetaImage reader accepts a short data file (it only prints to stderr), and inflates only
 * CompressedDataSize bytes, leaving the rest of the image uninitialised when the header understates
 * it (VTK's frogtissue.mhd says 260020 of 262087 bytes). Such a header is repaired: a temporary copy
 * with the true size and an absolute data file path.
 *
 * @sa amImageReader amNiftiCheck
 */
#ifndef amMetaImageCheck_h
#define amMetaImageCheck_h

#include <string>

class amMetaImageCheck
{
public:
  /// "" when the file can be read fully; otherwise what is wrong. 'repairedHeader' gets the path
  /// of a repaired temporary header when one is needed (else "").
  static std::string Check(const std::string& path, std::string& repairedHeader);
};

#endif
