/**
 * @class   amMorphologyCleaning
 * @brief   Cleans a label map: per-label morphology in millimetres, small-component removal,
 *          hole filling, largest component, label-preserving Gaussian regularisation.
 *
 * The paper's cleaning stage. First, with ModeFilterRadius > 0, ModeFilterPasses of a mode
 * (majority) filter: every voxel takes the most frequent label of its (2r+1)^3 neighbourhood (its
 * own on a tie), which removes the salt and pepper of a noisy intensity classification (it also
 * rounds a region's edges and corners, and parts thinner than the neighbourhood go); the voxels it
 * changed are field data "ModeFilterChanged". Then, for each processed label (AddLabel; all non-zero labels when none
 * is given), in increasing label order, on that label's own mask:
 * 1. Operation (None, Erode, Dilate, Open, Close) with a ball of Radius millimetres (an
 *    ellipsoid in voxels when the spacing is anisotropic);
 * 2. connected components (6-connected) smaller than MinimumComponentVolume mm^3 are removed,
 *    or all but the largest with KeepLargestComponent; every removal is listed in the field-data
 *    table "RemovedComponents" (label, voxels, mm^3);
 * 3. FillHoles fills unlabelled cavities enclosed by the label.
 * A label only ever grows into unlabelled (0) voxels: it never overwrites another organ. Voxels
 * it gives up are handed to their neighbours (the most frequent label among the 26 neighbours
 * that keep theirs, repeatedly), so cleaning leaves no gap where there was tissue; only Erode and
 * Open at the outside of the body hand voxels to the background, as the operation says.
 * 4. SmoothingSigma > 0 (mm) regularises all boundaries at once: each label's indicator is
 *    smoothed by a Gaussian and every voxel takes the label of the largest smoothed indicator
 *    (its own on ties), so no gap or overlap can appear.
 * If a label present in the input is absent from the output, the filter says so (a warning and
 * field data "VanishedLabels"). Field data "LabelVolumes" has (label, mm^3 before, mm^3 after).
 */
#ifndef amMorphologyCleaning_h
#define amMorphologyCleaning_h

#include "AnatomeshFiltersCleaningModule.h" // export macro
#include "vtkImageAlgorithm.h"

#include <vector>

class ANATOMESHFILTERSCLEANING_EXPORT amMorphologyCleaning : public vtkImageAlgorithm
{
public:
  static amMorphologyCleaning* New();
  vtkTypeMacro(amMorphologyCleaning, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Operations
  {
    None = 0,
    Erode = 1,
    Dilate = 2,
    Open = 3,
    Close = 4
  };

  ///@{
  /// Morphological operation (default None) and its ball radius in mm (default 1).
  vtkSetClampMacro(Operation, int, None, Close);
  vtkGetMacro(Operation, int);
  vtkSetClampMacro(Radius, double, 0.0, 100.0);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// Remove connected components smaller than this volume, mm^3 (default 0: keep all).
  vtkSetClampMacro(MinimumComponentVolume, double, 0.0, 1e12);
  vtkGetMacro(MinimumComponentVolume, double);
  ///@}

  ///@{
  /// Keep only each label's largest component (default off).
  vtkSetMacro(KeepLargestComponent, bool);
  vtkGetMacro(KeepLargestComponent, bool);
  vtkBooleanMacro(KeepLargestComponent, bool);
  ///@}

  ///@{
  /// Fill unlabelled cavities enclosed by a label (default off).
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  ///@}

  ///@{
  /// Mode filter: neighbourhood radius in voxels (default 0: off) and passes (default 1).
  vtkSetClampMacro(ModeFilterRadius, int, 0, 5);
  vtkGetMacro(ModeFilterRadius, int);
  vtkSetClampMacro(ModeFilterPasses, int, 1, 100);
  vtkGetMacro(ModeFilterPasses, int);
  ///@}

  ///@{
  /// Label-preserving Gaussian regularisation, mm (default 0: off).
  vtkSetClampMacro(SmoothingSigma, double, 0.0, 50.0);
  vtkGetMacro(SmoothingSigma, double);
  ///@}

  /// Process only these labels (none added: every non-zero label).
  void AddLabel(int label);
  void RemoveAllLabels();

protected:
  amMorphologyCleaning();
  ~amMorphologyCleaning() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Operation;
  double Radius;
  double MinimumComponentVolume;
  bool KeepLargestComponent;
  bool FillHoles;
  double SmoothingSigma;
  int ModeFilterRadius;
  int ModeFilterPasses;
  std::vector<int> Labels;

private:
  amMorphologyCleaning(const amMorphologyCleaning&) = delete;
  void operator=(const amMorphologyCleaning&) = delete;
};

#endif
