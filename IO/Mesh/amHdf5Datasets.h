/**
 * @class   amHdf5Datasets
 * @brief   An HDF5 file of named one- or two-dimensional datasets (the heavy data of an XDMF mesh), made
 *          in memory through HDF5's C library and handed over as bytes.
 *
 * HDF5's core driver holds the file in memory: the caller writes its bytes with checked system calls
 * (amAtomicFile), as a file that fails part-way inside HDF5 stays open in HDF5's tables and crashes its
 * clean-up at exit. The file holds no modification times (HDF5 records them in each object header by
 * default), so the same data gives the same bytes. HDF5's own error printing is silenced while the file
 * is made and restored afterwards.
 */
#ifndef amHdf5Datasets_h
#define amHdf5Datasets_h

#include <cstdint>
#include <string>

class amHdf5Datasets
{
public:
  amHdf5Datasets();
  ~amHdf5Datasets();
  amHdf5Datasets(const amHdf5Datasets&) = delete;
  amHdf5Datasets& operator=(const amHdf5Datasets&) = delete;

  /// A rows x columns dataset (columns 1: one-dimensional) at "/name", row-major.
  bool Write(const std::string& name, const double* values, std::size_t rows, std::size_t columns);
  bool Write(const std::string& name, const std::int64_t* values, std::size_t rows, std::size_t columns);

  /// Closes the file and gives its bytes; false, with 'why', if making it or any write failed.
  bool Finish(std::string& bytes, std::string& why);

  bool Ok() const { return this->Failed.empty(); }

private:
  bool WriteAny(const std::string& name, const void* values, long long type, std::size_t rows, std::size_t columns);
  void Close();
  long long File = -1;
  long long Access = -1;     // file access: the core driver, no backing store
  long long Properties = -1; // dataset creation: no times
  std::string Failed;
  void* SavedPrinter = nullptr;
  void* SavedData = nullptr;
};

#endif
