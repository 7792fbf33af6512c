#include "amImageReader.h"

#include "amHeaderText.h"

#include "amDicomSeries.h"
#include "amITKBridge.h"
#include "amInputCheck.h"
#include "amIntensityWindow.h"
#include "amMetaImageCheck.h"
#include "amNiftiCheck.h"
#include "amNrrdCheck.h"
#include "amProvenance.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <itkGDCMImageIO.h>
#include <itkGDCMImageIOFactory.h>
#include <itkImageFileReader.h>
#include <itkImageIOFactory.h>
#include <itkMetaImageIOFactory.h>

#include <itkNiftiImageIOFactory.h>
#include <itkNrrdImageIOFactory.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <numeric>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

vtkStandardNewMacro(amImageReader);

namespace
{
using amHeaderText::FolderOf;
using amHeaderText::Trim;

void RegisterITKFactories()
{
  static std::once_flag once;
  std::call_once(once, [] {
    itk::NiftiImageIOFactory::RegisterOneFactory();
    itk::NrrdImageIOFactory::RegisterOneFactory();
    itk::MetaImageIOFactory::RegisterOneFactory();
    itk::GDCMImageIOFactory::RegisterOneFactory();
  });
}

bool IsDirectory(const std::string& path)
{
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// A NRRD header with both "space" and per-axis "spacings" is invalid (the spec wants "space
// directions" then), and ITK refuses it; such files exist (VTK's headsq). Write a repaired copy
// without the "space" line and with an absolute data file path; returns its path, or "".
std::string RepairNrrdSpacingsWithSpace(const std::string& path)
{
  std::ifstream in(path);
  std::string line, out;
  bool changed = false;
  while (std::getline(in, line))
  {
    if (line.rfind("space:", 0) == 0)
    {
      changed = true;
      continue;
    }
    if (line.rfind("data file:", 0) == 0 || line.rfind("datafile:", 0) == 0)
    {
      const auto colon = line.find(':');
      std::string rest = Trim(line.substr(colon + 1));
      if (!rest.empty() && rest[0] != '/' && rest != "LIST")
        rest = FolderOf(path) + "/" + rest;
      line = line.substr(0, colon + 1) + " " + rest;
    }
    out += line + "\n";
  }
  if (!changed)
    return std::string();
  char tmpl[] = "/tmp/anatomesh-nrrd-XXXXXX.nhdr";
  const int fd = ::mkstemps(tmpl, 5);
  if (fd < 0)
    return std::string();
  const bool ok = ::write(fd, out.data(), out.size()) == static_cast<ssize_t>(out.size());
  ::close(fd);
  return ok ? std::string(tmpl) : std::string();
}

void AddString(vtkImageData* img, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  img->GetFieldData()->AddArray(a);
}
}

amImageReader::amImageReader()
  : FileName(nullptr)
  , SeriesUID(nullptr)
  , ResampleIrregularSeries(false)
  , OutputSliceSpacing(0.0)
  , IntensityWindow{ 0.0, 0.0 }
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

amImageReader::~amImageReader()
{
  this->SetFileName(nullptr);
  this->SetSeriesUID(nullptr);
}

bool amImageReader::CanReadFile(const char* path)
{
  if (!path)
    return false;
  const std::string p(path);
  if (IsDirectory(p))
    return true;
  static const char* exts[] = { ".nii", ".nii.gz", ".nrrd", ".nhdr", ".mha", ".mhd", ".dcm" };
  std::string lower = p;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  for (const char* e : exts)
  {
    const std::string ext(e);
    if (lower.size() > ext.size() && lower.compare(lower.size() - ext.size(), ext.size(), ext) == 0)
      return true;
  }
  return false;
}

bool amImageReader::LoadFile(const std::string& path)
{
  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::ReadMode);
  if (!io)
  {
    // ITK recognises none of its formats: when the name says which one it should be, say why not.
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    const auto endsWith = [&](const std::string& end) {
      return lower.size() >= end.size() && lower.compare(lower.size() - end.size(), end.size(), end) == 0;
    };
    const std::string why = amNiftiCheck::IsNifti(lower) ? amNiftiCheck::Check(path)
      : endsWith(".nrrd") || endsWith(".nhdr")           ? amNrrdCheck::Check(path)
                                                         : std::string();
    if (!why.empty())
    {
      vtkErrorMacro("Cannot read '" << path << "': " << why << ".");
      return false;
    }
    vtkErrorMacro(
      "Cannot read '" << path << "': not a NIfTI, NRRD, MetaImage or DICOM file, or its header is corrupt.");
    return false;
  }
  if (dynamic_cast<itk::GDCMImageIO*>(io.GetPointer()))
    return this->LoadDicomSeries(FolderOf(path), path);
  std::string format = io->GetNameOfClass();
  // Before ITK: it zero-fills truncated NIfTI data, aborts on a NaN in a sform, reads a NaN NRRD
  // spacing as 1, blocks on a data file that is a pipe, and leaves the end of an understated
  // compressed MetaImage undefined.
  struct RemoveRepaired
  {
    std::string Path;
    ~RemoveRepaired()
    {
      if (!Path.empty())
        std::remove(Path.c_str());
    }
  } nrrdRepaired, metaRepaired;
  std::string problem;
  if (format.find("Nifti") != std::string::npos)
    problem = amNiftiCheck::Check(path);
  else if (format.find("Nrrd") != std::string::npos)
    problem = amNrrdCheck::Check(path);
  else if (format.find("Meta") != std::string::npos)
    problem = amMetaImageCheck::Check(path, metaRepaired.Path);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot read '" << path << "': " << problem << ".");
    return false;
  }
  std::string readPath = path;
  if (!metaRepaired.Path.empty())
  {
    vtkWarningMacro("'" << path
                        << "' understates its CompressedDataSize; read with the size of the actual "
                           "compressed stream (ITK would otherwise leave the last voxels undefined).");
    readPath = metaRepaired.Path;
  }
  try
  {
    io->SetFileName(readPath);
    io->ReadImageInformation();
  }
  catch (const itk::ExceptionObject& e)
  {
    const std::string what = e.what();
    if (format.find("Nrrd") != std::string::npos &&
      what.find("nrrdSpacingStatusScalarWithSpace") != std::string::npos &&
      !(nrrdRepaired.Path = RepairNrrdSpacingsWithSpace(path)).empty())
    {
      vtkWarningMacro("'" << path
                          << "' gives both 'space' and per-axis 'spacings', which NRRD forbids; read it "
                             "ignoring the 'space' line (identity direction, spacings kept).");
      readPath = nrrdRepaired.Path;
      try
      {
        io->SetFileName(readPath);
        io->ReadImageInformation();
      }
      catch (const itk::ExceptionObject& e2)
      {
        vtkErrorMacro("Cannot read the header of '" << path << "': " << amITK::Description(e2.what()));
        return false;
      }
    }
    else
    {
      vtkErrorMacro("Cannot read the header of '" << path << "': " << amITK::Description(what));
      return false;
    }
  }
  const unsigned dim = io->GetNumberOfDimensions();
  if (dim < 2 || dim > 4 || (dim == 4 && io->GetDimensions(3) != 1))
  {
    vtkErrorMacro("'" << path << "' has " << dim << " dimensions" << (dim == 4 ? " with more than one volume" : "")
                      << "; a 2-D or 3-D scalar image is needed.");
    return false;
  }
  if (io->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("'" << path << "' has " << io->GetNumberOfComponents()
                      << " components per voxel; Anatomesh reads scalar (one-component) images.");
    return false;
  }
  for (unsigned d = 0; d < std::min(3u, dim); ++d)
    if (io->GetDimensions(d) == 0 || !(io->GetSpacing(d) > 0.0) || !std::isfinite(io->GetSpacing(d)))
    {
      vtkErrorMacro("'" << path << "' has an invalid size or spacing along axis " << d << " (size "
                        << io->GetDimensions(d) << ", spacing " << io->GetSpacing(d) << ").");
      return false;
    }
  bool ok = false;
  std::string error;
  const bool known = amITK::DispatchComponent(io->GetComponentType(), [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    using ReaderType = itk::ImageFileReader<amITK::Image3<T>>;
    auto reader = ReaderType::New();
    reader->SetImageIO(io);
    reader->SetFileName(readPath);
    try
    {
      reader->Update();
      this->Cache = amITK::ToVTK<T>(reader->GetOutput(), "ImageScalars");
      ok = true;
    }
    catch (const itk::ExceptionObject& e)
    {
      error = amITK::Description(e.what());
    }
  });
  if (!known)
  {
    vtkErrorMacro("'" << path << "' has an unsupported pixel type ("
                      << itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()) << ").");
    return false;
  }
  if (!ok)
  {
    vtkErrorMacro("Cannot read the voxels of '" << path << "' (corrupt or truncated?): " << error);
    return false;
  }
  if (format.find("Nifti") != std::string::npos)
    format = "NIfTI";
  else if (format.find("Nrrd") != std::string::npos)
    format = "NRRD";
  else if (format.find("Meta") != std::string::npos)
    format = "MetaImage";
  AddString(this->Cache, "SourceFormat", format);
  return true;
}

