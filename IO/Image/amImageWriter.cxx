#include "amImageWriter.h"

#include "amAtomicFile.h"
#include "amDeflate.h"
#include "amITKBridge.h"
#include "amLabelTable.h"
#include "amMetaImageCheck.h"
#include "amNiftiCheck.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <itkImageFileWriter.h>
#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>

#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>

vtkStandardNewMacro(amImageWriter);

namespace
{
/// ITK's image IO for a file extension, or null.
itk::ImageIOBase::Pointer IOFor(const std::string& ext)
{
  if (ext == ".nii" || ext == ".nii.gz")
    return itk::NiftiImageIO::New().GetPointer();
  if (ext == ".mha" || ext == ".mhd")
    return itk::MetaImageIO::New().GetPointer();
  if (ext == ".nrrd" || ext == ".nhdr")
    return itk::NrrdImageIO::New().GetPointer();
  return nullptr;
}

/// Calls f with a null pointer of the C++ type of a VTK scalar type; false for a type not written.
template<typename F>
bool DispatchVTKType(int type, F&& f)
{
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
      f(static_cast<unsigned char*>(nullptr));
      return true;
    case VTK_SIGNED_CHAR:
    case VTK_CHAR:
      f(static_cast<signed char*>(nullptr));
      return true;
    case VTK_UNSIGNED_SHORT:
      f(static_cast<unsigned short*>(nullptr));
      return true;
    case VTK_SHORT:
      f(static_cast<short*>(nullptr));
      return true;
    case VTK_UNSIGNED_INT:
      f(static_cast<unsigned int*>(nullptr));
      return true;
    case VTK_INT:
      f(static_cast<int*>(nullptr));
      return true;
    case VTK_FLOAT:
      f(static_cast<float*>(nullptr));
      return true;
    case VTK_DOUBLE:
      f(static_cast<double*>(nullptr));
      return true;
    default:
      return false;
  }
}

/// The image written through ITK; false with ITK's description on failure.
template<typename T>
bool WriteITK(vtkImageData* input, itk::ImageIOBase* io, const std::string& path, bool compress, std::string& error)
{
  auto writer = itk::ImageFileWriter<amITK::Image3<T>>::New();
  writer->SetImageIO(io);
  writer->SetFileName(path);
  writer->SetInput(amITK::FromVTK<T>(input));
  writer->SetUseCompression(compress);
  try
  {
    writer->Update();
    return true;
  }
  catch (const itk::ExceptionObject& e)
  {
    error = e.GetDescription();
    return false;
  }
}

/// A file's whole text ("" when it cannot be read), and the data file a MetaImage header names.
std::string ReadWhole(const std::string& path, std::string& dataName)
{
  std::string header;
  if (FILE* f = std::fopen(path.c_str(), "rb"))
  {
    char buf[4096];
    size_t got;
    while ((got = std::fread(buf, 1, sizeof buf, f)) > 0)
      header.append(buf, got);
    std::fclose(f);
  }
  const auto key = header.find("ElementDataFile = ");
  if (key != std::string::npos)
  {
    const auto begin = key + 18;
    dataName = header.substr(begin, header.find_first_of("\r\n", begin) - begin);
  }
  return header;
}

/// ITK and MetaIO do not always report a short write (a full disk, a file size limit): the file
/// must read back whole before it replaces anything. The problem, or "".
std::string CheckWritten(const std::string& ext, const std::string& path)
{
  if (ext == ".nii" || ext == ".nii.gz")
  {
    const std::string incomplete = amNiftiCheck::Check(path, false);
    if (!incomplete.empty())
      return "the file written is incomplete (" + incomplete + "); is the disk full?";
  }
  if (ext == ".mha" || ext == ".mhd")
  {
    std::string repaired;
    const std::string incomplete = amMetaImageCheck::Check(path, repaired);
    if (!repaired.empty())
      std::remove(repaired.c_str());
    if (!incomplete.empty() || !repaired.empty())
      return "the file written is incomplete (" +
        (incomplete.empty() ? std::string("its header needed repair") : incomplete) + "); is the disk full?";
  }
  return "";
}

