#include "amHdf5Datasets.h"

#include <hdf5.h>

#include <atomic>

amHdf5Datasets::amHdf5Datasets()
{
  H5E_auto2_t printer = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &printer, &this->SavedData);
  this->SavedPrinter = reinterpret_cast<void*>(printer);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  // A name of its own per file: HDF5 refuses to create a core file whose name is open already.
  static std::atomic<unsigned long> counter{ 0 };
  const std::string name = "amHdf5Datasets-" + std::to_string(counter++);
  this->Access = H5Pcreate(H5P_FILE_ACCESS);
  this->Properties = H5Pcreate(H5P_DATASET_CREATE);
  if (this->Access < 0 || H5Pset_fapl_core(this->Access, 1 << 20, 0) < 0 || this->Properties < 0 ||
    H5Pset_obj_track_times(this->Properties, 0) < 0 ||
    (this->File = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, this->Access)) < 0)
    this->Failed = "HDF5 cannot make the file";
}

amHdf5Datasets::~amHdf5Datasets()
{
  this->Close();
}

bool amHdf5Datasets::WriteAny(
  const std::string& name, const void* values, long long type, std::size_t rows, std::size_t columns)
{
  if (!this->Ok())
    return false;
  const hsize_t dims[2] = { rows, columns };
  const hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
  const hid_t set = space < 0
    ? -1
    : H5Dcreate2(static_cast<hid_t>(this->File), ("/" + name).c_str(), static_cast<hid_t>(type), space, H5P_DEFAULT,
        static_cast<hid_t>(this->Properties), H5P_DEFAULT);
  const bool ok = set >= 0 && H5Dwrite(set, static_cast<hid_t>(type), H5S_ALL, H5S_ALL, H5P_DEFAULT, values) >= 0;
  if ((set >= 0 && H5Dclose(set) < 0) || !ok)
    this->Failed = "HDF5 cannot write the dataset " + name + " (out of memory?)";
  if (space >= 0)
    H5Sclose(space);
  return this->Ok();
}

bool amHdf5Datasets::Write(const std::string& name, const double* values, std::size_t rows, std::size_t columns)
{
  return this->WriteAny(name, values, H5T_NATIVE_DOUBLE, rows, columns);
}

bool amHdf5Datasets::Write(const std::string& name, const std::int64_t* values, std::size_t rows, std::size_t columns)
{
  return this->WriteAny(name, values, H5T_NATIVE_INT64, rows, columns);
}

bool amHdf5Datasets::Finish(std::string& bytes, std::string& why)
{
  bytes.clear();
  if (this->Ok())
  {
    const hid_t file = static_cast<hid_t>(this->File);
    const ssize_t size = H5Fflush(file, H5F_SCOPE_GLOBAL) < 0 ? -1 : H5Fget_file_image(file, nullptr, 0);
    if (size > 0)
    {
      bytes.resize(static_cast<std::size_t>(size));
      if (H5Fget_file_image(file, &bytes[0], bytes.size()) != size)
        bytes.clear();
    }
    if (bytes.empty())
      this->Failed = "HDF5 cannot give the file's image";
  }
  this->Close();
  why = this->Failed;
  return this->Failed.empty();
}

void amHdf5Datasets::Close()
{
  for (long long* list : { &this->Properties, &this->Access })
  {
    if (*list >= 0)
      H5Pclose(static_cast<hid_t>(*list));
    *list = -1;
  }
  if (this->File >= 0)
    H5Fclose(static_cast<hid_t>(this->File)); // in memory: nothing to fail on
  this->File = -1;
  if (this->SavedPrinter || this->SavedData)
    H5Eset_auto2(H5E_DEFAULT, reinterpret_cast<H5E_auto2_t>(this->SavedPrinter), this->SavedData);
  this->SavedPrinter = this->SavedData = nullptr;
}
