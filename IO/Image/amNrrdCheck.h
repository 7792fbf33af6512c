/**
 * @class   amNrrdCheck
 * @brief   Checks a NRRD file (.nrrd, or a detached .nhdr with its data file) before ITK reads it:
 *          a finite, non-degenerate geometry, dimensions whose voxels fit in a size, and all the
 *          voxel data there (a gzip stream inflated to its end, its CRC checked).
 *
 * ITK (through teem) reads a "nan" spacing as 1 mm without a word, allocates whatever the sizes ask
 * before finding the data short, and blocks reading a data file that is a pipe or a device. Each of
 * those is a message here naming the field. Encodings other than raw and gzip (ascii, hex, bzip2),
 * data files given as a list or a pattern, and "line skip" are left to teem, which checks them.
 *
 * Reference: the NRRD format, version 5 (teem, http://teem.sourceforge.net/nrrd/format.html).
 *
 * @sa amImageReader amNiftiCheck amMetaImageCheck
 */
#ifndef amNrrdCheck_h
#define amNrrdCheck_h

#include <string>

class amNrrdCheck
{
public:
  /// "" when the file can be read fully; otherwise what is wrong (the caller names the file).
  static std::string Check(const std::string& path);
};

#endif
