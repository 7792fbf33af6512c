/**
 * @class   amNiftiCheck
 * @brief   Checks a NIfTI-1 file (.nii, .nii.gz, or a .hdr/.img pair) before ITK reads it: the
 *          header's geometry is finite and not degenerate, its dimensions plausible, and the voxel
 *          data all there (a compressed stream inflated to its end, its CRC checked).
 *
 * ITK's NIfTI reader zero-fills what a truncated file lacks, reads a corrupt deflate stream or a
 * bad CRC without a word, allocates whatever the dimensions ask before finding the data missing,
 * and aborts the process (in VNL) on a NaN in the sform. Each of those is a message here, naming
 * the file and the field. NIfTI-2 headers are left to ITK.
 *
 * Reference: the NIfTI-1 data format, nifti1.h (NIMH Data Format Working Group, 2004).
 *
 * @sa amImageReader
 */
#ifndef amNiftiCheck_h
#define amNiftiCheck_h

#include <string>

class amNiftiCheck
{
public:
  /// Whether the path names a NIfTI file by its extension (.nii, .nii.gz, .hdr, .hdr.gz).
  static bool IsNifti(const std::string& path);
  /// "" when the file can be read fully; otherwise what is wrong (the caller names the file).
  /// 'finiteVoxels': float voxels that are NaN or infinite are wrong too (ITK reads them as 0).
  static std::string Check(const std::string& path, bool finiteVoxels = true);
};

#endif
