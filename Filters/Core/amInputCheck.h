/**
 * @class   amInputCheck
 * @brief   Shared validation of filter inputs, so every filter words the same problem the same way.
 */
#ifndef amInputCheck_h
#define amInputCheck_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <string>
#include <vector>

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

  /// The values of a one-component label array as bytes, each a whole number in 0..maximum
  /// (at most 255); false with 'why' naming the first voxel that is not.
  static bool LabelBytes(vtkDataArray* scalars, int maximum, std::vector<unsigned char>& out, std::string& why);
};

#endif
