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
#include <limits>
#include <sstream>
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

namespace
{
// Calls f(i, value) for the values i0..i1-1 of the first component, through a typed pointer where
// the array is a plain buffer (GetComponent is a virtual call per value).
template<typename F>
void ForValues(vtkDataArray* scalars, vtkIdType i0, vtkIdType i1, F&& f)
{
  if (scalars->HasStandardMemoryLayout() && scalars->GetNumberOfComponents() == 1)
  {
    switch (scalars->GetDataType())
    {
      vtkTemplateMacro({
        const VTK_TT* p = static_cast<const VTK_TT*>(scalars->GetVoidPointer(0));
        for (vtkIdType i = i0; i < i1; ++i)
          if (!f(i, static_cast<double>(p[i])))
            return;
      });
    }
    return;
  }
  for (vtkIdType i = i0; i < i1; ++i)
    if (!f(i, scalars->GetComponent(i, 0)))
      return;
}

// A label map's value: a whole number in minimum..maximum (NaN is not).
bool IsLabel(double v, double minimum, double maximum)
{
  return v >= minimum && v <= maximum && v == std::floor(v);
}

std::string NotALabel(vtkDataArray* scalars, vtkIdType bad, double minimum, double maximum)
{
  std::ostringstream why;
  why << "Voxel " << bad << " has value " << scalars->GetComponent(bad, 0) << ": a label map holds whole numbers "
      << minimum << ".." << maximum;
  if (scalars->GetDataType() == VTK_FLOAT || scalars->GetDataType() == VTK_DOUBLE)
    why << " (this " << scalars->GetDataTypeAsString() << " array looks like an intensity image)";
  why << ".";
  return why.str();
}
}

bool amInputCheck::LabelCounts(
  vtkDataArray* scalars, double minimum, double maximum, std::map<int, vtkIdType>& counts, std::string& why)
{
  counts.clear();
  minimum = std::max(minimum, -LargestLabel);
  maximum = std::min(maximum, LargestLabel);
  const vtkIdType n = scalars->GetNumberOfTuples(), block = 1 << 16;
  const vtkIdType blocks = (n + block - 1) / block;
  std::vector<std::map<int, vtkIdType>> blockCounts(static_cast<std::size_t>(blocks));
  std::vector<vtkIdType> firstBad(static_cast<std::size_t>(blocks), -1);
  vtkSMPTools::For(0, blocks, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
    {
      auto& mine = blockCounts[b];
      // Runs of one label are common: the map is looked up only where the value changes.
      double last = std::numeric_limits<double>::quiet_NaN();
      vtkIdType* slot = nullptr;
      ForValues(scalars, b * block, std::min(n, (b + 1) * block), [&](vtkIdType i, double v) {
        if (v == last)
        {
          ++*slot;
          return true;
        }
        if (!IsLabel(v, minimum, maximum))
        {
          firstBad[b] = i;
          return false;
        }
        last = v;
        slot = &mine[static_cast<int>(v)];
        ++*slot;
        return true;
      });
    }
  });
  for (vtkIdType b = 0; b < blocks; ++b)
    if (firstBad[b] >= 0)
    {
      why = NotALabel(scalars, firstBad[b], minimum, maximum);
      return false;
    }
  for (const auto& mine : blockCounts)
    for (const auto& lv : mine)
      counts[lv.first] += lv.second;
  return true;
}

bool amInputCheck::LabelBytes(vtkDataArray* scalars, int maximum, std::vector<unsigned char>& out, std::string& why)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  out.resize(static_cast<std::size_t>(n));
  // On the threads; the voxel named is the first bad one (the smallest index), as in order.
  const vtkIdType bad = amThreading::FirstFailure(0, n, [&](vtkIdType i) {
    const double v = scalars->GetComponent(i, 0);
    if (!IsLabel(v, 0, maximum))
      return false;
    out[i] = static_cast<unsigned char>(v);
    return true;
  });
  if (bad < n)
  {
    why = NotALabel(scalars, bad, 0, maximum);
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
