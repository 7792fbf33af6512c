/**
 * @class   amImageWriter
 * @brief   Writes a vtkImageData (a label map or a scan) to NIfTI (.nii, .nii.gz), MetaImage
 *          (.mha, .mhd) or NRRD (.nrrd) through ITK, keeping origin, spacing and direction.
 *
 * The format follows the file name's extension. The active point scalars are written with
 * their own component type (a label map stays 8-bit). The file appears atomically: it is written
 * under a temporary name in the same folder and renamed when complete, so a failure never leaves a
 * half-written file (for .mhd, the .raw companion is renamed first).
 * UseCompression (default on) compresses MetaImage and NRRD data; .nii.gz is always compressed,
 * at CompressionLevel (the plain .nii is written first, beside it, so the disk needs room for both
 * while the file is written).
 * A label map with field data "LabelNames" gets its colour and name tables beside it,
 * "<name>.ctbl" (amLabelTable: "value name R G B A" lines, read by 3D Slicer) and
 * "<name>.itksnap.txt" (ITK-SNAP's label description file), since NIfTI, MetaImage and NRRD
 * files keep no label names.
 */
#ifndef amImageWriter_h
#define amImageWriter_h

#include "AnatomeshIOImageModule.h" // export macro
#include "vtkImageAlgorithm.h"

class ANATOMESHIOIMAGE_EXPORT amImageWriter : public vtkImageAlgorithm
{
public:
  static amImageWriter* New();
  vtkTypeMacro(amImageWriter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Target file; its extension picks the format.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Compress the voxel data where the format allows it (default on).
  vtkSetMacro(UseCompression, bool);
  vtkGetMacro(UseCompression, bool);
  vtkBooleanMacro(UseCompression, bool);
  ///@}

  ///@{
  /// The zlib level of a .nii.gz file: 1 (fastest, the default) to 9 (smallest). The voxels read
  /// back the same at every level; on a noisy scan the higher levels cost much time for a file
  /// only a little smaller.
  vtkSetClampMacro(CompressionLevel, int, 1, 9);
  vtkGetMacro(CompressionLevel, int);
  ///@}

  /// Write the input to FileName. Returns 1 on success, 0 on error (reported with vtkErrorMacro).
  int Write();

protected:
  amImageWriter();
  ~amImageWriter() override;

  int FillOutputPortInformation(int, vtkInformation*) override { return 1; }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;
  bool UseCompression;
  int CompressionLevel;

private:
  bool LastWriteOk = false;
  amImageWriter(const amImageWriter&) = delete;
  void operator=(const amImageWriter&) = delete;
};

#endif
