/**
 * @class   amIntensityClassifier
 * @brief   Scan to label map by intensity: explicit ranges, or automatic multi-level Otsu.
 *
 * Output port 0 is a label map (unsigned 8-bit scalars "Labels", 0 = unclassified) on the input's
 * grid (origin, spacing and direction kept). Output port 1 is the input windowed to 8 bits
 * (scalars "Windowed": (value - Level + Window/2) / Window * 255, clamped), as the paper did with
 * its 16-bit CT before segmenting.
 *
 * Mode Ranges (default): each range [Low, High) maps to a label; the first range that contains a
 * value wins; values in no range get label 0. Without AddRange calls, CT defaults are used, with
 * boundaries half-way between typical tissue values (HU): < -925 air (0), [-925, -475) lung (1),
 * [-475, -30) fat (2), [-30, 170) soft tissue (3), [170, 400) contrast-enhanced blood (4),
 * >= 400 bone (5, half-way between soft tissue and cortical bone, so thin bones survive partial
 * volume; dense contrast above 400 HU is classified as bone); names in field data "LabelNames".
 * Mode Otsu: ITK's multiple-threshold Otsu on a histogram of NumberOfHistogramBins bins splits the
 * intensities into NumberOfClasses classes, labelled 0 (darkest) to NumberOfClasses-1; the
 * thresholds are recorded in field data "Thresholds".
 * Mode Automatic: the six CT classes above (0 air .. 5 bone), their boundaries read from the scan
 * itself: a Gaussian mixture fitted to the histogram of the body (all but the air below -500 HU
 * open to the sides), each class's centre held in its anatomical range (amTissueMixture: any
 * contrast phase, kernel and noise); a class the scan does not show (no contrast, no fat) has an
 * empty range, except bone, which without a peak of its own (a crop, thin bone at coarse voxels)
 * starts half-way from soft tissue to cortical bone (700 HU), above any contrast. Field data "TissueClasses" gives each
 * class's centre, spread, weight (fraction of the body), whether it was found, and its upper boundary (HU). A scan with
 * no soft tissue class (not a CT in HU) is an error that says so. ClassifyWindowed applies Ranges or Otsu to the 8-bit
 * windowed values instead of the raw ones. ExteriorAir (default on): the air around the patient is label 0 connected
 * (across faces) to the sides of the image (the borders of the first two index axes; not the ends of the third, where a
 * trachea may leave the field of view). A voxel of another class that touches it, is darker than
 * ExteriorThreshold (default -480 HU, half-way between air and soft tissue) and has a voxel at least
 * that bright within two voxels along an axis is mostly air: partial volume of the skin, which
 * would otherwise land in the lung or fat class (lung beside an air pocket that reaches the sides
 * of a cropped scan has no such tissue beside it and stays lung). Such voxels become
 * label 0 and join the exterior, twice over (the blur spans up to two voxels); their number is
 * field data "ExteriorVoxels".
 * Errors: no input scalars, several components, an empty image, NaN values.
 */
#ifndef amIntensityClassifier_h
#define amIntensityClassifier_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro
#include "vtkImageAlgorithm.h"

#include <vector>

class ANATOMESHFILTERSSEGMENTATION_EXPORT amIntensityClassifier : public vtkImageAlgorithm
{
public:
  static amIntensityClassifier* New();
  vtkTypeMacro(amIntensityClassifier, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    Ranges = 0,
    Otsu = 1,
    Automatic = 2
  };

  ///@{
  /// Ranges (0, default), Otsu (1) or Automatic (2).
  vtkSetClampMacro(Mode, int, Ranges, Automatic);
  vtkGetMacro(Mode, int);
  ///@}

  /// Map values in [low, high) to label (1..255). Ranges are tested in the order added.
  void AddRange(double low, double high, double label);
  /// Forget the ranges (the CT defaults apply again).
  void RemoveAllRanges();
  int GetNumberOfRanges() { return static_cast<int>(this->RangeList.size() / 3); }

  ///@{
  /// Otsu: number of classes, 2..8 (default 4).
  vtkSetClampMacro(NumberOfClasses, int, 2, 8);
  vtkGetMacro(NumberOfClasses, int);
  ///@}

  ///@{
  /// Otsu: histogram bins (default 128).
  vtkSetClampMacro(NumberOfHistogramBins, int, 16, 4096);
  vtkGetMacro(NumberOfHistogramBins, int);
  ///@}

  ///@{
  /// Window width and level (input units, HU for CT) of the 8-bit output (defaults 1500, -300:
  /// the lung/soft-tissue window).
  vtkSetClampMacro(Window, double, 1e-6, 1e9);
  vtkGetMacro(Window, double);
  vtkSetMacro(Level, double);
  vtkGetMacro(Level, double);
  ///@}

  ///@{
  /// Classify the 8-bit windowed values (0..255) instead of the raw ones (default off).
  vtkSetMacro(ClassifyWindowed, bool);
  vtkGetMacro(ClassifyWindowed, bool);
  vtkBooleanMacro(ClassifyWindowed, bool);
  ///@}

  ///@{
  /// Partial volume at the body's surface to air (see the class description; default on, -480).
  vtkSetMacro(ExteriorAir, bool);
  vtkGetMacro(ExteriorAir, bool);
  vtkBooleanMacro(ExteriorAir, bool);
  vtkSetMacro(ExteriorThreshold, double);
  vtkGetMacro(ExteriorThreshold, double);
  ///@}

protected:
  amIntensityClassifier();
  ~amIntensityClassifier() override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode;
  int NumberOfClasses;
  int NumberOfHistogramBins;
  double Window;
  double Level;
  bool ClassifyWindowed;
  bool ExteriorAir;
  double ExteriorThreshold;
  std::vector<double> RangeList; // low, high, label triples

private:
  amIntensityClassifier(const amIntensityClassifier&) = delete;
  void operator=(const amIntensityClassifier&) = delete;
};

#endif
