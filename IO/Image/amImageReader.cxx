#include "amImageReader.h"

#include "amHeaderText.h"

#include "amITKBridge.h"
#include "amInputCheck.h"
#include "amMetaImageCheck.h"
#include "amNiftiCheck.h"
#include "amNrrdCheck.h"
#include "amProvenance.h"

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
#include <itkGDCMSeriesFileNames.h>
#include <itkImageFileReader.h>
#include <itkImageIOFactory.h>
#include <itkImageSeriesReader.h>
#include <itkMetaImageIOFactory.h>

#include <itkNiftiImageIOFactory.h>
#include <itkNrrdImageIOFactory.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <dirent.h>
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

std::string FirstLine(const std::string& text)
{
  // ITK messages carry the source location first; keep the description, on one line.
  std::string t = text;
  const auto desc = t.find("Description: ");
  if (desc != std::string::npos)
    t = t.substr(desc + 13);
  t = amITK::WithoutLocation(t);
  std::replace(t.begin(), t.end(), '\n', ' ');
  return t;
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

// The geometry of one DICOM slice.
struct Slice
{
  std::string File;
  double Position[3];
  double Offset; // along the slice normal
};

struct Vec
{
  static double Dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
};

// Trilinear resampling of an irregular (tilted and/or unevenly spaced) stack of parallel slices
// onto a regular grid aligned with the slices.
template<typename T>
vtkSmartPointer<vtkImageData> ResampleStack(const amITK::Image3<T>* stack, const std::vector<Slice>& slices,
  const double r[3], const double c[3], const double n[3], double sliceSpacing)
{
  const auto size = stack->GetLargestPossibleRegion().GetSize();
  const int W = static_cast<int>(size[0]), H = static_cast<int>(size[1]);
  const double sx = stack->GetSpacing()[0], sy = stack->GetSpacing()[1];
  const size_t K = slices.size();
  std::vector<double> a(K), b(K);
  double amin = 0, amax = 0, bmin = 0, bmax = 0;
  for (size_t k = 0; k < K; ++k)
  {
    const double d[3] = { slices[k].Position[0] - slices[0].Position[0], slices[k].Position[1] - slices[0].Position[1],
      slices[k].Position[2] - slices[0].Position[2] };
    a[k] = Vec::Dot(d, r);
    b[k] = Vec::Dot(d, c);
    amin = std::min(amin, a[k]);
    amax = std::max(amax, a[k]);
    bmin = std::min(bmin, b[k]);
    bmax = std::max(bmax, b[k]);
  }
  const int Wo = static_cast<int>(std::floor((amax - amin) / sx + 1e-6)) + W;
  const int Ho = static_cast<int>(std::floor((bmax - bmin) / sy + 1e-6)) + H;
  const double span = slices.back().Offset - slices.front().Offset;
  const int Ko = static_cast<int>(std::floor(span / sliceSpacing + 1e-6)) + 1;
  const T* in = stack->GetBufferPointer();
  const T fill = *std::min_element(in, in + static_cast<size_t>(W) * H * K);

  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(Wo, Ho, Ko);
  double origin[3], direction[9];
  for (int i = 0; i < 3; ++i)
  {
    origin[i] = slices[0].Position[i] + amin * r[i] + bmin * c[i];
    direction[3 * i + 0] = r[i];
    direction[3 * i + 1] = c[i];
    direction[3 * i + 2] = n[i];
  }
  out->SetOrigin(origin);
  out->SetSpacing(sx, sy, sliceSpacing);
  out->SetDirectionMatrix(direction);
  vtkSmartPointer<vtkDataArray> array;
  array.TakeReference(vtkDataArray::CreateDataArray(vtkTypeTraits<T>::VTKTypeID()));
  array->SetName("ImageScalars");
  array->SetNumberOfTuples(static_cast<vtkIdType>(Wo) * Ho * Ko);
  T* o = static_cast<T*>(array->GetVoidPointer(0));

  auto sample = [&](size_t k, double u, double v) -> double {
    if (u < 0 || v < 0 || u > W - 1 || v > H - 1)
      return fill;
    const int i0 = std::min(W - 2, static_cast<int>(u)), j0 = std::min(H - 2, static_cast<int>(v));
    const double fu = u - i0, fv = v - j0;
    const T* s = in + k * static_cast<size_t>(W) * H;
    const double v00 = s[j0 * W + i0], v10 = s[j0 * W + i0 + 1];
    const double v01 = s[(j0 + 1) * W + i0], v11 = s[(j0 + 1) * W + i0 + 1];
    return (1 - fv) * ((1 - fu) * v00 + fu * v10) + fv * ((1 - fu) * v01 + fu * v11);
  };
  size_t k = 0;
  for (int m = 0; m < Ko; ++m)
  {
    const double s = slices.front().Offset + m * sliceSpacing;
    while (k + 2 < K && slices[k + 1].Offset < s)
      ++k;
    const double t = std::min(1.0, std::max(0.0, (s - slices[k].Offset) / (slices[k + 1].Offset - slices[k].Offset)));
    for (int j = 0; j < Ho; ++j)
      for (int i = 0; i < Wo; ++i)
      {
        const double pa = amin + i * sx, pb = bmin + j * sy;
        const double v0 = sample(k, (pa - a[k]) / sx, (pb - b[k]) / sy);
        const double v1 = sample(k + 1, (pa - a[k + 1]) / sx, (pb - b[k + 1]) / sy);
        double v = (1 - t) * v0 + t * v1;
        if (std::is_integral<T>::value)
          v = std::floor(v + 0.5);
        o[(static_cast<size_t>(m) * Ho + j) * Wo + i] = static_cast<T>(v);
      }
  }
  out->GetPointData()->SetScalars(array);
  return out;
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
        vtkErrorMacro("Cannot read the header of '" << path << "': " << FirstLine(e2.what()));
        return false;
      }
    }
    else
    {
      vtkErrorMacro("Cannot read the header of '" << path << "': " << FirstLine(what));
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
      error = FirstLine(e.what());
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
  // GDCM opens every entry of the folder: a FIFO or a device among them would block it.
  if (DIR* d = opendir(folder.c_str()))
  {
    std::string why;
    while (const dirent* e = readdir(d))
    {
      const std::string name = e->d_name;
      // (A dangling link GDCM skips as it would any file it cannot open.)
      if (name == "." || name == ".." || amInputCheck::ReadableFile(folder + "/" + name, true, why) ||
        why.find("does not exist") != std::string::npos)
        continue;
      closedir(d);
      vtkErrorMacro("Cannot read the DICOM folder '" << folder << "': " << why);
      return false;
    }
    closedir(d);
  }
  auto names = itk::GDCMSeriesFileNames::New();
  std::vector<std::string> files;
  std::string uid;
  try
  {
    // Group strictly by SeriesInstanceUID: the geometry checks below find what does not fit.
    names->SetUseSeriesDetails(false);
    names->SetDirectory(folder);
    const auto& uids = names->GetSeriesUIDs();
    if (uids.empty())
    {
      vtkErrorMacro("No DICOM series in folder '" << folder << "'.");
      return false;
    }
    const bool byUID = this->SeriesUID && *this->SeriesUID;
    if (!byUID && onlyFile.empty() && uids.size() > 1)
    {
      // Reading one of several series without a word would hide the others (or mix them up).
      std::ostringstream list;
      for (const auto& u : uids)
      {
        const auto f = names->GetFileNames(u);
        list << "\n  " << (u.empty() ? std::string("(no SeriesInstanceUID)") : u) << ": " << f.size()
             << " files, e.g. '" << (f.empty() ? std::string() : f.front()) << "'";
      }
      vtkErrorMacro("DICOM folder '" << folder << "' holds " << uids.size()
                                     << " series; set SeriesUID to the one to read, or FileName to one of its files:"
                                     << list.str());
      return false;
    }
    for (const auto& u : uids)
    {
      const auto f = names->GetFileNames(u);
      bool take;
      if (byUID)
        take = (u == this->SeriesUID);
      else if (!onlyFile.empty())
        take = std::find(f.begin(), f.end(), onlyFile) != f.end();
      else
        take = f.size() > files.size();
      if (take)
      {
        files = f;
        uid = u;
        if (byUID || !onlyFile.empty())
          break;
      }
    }
  }
  catch (const itk::ExceptionObject& e)
  {
    vtkErrorMacro("Cannot scan DICOM folder '" << folder << "': " << FirstLine(e.what()));
    return false;
  }
  if (files.empty())
  {
    vtkErrorMacro("DICOM folder '" << folder << "' has no series "
                                   << (this->SeriesUID && *this->SeriesUID ? std::string("with UID ") + this->SeriesUID
                                                                           : std::string("containing ") + onlyFile)
                                   << ".");
    return false;
  }

  // Geometry of every slice, to detect what a regular grid cannot hold.
  std::vector<Slice> slices;
  double dir[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  itk::IOComponentEnum componentType = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  std::string modality, tiltTag;
  double pixel = 0.0; // the smaller in-plane pixel spacing
  for (size_t i = 0; i < files.size(); ++i)
  {
    auto io = itk::GDCMImageIO::New();
    try
    {
      io->SetFileName(files[i]);
      io->ReadImageInformation();
    }
    catch (const itk::ExceptionObject& e)
    {
      vtkErrorMacro("Cannot read DICOM file '" << files[i] << "': " << FirstLine(e.what()));
      return false;
    }
    if (io->GetNumberOfComponents() != 1)
    {
      vtkErrorMacro("DICOM file '" << files[i] << "' has " << io->GetNumberOfComponents()
                                   << " components per pixel; Anatomesh reads scalar images.");
      return false;
    }
    Slice s;
    s.File = files[i];
    for (int d = 0; d < 3; ++d)
      s.Position[d] = io->GetOrigin(d);
    if (i == 0)
    {
      for (int c = 0; c < 3; ++c)
      {
        const auto axis = io->GetDirection(c);
        for (int r = 0; r < 3; ++r)
          dir[3 * r + c] = axis[r];
      }
      componentType = io->GetComponentType();
      pixel = std::min(io->GetSpacing(0), io->GetSpacing(1));
      io->GetValueFromTag("0008|0060", modality);
      io->GetValueFromTag("0018|1120", tiltTag);
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        const auto axis = io->GetDirection(c);
        for (int r = 0; r < 3; ++r)
          if (std::fabs(dir[3 * r + c] - axis[r]) > 1e-3)
          {
            vtkErrorMacro("DICOM series in '" << folder << "' mixes slice orientations ('" << files[0] << "' and '"
                                              << files[i] << "' differ); it is not one volume.");
            return false;
          }
      }
    }
    if (i > 0 && io->GetComponentType() != componentType)
    {
      // Rescale parameters that differ between slices can change the component type: read as float.
      componentType = itk::IOComponentEnum::FLOAT;
    }
    slices.push_back(s);
  }
  const double r[3] = { dir[0], dir[3], dir[6] }, c[3] = { dir[1], dir[4], dir[7] };
  double n[3] = { r[1] * c[2] - r[2] * c[1], r[2] * c[0] - r[0] * c[2], r[0] * c[1] - r[1] * c[0] };
  const double nn = std::sqrt(Vec::Dot(n, n));
  for (double& v : n)
    v /= nn;
  for (Slice& s : slices)
    s.Offset = Vec::Dot(s.Position, n);
  std::stable_sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.Offset < b.Offset; });
  files.clear();
  for (const Slice& s : slices)
    files.push_back(s.File);

  double minGap = 1e300, maxGap = 0.0, maxTilt = 0.0, maxShift = 0.0;
  for (size_t i = 0; i + 1 < slices.size(); ++i)
  {
    double d[3];
    for (int k = 0; k < 3; ++k)
      d[k] = slices[i + 1].Position[k] - slices[i].Position[k];
    const double along = Vec::Dot(d, n);
    const double len = std::sqrt(Vec::Dot(d, d));
    const double shift = std::sqrt(std::max(0.0, len * len - along * along));
    minGap = std::min(minGap, along);
    maxGap = std::max(maxGap, along);
    maxShift = std::max(maxShift, shift);
    if (len > 0)
      maxTilt = std::max(maxTilt, std::acos(std::min(1.0, std::fabs(along) / len)) * 180.0 / 3.14159265358979);
  }
  if (slices.size() > 1 && minGap < 1e-3)
  {
    vtkErrorMacro("DICOM series in '" << folder << "' has two slices at the same position (gap " << minGap
                                      << " mm): several acquisitions mixed? Set SeriesUID or separate them.");
    return false;
  }

  const bool tilted = slices.size() > 1 && maxShift > 0.05 * pixel;
  const bool uneven = slices.size() > 2 && (maxGap - minGap) > 0.01 * maxGap + 1e-3;
  if ((tilted || uneven) && !this->ResampleIrregularSeries)
  {
    std::ostringstream msg;
    msg << "DICOM series in '" << folder << "' (" << slices.size() << " slices) is not a regular grid:";
    if (tilted)
      msg << " its slices are not stacked along their normal (gantry tilt of " << maxTilt << " degrees"
          << (tiltTag.empty() ? std::string() : "; GantryDetectorTilt tag says " + tiltTag) << ")";
    if (tilted && uneven)
      msg << " and";
    if (uneven)
      msg << " its slice gaps are uneven (" << minGap << " to " << maxGap << " mm)";
    msg << ". Reading it as a regular volume would warp the anatomy; set ResampleIrregularSeries to resample it "
           "onto a regular grid.";
    vtkErrorMacro(<< msg.str());
    return false;
  }

  bool ok = false;
  std::string error;
  const bool known = amITK::DispatchComponent(componentType, [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    auto reader = itk::ImageSeriesReader<amITK::Image3<T>>::New();
    auto io = itk::GDCMImageIO::New();
    reader->SetImageIO(io);
    reader->SetFileNames(files);
    try
    {
      reader->Update();
      if (tilted || uneven)
      {
        const double h = this->OutputSliceSpacing > 0 ? this->OutputSliceSpacing : minGap;
        this->Cache = ResampleStack<T>(reader->GetOutput(), slices, r, c, n, h);
      }
      else
        this->Cache = amITK::ToVTK<T>(reader->GetOutput(), "ImageScalars");
      ok = true;
    }
    catch (const itk::ExceptionObject& e)
    {
      error = FirstLine(e.what());
      // The series reader does not say which slice failed: decode them one by one to name it.
      for (std::size_t k = 0; k < files.size(); ++k)
      {
        auto one = itk::ImageFileReader<amITK::Image3<T>>::New();
        one->SetImageIO(itk::GDCMImageIO::New());
        one->SetFileName(files[k]);
        try
        {
          one->Update();
        }
        catch (const itk::ExceptionObject& e1)
        {
          error = "slice " + std::to_string(k + 1) + " of " + std::to_string(files.size()) + ", '" + files[k] +
            "', cannot be decoded: " + FirstLine(e1.what());
          break;
        }
      }
    }
  });
  if (!known || !ok)
  {
    vtkErrorMacro("Cannot read the DICOM series in '"
      << folder << "': " << (known ? error : std::string("unsupported pixel type")));
    return false;
  }
  AddString(this->Cache, "SourceFormat", "DICOM");
  AddString(this->Cache, "SeriesInstanceUID", uid);
  if (!modality.empty())
  {
    while (!modality.empty() && modality.back() == ' ')
      modality.pop_back();
    AddString(this->Cache, "Modality", modality);
  }
  if (tilted || uneven)
  {
    std::ostringstream note;
    note << "resampled from an irregular series: tilt " << maxTilt << " deg, gaps " << minGap << ".." << maxGap
         << " mm";
    AddString(this->Cache, "Resampling", note.str());
  }
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
      << this->OutputSliceSpacing;
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
  const double* dm = this->Cache->GetDirectionMatrix()->GetData();
  AddString(this->Cache, "SourceOrientation", amITK::OrientationCode(dm));
  std::ostringstream params;
  params << "FileName=" << path;
  if (this->ResampleIrregularSeries)
    params << " ResampleIrregularSeries=1 OutputSliceSpacing=" << this->OutputSliceSpacing;
  amProvenance::Record(this->Cache, nullptr, "amImageReader", params.str());
  this->CacheKey = key.str();
  this->CacheTime = this->GetMTime();
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
}
