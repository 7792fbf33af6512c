/**
 * @class   amInputCheck
 * @brief   Shared validation of filter inputs, so every filter words the same problem the same way.
 */
#ifndef amInputCheck_h
#define amInputCheck_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <map>
#include <string>
#include <vector>

#include "vtkType.h"

class vtkDataArray;
class vtkImageData;

class ANATOMESHFILTERSCORE_EXPORT amInputCheck
{
public:
  /// The one-component point scalars of a non-empty image, or null with 'why' set
  /// ("The input image is empty.", "... has no scalars ...", "... has 3 components ...").
  static vtkDataArray* ScalarImage(vtkImageData* image, std::string& why);

  /// The number of NaN and infinite values of the array's first component (GetRange skips NaNs).
  static long long NonFinite(vtkDataArray* scalars);

  /// The label map's check, the same for every filter that reads one: every value of the
  /// one-component array a whole number in minimum..maximum, and the voxels of each (counts, in
  /// increasing label order). Otherwise false with 'why' naming the first voxel that is not
  /// ("Voxel 12 has value 0.5: a label map holds whole numbers -2000000000..2000000000 (this float
  /// array looks like an intensity image)."). On the threads; the same result whatever their count.
  static bool LabelCounts(
    vtkDataArray* scalars, double minimum, double maximum, std::map<int, vtkIdType>& counts, std::string& why);

  /// The largest label magnitude LabelCounts accepts when no narrower range is asked for.
  static constexpr double LargestLabel = 2.0e9;

  /// The values of a one-component label array as bytes, each a whole number in 0..maximum
  /// (at most 255); false with 'why' naming the first voxel that is not.
  static bool LabelBytes(vtkDataArray* scalars, int maximum, std::vector<unsigned char>& out, std::string& why);

  /// The most distinct values a label map may hold. Atlases hold hundreds of labels; a scan (a CT in
  /// Hounsfield units, an MR) holds thousands of distinct values even at 8 mm.
  static constexpr std::size_t MaximumLabels = 1000;

  /// Whether 'count' distinct values can be a label map's; otherwise 'why' says the input looks like
  /// a scan given where its segmentation belongs.
  static bool LabelCount(std::size_t count, std::string& why);

  /// Whether a reader may open 'path': it exists and is a regular file (or, with 'folderAllowed', a
  /// folder). Otherwise 'why' ends "... does not exist.", "... is a symbolic link loop.", "... is a FIFO
  /// (named pipe), not a regular file." (a reader would block on it until killed), and so on.
  static bool ReadableFile(const std::string& path, bool folderAllowed, std::string& why);
};

#endif
