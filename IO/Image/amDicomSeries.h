// Internal: one DICOM series read from a folder as one volume. The series is picked by its UID, by a
// file of it, or as the only one; every slice's geometry is checked (orientation, coincident slices,
// gantry tilt, uneven gaps), and an irregular stack is refused or resampled onto a regular grid
// aligned with its slices. amImageReader is its face.
#ifndef amDicomSeries_h
#define amDicomSeries_h

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <string>

namespace amDicomSeries
{
struct Request
{
  std::string Folder;
  std::string OnlyFile;  ///< a file of the series to read ("": the folder's only series)
  std::string SeriesUID; ///< the SeriesInstanceUID to read ("": by OnlyFile or the only one)
  bool ResampleIrregular = false;
  double OutputSliceSpacing = 0.0; ///< mm; 0: the smallest gap of the stack
};

struct Result
{
  vtkSmartPointer<vtkImageData> Image; ///< with field data SourceFormat, SeriesInstanceUID, Modality, Resampling
  std::string Error;                   ///< the whole message when Image is null
  std::string SeriesUID;               ///< the series read
  std::string Modality;                ///< DICOM Modality (0008,0060), "" when absent
  std::string Resampling;              ///< how an irregular stack was resampled, "" when it was regular
};

Result Read(const Request& request);
}

#endif
