#include "amDicomSeries.h"

#include "amITKBridge.h"
#include "amInputCheck.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <itkGDCMImageIO.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImageFileReader.h>
#include <itkImageSeriesReader.h>

#include <algorithm>
#include <cmath>
#include <dirent.h>
#include <sstream>
#include <type_traits>
#include <vector>

namespace
{
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

/// The slices' common geometry, read from their headers.
struct Geometry
{
  std::vector<Slice> Slices;
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  itk::IOComponentEnum ComponentType = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  std::string Modality, TiltTag;
  double Pixel = 0.0; // the smaller in-plane pixel spacing
};

/// How the slices stack: their axes, gaps, tilt and in-plane shift.
struct Stack
{
  double R[3], C[3], N[3];
  double MinGap = 1e300, MaxGap = 0.0, MaxTilt = 0.0, MaxShift = 0.0;
  bool Tilted = false, Uneven = false;
};

/// GDCM opens every entry of the folder: a FIFO or a device among them would block it. The
/// problem, or "".
std::string CheckEntries(const std::string& folder)
{
  DIR* d = opendir(folder.c_str());
  if (!d)
    return "";
  std::string why;
  while (const dirent* e = readdir(d))
  {
    const std::string name = e->d_name;
    // (A dangling link GDCM skips as it would any file it cannot open.)
    if (name == "." || name == ".." || amInputCheck::ReadableFile(folder + "/" + name, true, why) ||
      why.find("does not exist") != std::string::npos)
      continue;
    closedir(d);
    return "Cannot read the DICOM folder '" + folder + "': " + why;
  }
  closedir(d);
  return "";
}

/// The files of the series asked for, grouped strictly by SeriesInstanceUID (the geometry checks
/// find what does not fit); the problem, or "".
std::string PickSeries(const amDicomSeries::Request& q, std::vector<std::string>& files, std::string& uid)
{
  auto names = itk::GDCMSeriesFileNames::New();
  try
  {
    names->SetUseSeriesDetails(false);
    names->SetDirectory(q.Folder);
    const auto& uids = names->GetSeriesUIDs();
    if (uids.empty())
      return "No DICOM series in folder '" + q.Folder + "'.";
    const bool byUID = !q.SeriesUID.empty();
    if (!byUID && q.OnlyFile.empty() && uids.size() > 1)
    {
      // Reading one of several series without a word would hide the others (or mix them up).
      std::ostringstream list;
      list << "DICOM folder '" << q.Folder << "' holds " << uids.size()
           << " series; set SeriesUID to the one to read, or FileName to one of its files:";
      for (const auto& u : uids)
      {
        const auto f = names->GetFileNames(u);
        list << "\n  " << (u.empty() ? std::string("(no SeriesInstanceUID)") : u) << ": " << f.size()
             << " files, e.g. '" << (f.empty() ? std::string() : f.front()) << "'";
      }
      return list.str();
    }
    for (const auto& u : uids)
    {
      const auto f = names->GetFileNames(u);
      bool take;
      if (byUID)
        take = (u == q.SeriesUID);
      else if (!q.OnlyFile.empty())
        take = std::find(f.begin(), f.end(), q.OnlyFile) != f.end();
      else
        take = f.size() > files.size();
      if (take)
      {
        files = f;
        uid = u;
        if (byUID || !q.OnlyFile.empty())
          break;
      }
    }
  }
  catch (const itk::ExceptionObject& e)
  {
    return "Cannot scan DICOM folder '" + q.Folder + "': " + amITK::Description(e.what());
  }
  if (files.empty())
    return "DICOM folder '" + q.Folder + "' has no series " +
      (!q.SeriesUID.empty() ? "with UID " + q.SeriesUID : "containing " + q.OnlyFile) + ".";
  return "";
}

/// Every slice's header: position, orientation (one for all), pixel type; the problem, or "".
std::string ReadGeometry(const std::string& folder, const std::vector<std::string>& files, Geometry& g)
{
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
      return "Cannot read DICOM file '" + files[i] + "': " + amITK::Description(e.what());
    }
    if (io->GetNumberOfComponents() != 1)
      return "DICOM file '" + files[i] + "' has " + std::to_string(io->GetNumberOfComponents()) +
        " components per pixel; Anatomesh reads scalar images.";
    Slice s;
    s.File = files[i];
    for (int d = 0; d < 3; ++d)
      s.Position[d] = io->GetOrigin(d);
    for (int c = 0; c < 3; ++c)
    {
      const auto axis = io->GetDirection(c);
      for (int r = 0; r < 3; ++r)
        if (i == 0)
          g.Direction[3 * r + c] = axis[r];
        else if (std::fabs(g.Direction[3 * r + c] - axis[r]) > 1e-3)
          return "DICOM series in '" + folder + "' mixes slice orientations ('" + files[0] + "' and '" + files[i] +
            "' differ); it is not one volume.";
    }
    if (i == 0)
    {
      g.ComponentType = io->GetComponentType();
      g.Pixel = std::min(io->GetSpacing(0), io->GetSpacing(1));
      io->GetValueFromTag("0008|0060", g.Modality);
      io->GetValueFromTag("0018|1120", g.TiltTag);
    }
    else if (io->GetComponentType() != g.ComponentType)
      g.ComponentType = itk::IOComponentEnum::FLOAT; // rescales that differ between slices: read as float
    g.Slices.push_back(s);
  }
  return "";
}

