#include "amInputCheck.h"

#include "amThreading.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <sys/stat.h>
#include <vector>

vtkDataArray* amInputCheck::ScalarImage(vtkImageData* image, std::string& why)
{
  if (!image || image->GetNumberOfPoints() == 0)
  {
    why = "The input image is empty.";
    return nullptr;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    why = "The input image has no scalars.";
    return nullptr;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    why = "The input scalars '" + std::string(scalars->GetName() ? scalars->GetName() : "") + "' have " +
      std::to_string(scalars->GetNumberOfComponents()) + " components; a one-component image is needed.";
    return nullptr;
  }
  return scalars;
}

bool amInputCheck::LabelBytes(vtkDataArray* scalars, int maximum, std::vector<unsigned char>& out, std::string& why)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  out.resize(static_cast<std::size_t>(n));
  // On the threads; the voxel named is the first bad one (the smallest index), as in order.
  const vtkIdType bad = amThreading::FirstFailure(0, n, [&](vtkIdType i) {
    const double v = scalars->GetComponent(i, 0);
    if (!(v >= 0 && v <= maximum) || v != std::floor(v))
      return false;
    out[i] = static_cast<unsigned char>(v);
    return true;
  });
  if (bad < n)
  {
    why = "Voxel " + std::to_string(bad) + " has value " + std::to_string(scalars->GetComponent(bad, 0)) +
      ": a label map holds whole numbers 0.." + std::to_string(maximum) + ".";
    return false;
  }
  return true;
}

long long amInputCheck::NonFinite(vtkDataArray* scalars)
{
  // Counted per block on the threads, the blocks added in order.
  const vtkIdType n = scalars->GetNumberOfTuples(), block = 1 << 16;
  std::vector<long long> counts(static_cast<std::size_t>((n + block - 1) / block), 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(counts.size()), [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
      for (vtkIdType i = b * block; i < std::min(n, (b + 1) * block); ++i)
        counts[b] += std::isfinite(scalars->GetComponent(i, 0)) ? 0 : 1;
  });
  long long count = 0;
  for (long long c : counts)
    count += c;
  return count;
}

bool amInputCheck::ReadableFile(const std::string& path, bool folderAllowed, std::string& why)
{
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    const int code = errno;
    why = "'" + path + "' " +
      (code == ENOENT || code == ENOTDIR ? std::string("does not exist.")
          : code == ELOOP                ? std::string("is a symbolic link loop.")
                                         : std::string("cannot be read: ") + std::strerror(code) + ".");
    return false;
  }
  if (S_ISREG(st.st_mode) || (folderAllowed && S_ISDIR(st.st_mode)))
    return true;
  why = "'" + path + "' is " +
    (S_ISDIR(st.st_mode)       ? std::string("a folder, not a file.")
        : S_ISFIFO(st.st_mode) ? std::string("a FIFO (named pipe), not a regular file.")
        : S_ISSOCK(st.st_mode) ? std::string("a socket, not a regular file.")
                               : std::string("a device, not a regular file."));
  return false;
}

bool amInputCheck::LabelCount(std::size_t count, std::string& why)
{
  if (count <= MaximumLabels)
    return true;
  why = "The label map holds " + std::to_string(count) + " distinct values, more than the " +
    std::to_string(MaximumLabels) + " labels a segmentation holds: is this the scan rather than its label map?";
  return false;
}