bool amImageReader::LoadDicomSeries(const std::string& folder, const std::string& onlyFile)
{
  amDicomSeries::Request request;
  request.Folder = folder;
  request.OnlyFile = onlyFile;
  request.SeriesUID = this->SeriesUID ? this->SeriesUID : "";
  request.ResampleIrregular = this->ResampleIrregularSeries;
  request.OutputSliceSpacing = this->OutputSliceSpacing;
  amDicomSeries::Result series = amDicomSeries::Read(request);
  if (!series.Image)
  {
    vtkErrorMacro(<< series.Error);
    return false;
  }
  this->Cache = series.Image;
  AddString(this->Cache, "SourceFormat", "DICOM");
  AddString(this->Cache, "SeriesInstanceUID", series.SeriesUID);
  if (!series.Modality.empty())
    AddString(this->Cache, "Modality", series.Modality);
  if (!series.Resampling.empty())
    AddString(this->Cache, "Resampling", series.Resampling);
  return true;
}

bool amImageReader::Load()
{
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return false;
  }
  const std::string path(this->FileName);
  std::ostringstream key;
  key << path << "|" << (this->SeriesUID ? this->SeriesUID : "") << "|" << this->ResampleIrregularSeries << "|"
      << this->OutputSliceSpacing << "|" << this->IntensityWindow[0] << "," << this->IntensityWindow[1];
  if (this->Cache && this->CacheKey == key.str() && this->CacheTime >= this->GetMTime())
    return true;
  this->Cache = nullptr;
  this->CacheKey.clear();
  std::string why;
  if (!amInputCheck::ReadableFile(path, true, why))
  {
    vtkErrorMacro("Cannot read the image: " << why);
    return false;
  }
  RegisterITKFactories();
  const bool ok = IsDirectory(path) ? this->LoadDicomSeries(path, std::string()) : this->LoadFile(path);
  if (!ok)
  {
    this->Cache = nullptr;
    return false;
  }
  if (!this->CheckWindow(path))
  {
    this->Cache = nullptr;
    return false;
  }
  const double* dm = this->Cache->GetDirectionMatrix()->GetData();
  AddString(this->Cache, "SourceOrientation", amITK::OrientationCode(dm));
  std::ostringstream params;
  params << "FileName=" << path;
  if (this->ResampleIrregularSeries)
    params << " ResampleIrregularSeries=1 OutputSliceSpacing=" << this->OutputSliceSpacing;
  if (this->IntensityWindow[0] > 0.0)
    params << " IntensityWindow=" << this->IntensityWindow[0] << "," << this->IntensityWindow[1];
  amProvenance::Record(this->Cache, nullptr, "amImageReader", params.str());
  this->CacheKey = key.str();
  this->CacheTime = this->GetMTime();
  return true;
}