/// The slices sorted along their normal, and how far the stack is from a regular grid.
Stack Measure(Geometry& g)
{
  Stack k;
  const double* dir = g.Direction;
  for (int i = 0; i < 3; ++i)
  {
    k.R[i] = dir[3 * i];
    k.C[i] = dir[3 * i + 1];
  }
  const double *r = k.R, *c = k.C;
  double* n = k.N;
  n[0] = r[1] * c[2] - r[2] * c[1];
  n[1] = r[2] * c[0] - r[0] * c[2];
  n[2] = r[0] * c[1] - r[1] * c[0];
  const double nn = std::sqrt(Vec::Dot(n, n));
  for (int i = 0; i < 3; ++i)
    n[i] /= nn;
  std::vector<Slice>& slices = g.Slices;
  for (Slice& s : slices)
    s.Offset = Vec::Dot(s.Position, n);
  std::stable_sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.Offset < b.Offset; });
  for (size_t i = 0; i + 1 < slices.size(); ++i)
  {
    double d[3];
    for (int m = 0; m < 3; ++m)
      d[m] = slices[i + 1].Position[m] - slices[i].Position[m];
    const double along = Vec::Dot(d, n);
    const double len = std::sqrt(Vec::Dot(d, d));
    const double shift = std::sqrt(std::max(0.0, len * len - along * along));
    k.MinGap = std::min(k.MinGap, along);
    k.MaxGap = std::max(k.MaxGap, along);
    k.MaxShift = std::max(k.MaxShift, shift);
    if (len > 0)
      k.MaxTilt = std::max(k.MaxTilt, std::acos(std::min(1.0, std::fabs(along) / len)) * 180.0 / 3.14159265358979);
  }
  k.Tilted = slices.size() > 1 && k.MaxShift > 0.05 * g.Pixel;
  k.Uneven = slices.size() > 2 && (k.MaxGap - k.MinGap) > 0.01 * k.MaxGap + 1e-3;
  return k;
}

/// Why an irregular stack is not read as it is.
std::string Irregular(const std::string& folder, const Geometry& g, const Stack& k)
{
  std::ostringstream msg;
  msg << "DICOM series in '" << folder << "' (" << g.Slices.size() << " slices) is not a regular grid:";
  if (k.Tilted)
    msg << " its slices are not stacked along their normal (gantry tilt of " << k.MaxTilt << " degrees"
        << (g.TiltTag.empty() ? std::string() : "; GantryDetectorTilt tag says " + g.TiltTag) << ")";
  if (k.Tilted && k.Uneven)
    msg << " and";
  if (k.Uneven)
    msg << " its slice gaps are uneven (" << k.MinGap << " to " << k.MaxGap << " mm)";
  msg << ". Reading it as a regular volume would warp the anatomy; set ResampleIrregularSeries to resample it "
         "onto a regular grid.";
  return msg.str();
}

