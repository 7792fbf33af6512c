/**
 * @class   amImageReader
 * @brief   Reads a CT or MR volume: NIfTI (.nii, .nii.gz), NRRD (.nrrd, .nhdr), MetaImage
 *          (.mha, .mhd) or a DICOM series (a folder, or one file of the series), through ITK ImageIO.
 *
 * The output vtkImageData keeps the scan's geometry: origin, spacing and direction (the
 * index-to-LPS rotation, set with vtkImageData::SetDirectionMatrix), so world coordinates are
 * patient coordinates in millimetres (DICOM/ITK LPS convention). Rescale slope/intercept are
 * applied (CT comes out in Hounsfield units). Scalars are named "ImageScalars" and keep the file's
 * component type. Field data records "SourceFormat", "SourceOrientation" (three letters naming
 * where the i, j, k axes point, e.g. "RAS" for a NIfTI in radiological convention), "Modality"
 * (DICOM) and "Provenance".
 *
 * A DICOM series whose slices are not stacked along the slice normal (gantry tilt) or whose
 * gaps are uneven cannot be a regular grid as it stands. By default the reader refuses it with a
 * message that gives the tilt angle and the range of gaps; with ResampleIrregularSeries on, it
 * resamples the series onto a regular grid aligned with the slices (in-plane spacing kept,
 * normal spacing = the smallest gap unless OutputSliceSpacing is set), trilinearly, so no anatomy
 * is warped. A folder with several series reads the one named by SeriesUID; without it, the
 * reader refuses the folder and lists its series (UID and file count).
 *
 * Errors (missing file, unknown format, corrupt or truncated data, more than one component,
 * empty series) are reported with vtkErrorMacro naming the file; no output is produced. A NIfTI
 * file is checked before ITK reads it (amNiftiCheck): its compressed stream to the end with its
 * CRC, its voxel data against its dimensions and offset, its sform, qform and voxel sizes finite
 * and not degenerate, each refusal naming the field.
 *
 * @sa amImageWriter amNiftiCheck
 */
#ifndef amImageReader_h
#define amImageReader_h

#include "AnatomeshIOImageModule.h" // export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h"

#include <string>

class ANATOMESHIOIMAGE_EXPORT amImageReader : public vtkImageAlgorithm
{
public:
  static amImageReader* New();
  vtkTypeMacro(amImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// A volume file, or a folder that holds a DICOM series.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// DICOM only: the SeriesInstanceUID to read when a folder holds several (empty: the largest).
  vtkSetStringMacro(SeriesUID);
  vtkGetStringMacro(SeriesUID);
  ///@}

  ///@{
  /// DICOM only: resample a tilted or unevenly spaced series onto a regular grid instead of
  /// refusing it (default off).
  vtkSetMacro(ResampleIrregularSeries, bool);
  vtkGetMacro(ResampleIrregularSeries, bool);
  vtkBooleanMacro(ResampleIrregularSeries, bool);
  ///@}

  ///@{
  /// DICOM resampling only: slice spacing (mm) of the regular grid; 0 (default) = smallest gap.
  vtkSetClampMacro(OutputSliceSpacing, double, 0.0, 100.0);
  vtkGetMacro(OutputSliceSpacing, double);
  ///@}

  ///@{
  /// The window (width, level; HU) a file that holds 0..255 was made through, when the file does
  /// not say (a CT exported for viewing). Default 0 0: the file holds HU (or MR intensities) as
  /// they are. Set, the reader checks the values lie in 0..255 and records the window in the
  /// output's field data "IntensityWindow" (amIntensityWindow), from which the filters whose
  /// settings are in HU (Snake Segmentation, Torso Segmentation) convert them.
  vtkSetVector2Macro(IntensityWindow, double);
  vtkGetVector2Macro(IntensityWindow, double);
  ///@}

  /// Whether this reader can read the path (by extension, or a folder); a cheap test.
  static bool CanReadFile(const char* path);

protected:
  amImageReader();
  ~amImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;
  char* SeriesUID;
  bool ResampleIrregularSeries;
  double OutputSliceSpacing;
  double IntensityWindow[2];

private:
  bool Load();
  bool LoadFile(const std::string& path);
  bool LoadDicomSeries(const std::string& folder, const std::string& onlyFile);
  /// Checks the values against IntensityWindow, when it is set, and records it; false (with an
  /// error) when they leave 0..255 or the window is not one.
  bool CheckWindow(const std::string& path);

  vtkSmartPointer<vtkImageData> Cache;
  vtkMTimeType CacheTime = 0;
  std::string CacheKey;

  amImageReader(const amImageReader&) = delete;
  void operator=(const amImageReader&) = delete;
};

#endif
