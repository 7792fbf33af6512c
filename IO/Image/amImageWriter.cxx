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

vtkStandardNewMacro(amImageWriter);

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
  itk::ImageIOBase::Pointer io;
  if (ext == ".nii" || ext == ".nii.gz")
    io = itk::NiftiImageIO::New();
  else if (ext == ".mha" || ext == ".mhd")
    io = itk::MetaImageIO::New();
  else if (ext == ".nrrd" || ext == ".nhdr")
    io = itk::NrrdImageIO::New();
  else
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
  auto write = [&](auto* tag) {
    using T = std::remove_pointer_t<decltype(tag)>;
    auto image = amITK::FromVTK<T>(input);
    auto writer = itk::ImageFileWriter<amITK::Image3<T>>::New();
    writer->SetImageIO(io);
    writer->SetFileName(plain ? plain->TemporaryPath() : file.TemporaryPath());
    writer->SetInput(image);
    writer->SetUseCompression(this->UseCompression && !plain);
    try
    {
      writer->Update();
      ok = true;
    }
    catch (const itk::ExceptionObject& e)
    {
      error = e.GetDescription();
    }
  };
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      write(static_cast<unsigned char*>(nullptr));
      break;
    case VTK_SIGNED_CHAR:
    case VTK_CHAR:
      write(static_cast<signed char*>(nullptr));
      break;
    case VTK_UNSIGNED_SHORT:
      write(static_cast<unsigned short*>(nullptr));
      break;
    case VTK_SHORT:
      write(static_cast<short*>(nullptr));
      break;
    case VTK_UNSIGNED_INT:
      write(static_cast<unsigned int*>(nullptr));
      break;
    case VTK_INT:
      write(static_cast<int*>(nullptr));
      break;
    case VTK_FLOAT:
      write(static_cast<float*>(nullptr));
      break;
    case VTK_DOUBLE:
      write(static_cast<double*>(nullptr));
      break;
    default:
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
  {
    if (FILE* f = std::fopen(file.TemporaryPath().c_str(), "rb"))
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
  }
  if (ok && plain && !amDeflate::GzipFile(plain->TemporaryPath(), file.TemporaryPath(), this->CompressionLevel, error))
    ok = false;
  plain.reset(); // the plain temporary removed
  if (ok && (ext == ".nii" || ext == ".nii.gz"))
  {
    // ITK does not always report a short write (a full disk, a file size limit): the file must read
    // back whole before it replaces anything.
    const std::string incomplete = amNiftiCheck::Check(file.TemporaryPath(), false);
    if (!incomplete.empty())
    {
      ok = false;
      error = "the file written is incomplete (" + incomplete + "); is the disk full?";
    }
  }
  if (ok && (ext == ".mha" || ext == ".mhd"))
  {
    // MetaIO does not fail on a short write either ("file stream is fail after write" only printed):
    // the header and every voxel must read back before the file replaces anything.
    std::string repaired;
    const std::string incomplete = amMetaImageCheck::Check(file.TemporaryPath(), repaired);
    if (!repaired.empty())
      std::remove(repaired.c_str());
    if (!incomplete.empty() || !repaired.empty())
    {
      ok = false;
      error = "the file written is incomplete (" +
        (incomplete.empty() ? std::string("its header needed repair") : incomplete) + "); is the disk full?";
    }
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
    const std::string dataExt = dataName.substr(dataName.find_last_of('.'));
    const std::string stem = target.substr(target.find_last_of('/') + 1, target.size() - folder.size() - 4);
    const std::string finalName = stem + dataExt;
    if (dataName.empty() || std::rename((folder + dataName).c_str(), (folder + finalName).c_str()) != 0)
    {
      if (!dataName.empty())
        std::remove((folder + dataName).c_str());
      vtkErrorMacro("Cannot write '" << target << "': could not place the MetaImage data file.");
      return 0;
    }
    header.replace(header.find("ElementDataFile = ") + 18, dataName.size(), finalName);
    FILE* f = std::fopen(file.TemporaryPath().c_str(), "wb");
    const bool written = f && std::fwrite(header.data(), 1, header.size(), f) == header.size();
    if (f)
      std::fclose(f);
    if (!written)
    {
      vtkErrorMacro("Cannot write '" << target << "': could not rewrite the .mhd header.");
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