bool amImageReader::CheckWindow(const std::string& path)
{
  if (this->IntensityWindow[0] == 0.0 && this->IntensityWindow[1] == 0.0)
    return true;
  if (!(this->IntensityWindow[0] > 0.0) || !std::isfinite(this->IntensityWindow[1]))
  {
    vtkErrorMacro(<< "IntensityWindow " << this->IntensityWindow[0] << " " << this->IntensityWindow[1]
                  << " is not a window: its width (HU) must be positive, its level finite.");
    return false;
  }
  double range[2];
  this->Cache->GetPointData()->GetScalars()->GetRange(range, 0);
  if (range[0] < 0.0 || range[1] > 255.0)
  {
    vtkErrorMacro(<< "IntensityWindow says " << path << " holds 0..255 made through a window, but its values span "
                  << range[0] << " .. " << range[1] << ".");
    return false;
  }
  amIntensityWindow::Record(this->Cache, this->IntensityWindow);
  return true;
}

int amImageReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->Load())
    return 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  this->Cache->GetExtent(extent);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), this->Cache->GetSpacing(), 3);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Cache->GetOrigin(), 3);
  outInfo->Set(vtkDataObject::DIRECTION(), this->Cache->GetDirectionMatrix()->GetData(), 9);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, this->Cache->GetScalarType(), 1);
  return 1;
}

int amImageReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->Load())
    return 0;
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  output->ShallowCopy(this->Cache);
  this->UpdateProgress(1.0);
  return 1;
}

void amImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SeriesUID: " << (this->SeriesUID ? this->SeriesUID : "(none)") << "\n";
  os << indent << "ResampleIrregularSeries: " << this->ResampleIrregularSeries << "\n";
  os << indent << "OutputSliceSpacing: " << this->OutputSliceSpacing << "\n";
  os << indent << "IntensityWindow: " << this->IntensityWindow[0] << " " << this->IntensityWindow[1] << "\n";
}
