/**
 * @class   amLabelTable
 * @brief   The colour and name tables written beside a label map: "<stem>.ctbl", one line per label
 *          ("value name R G B A", 0-255), the format 3D Slicer and FreeSurfer's LUT readers take, and
 *          "<stem>.itksnap.txt", ITK-SNAP's label description file (IDX R G B A VIS MSH "LABEL").
 *
 * For a label map (point scalars named "Labels"), names come from the image's field data "LabelNames" (a string array
 * indexed by label value, as amTorsoSegmentation, amIntensityClassifier and amThoraxPhantomSource write it); spaces in
 * a name become '_'. Colours are fixed per value (a golden-angle hue walk; 0 is transparent black), so one label keeps
 * its colour across files. The tables are written atomically like the image.
 */
#ifndef amLabelTable_h
#define amLabelTable_h

#include <string>

class vtkImageData;

class amLabelTable
{
public:
  /// The table's path for an image path: the image's name without its extension, plus ".ctbl".
  static std::string PathFor(const std::string& imagePath);
  /// The ITK-SNAP label description's path: the image's name without its extension, plus ".itksnap.txt".
  static std::string ItkSnapPathFor(const std::string& imagePath);
  /// Writes both tables when the image has "LabelNames"; true when there is none to write. False
  /// with 'why' set when writing fails.
  static bool Write(vtkImageData* image, const std::string& imagePath, std::string& why);
  /// The colour of a label value (RGB, 0-255).
  static void Colour(int value, unsigned char rgb[3]);
};

#endif