/// The pixels of the sorted slices, resampled when the stack is irregular; on failure the slice
/// that cannot be decoded is named (the series reader does not say which).
template<typename T>
vtkSmartPointer<vtkImageData> ReadPixels(
  const Geometry& g, const Stack& k, double sliceSpacing, const std::vector<std::string>& files, std::string& error)
{
  auto reader = itk::ImageSeriesReader<amITK::Image3<T>>::New();
  reader->SetImageIO(itk::GDCMImageIO::New());
  reader->SetFileNames(files);
  try
  {
    reader->Update();
    if (k.Tilted || k.Uneven)
      return ResampleStack<T>(reader->GetOutput(), g.Slices, k.R, k.C, k.N, sliceSpacing);
    return amITK::ToVTK<T>(reader->GetOutput(), "ImageScalars");
  }
  catch (const itk::ExceptionObject& e)
  {
    error = amITK::Description(e.what());
  }
  for (std::size_t m = 0; m < files.size(); ++m)
  {
    auto one = itk::ImageFileReader<amITK::Image3<T>>::New();
    one->SetImageIO(itk::GDCMImageIO::New());
    one->SetFileName(files[m]);
    try
    {
      one->Update();
    }
    catch (const itk::ExceptionObject& e1)
    {
      error = "slice " + std::to_string(m + 1) + " of " + std::to_string(files.size()) + ", '" + files[m] +
        "', cannot be decoded: " + amITK::Description(e1.what());
      break;
    }
  }
  return nullptr;
}
}

amDicomSeries::Result amDicomSeries::Read(const Request& q)
{
  Result result;
  std::vector<std::string> files;
  Geometry g;
  result.Error = CheckEntries(q.Folder);
  if (result.Error.empty())
    result.Error = PickSeries(q, files, result.SeriesUID);
  if (result.Error.empty())
    result.Error = ReadGeometry(q.Folder, files, g);
  if (!result.Error.empty())
    return result;
  const Stack k = Measure(g);
  if (g.Slices.size() > 1 && k.MinGap < 1e-3)
  {
    std::ostringstream why;
    why << "DICOM series in '" << q.Folder << "' has two slices at the same position (gap " << k.MinGap
        << " mm): several acquisitions mixed? Set SeriesUID or separate them.";
    result.Error = why.str();
    return result;
  }
  if ((k.Tilted || k.Uneven) && !q.ResampleIrregular)
  {
    result.Error = Irregular(q.Folder, g, k);
    return result;
  }
  files.clear();
  for (const Slice& s : g.Slices)
    files.push_back(s.File);
  const double sliceSpacing = q.OutputSliceSpacing > 0 ? q.OutputSliceSpacing : k.MinGap;
  std::string error;
  const bool known = amITK::DispatchComponent(g.ComponentType, [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    result.Image = ReadPixels<T>(g, k, sliceSpacing, files, error);
  });
  if (!known || !result.Image)
  {
    result.Image = nullptr;
    result.Error = "Cannot read the DICOM series in '" + q.Folder + "': " + (known ? error : "unsupported pixel type");
    return result;
  }
  g.Modality.erase(g.Modality.find_last_not_of(' ') + 1);
  result.Modality = g.Modality;
  if (k.Tilted || k.Uneven)
  {
    std::ostringstream note;
    note << "resampled from an irregular series: tilt " << k.MaxTilt << " deg, gaps " << k.MinGap << ".." << k.MaxGap
         << " mm";
    result.Resampling = note.str();
  }
  return result;
}
