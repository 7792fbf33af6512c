/**
 * @class   amIntensityWindow
 * @brief   The display window a scan stored as 0..255 was made through, carried by the image.
 *
 * A CT exported for viewing (8-bit PNG or JPEG stacks, some MetaImage and NRRD files) holds
 * 0..255 made from Hounsfield units through a window of some width and level: 0 is every value
 * at or below level - width/2, 255 every value at or above level + width/2. The file rarely says
 * which window. amImageReader's IntensityWindow property states it, and the reader records it in
 * the image's field data "IntensityWindow" (width, level; HU); filters whose settings are in HU
 * (amSnakeSegmentation, amTorsoSegmentation) read it from there and convert, so a pipeline states
 * the window once, where the file is read.
 */
#ifndef amIntensityWindow_h
#define amIntensityWindow_h

#include "AnatomeshFiltersCoreModule.h" // export macro

class vtkDataObject;

class ANATOMESHFILTERSCORE_EXPORT amIntensityWindow
{
public:
  /// The window (width, level, HU) the image's field data "IntensityWindow" holds; false (window
  /// untouched) when it holds none or one whose width is not positive.
  static bool Of(vtkDataObject* image, double window[2]);

  /// Records the window in the image's field data (replacing one recorded before); a width of 0
  /// removes it.
  static void Record(vtkDataObject* image, const double window[2]);

  /// A value in HU as the window's 0..255 stores it (not clamped), and a width in HU in those units.
  static double Level(const double window[2], double hu);
  static double Width(const double window[2], double hu);
};

#endif
