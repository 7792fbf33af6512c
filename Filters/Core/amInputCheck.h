/**
 * @class   amInputCheck
 * @brief   Shared validation of filter inputs, so every filter words the same problem the same way.
 */
#ifndef amInputCheck_h
#define amInputCheck_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <string>

class vtkDataArray;
class vtkImageData;

class ANATOMESHFILTERSCORE_EXPORT amInputCheck
{
public:
  /// The one-component point scalars of a non-empty image, or null with 'why' set
  /// ("The input image is empty.", "... has no scalars ...", "... has 3 components ...").
  static vtkDataArray* ScalarImage(vtkImageData* image, std::string& why);
};

#endif