/// A detached .mhd's data file moved to the target's stem and the header pointed at it; the
/// problem, or "".
std::string PlaceMetaImageData(const std::string& target, const std::string& folder, std::string header,
  const std::string& dataName, const std::string& headerPath)
{
  if (dataName.empty())
    return "could not place the MetaImage data file.";
  const std::string dataExt = dataName.substr(dataName.find_last_of('.'));
  const std::string stem = target.substr(target.find_last_of('/') + 1, target.size() - folder.size() - 4);
  const std::string finalName = stem + dataExt;
  if (std::rename((folder + dataName).c_str(), (folder + finalName).c_str()) != 0)
  {
    std::remove((folder + dataName).c_str());
    return "could not place the MetaImage data file.";
  }
  header.replace(header.find("ElementDataFile = ") + 18, dataName.size(), finalName);
  FILE* f = std::fopen(headerPath.c_str(), "wb");
  const bool written = f && std::fwrite(header.data(), 1, header.size(), f) == header.size();
  if (f)
    std::fclose(f);
  return written ? "" : "could not rewrite the .mhd header.";
}
}

amImageWriter::amImageWriter()
  : FileName(nullptr)
  , UseCompression(true)
  , CompressionLevel(1)
{
  this->SetNumberOfOutputPorts(0);
}

amImageWriter::~amImageWriter()
{
  this->SetFileName(nullptr);
}

int amImageWriter::Write()
{
  this->LastWriteOk = false;
  this->Modified();
  this->Update();
  return this->LastWriteOk ? 1 : 0;
}

int amImageWriter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  this->LastWriteOk = false;
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const std::string target(this->FileName);
  if (!input || !input->GetPointData()->GetScalars() || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("Cannot write '" << target << "': the input image is empty or has no scalars.");
    return 0;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("Cannot write '" << target << "': the scalars have " << scalars->GetNumberOfComponents()
                                   << " components; one is needed.");
    return 0;
  }
  const std::string ext = amAtomicFile::Extension(target);
  itk::ImageIOBase::Pointer io = IOFor(ext);
  if (!io)
  {
    vtkErrorMacro(
      "Cannot write '" << target << "': unknown extension '" << ext << "' (use .nii, .nii.gz, .mha, .mhd or .nrrd).");
    return 0;
  }
  amAtomicFile file(target);
  std::string why;
  if (!file.CanWrite(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why << ".");
    return 0;
  }

  // A .nii.gz: ITK writes the plain .nii beside it (ITK's NIfTI writer compresses only at zlib's
  // default level), compressed here at CompressionLevel.
  std::unique_ptr<amAtomicFile> plain;
  if (ext == ".nii.gz")
    plain.reset(new amAtomicFile(target.substr(0, target.size() - 3)));
  std::string error;
  bool ok = false;
  const bool known = DispatchVTKType(scalars->GetDataType(), [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    ok = WriteITK<T>(
      input, io, plain ? plain->TemporaryPath() : file.TemporaryPath(), this->UseCompression && !plain, error);
  });
  if (!known)
  {
    vtkErrorMacro(
      "Cannot write '" << target << "': scalar type " << scalars->GetDataTypeAsString() << " is not supported.");
    return 0;
  }
  const std::string folder =
    target.find('/') == std::string::npos ? std::string() : target.substr(0, target.find_last_of('/') + 1);
  // A detached .mhd header names its data file (.raw or .zraw) after the temporary stem: move the
  // data file to the final stem first, and point the header at it.
  std::string header, dataName;
  if (ext == ".mhd")
    header = ReadWhole(file.TemporaryPath(), dataName);
  if (ok && plain && !amDeflate::GzipFile(plain->TemporaryPath(), file.TemporaryPath(), this->CompressionLevel, error))
    ok = false;
  plain.reset(); // the plain temporary removed
  if (ok)
  {
    error = CheckWritten(ext, file.TemporaryPath());
    ok = error.empty();
  }
  if (!ok)
  {
    if (!dataName.empty())
      std::remove((folder + dataName).c_str());
    // What ITK and its libraries say names the temporary: name the target instead.
    const std::string& tmp = file.TemporaryPath();
    for (auto at = error.find(tmp); at != std::string::npos; at = error.find(tmp, at + target.size()))
      error.replace(at, tmp.size(), target);
    error = amITK::WithoutLocation(error);
    vtkErrorMacro("Cannot write '" << target << "': " << error);
    return 0;
  }
  if (ext == ".mhd")
  {
    why = PlaceMetaImageData(target, folder, header, dataName, file.TemporaryPath());
    if (!why.empty())
    {
      vtkErrorMacro("Cannot write '" << target << "': " << why);
      return 0;
    }
  }
  if (!file.Commit(why))
  {
    vtkErrorMacro("Cannot write '" << target << "': " << why);
    return 0;
  }
  if (!amLabelTable::Write(input, target, why))
  {
    vtkErrorMacro("Wrote '" << target << "', but " << why << ".");
    return 0;
  }
  this->LastWriteOk = true;
  return 1;
}

void amImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "UseCompression: " << this->UseCompression << "\n";
  os << indent << "CompressionLevel: " << this->CompressionLevel << "\n";
}
