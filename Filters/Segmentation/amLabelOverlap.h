/**
 * @class   amLabelOverlap
 * @brief   Dice, Jaccard and volumes per label between two label maps, in world coordinates.
 *
 * Input 0 is the label map to evaluate, input 1 the reference; they may lie on different grids
 * (origin, spacing, direction): every voxel centre of input 0 is looked up in input 1 (nearest
 * voxel, through both direction matrices; 0 outside it), so the comparison happens in patient
 * space on input 0's grid. Output: a vtkTable with one row per label present in either map
 * (columns Label, Volume (mm^3 of input 0), ReferenceVolume (mm^3 of the reference resampled on
 * input 0's grid), Dice, Jaccard) and a last row, Label -1, for the union of all non-zero labels
 * ("foreground"). With BinaryReference on, any non-zero reference voxel counts as the label being
 * evaluated (masks saved as 0/1 against a multi-label result).
 */
#ifndef amLabelOverlap_h
#define amLabelOverlap_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro
#include "vtkTableAlgorithm.h"

class ANATOMESHFILTERSSEGMENTATION_EXPORT amLabelOverlap : public vtkTableAlgorithm
{
public:
  static amLabelOverlap* New();
  vtkTypeMacro(amLabelOverlap, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The reference label map (input port 1).
  void SetReferenceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetReferenceData(vtkDataObject* data) { this->SetInputData(1, data); }

  ///@{
  /// Treat every non-zero reference voxel as matching any label (default off).
  vtkSetMacro(BinaryReference, bool);
  vtkGetMacro(BinaryReference, bool);
  vtkBooleanMacro(BinaryReference, bool);
  ///@}

  /// After an update: the Dice of a label (-1 = foreground), or -1 if the label is absent.
  double GetDice(int label);

protected:
  amLabelOverlap();
  ~amLabelOverlap() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool BinaryReference;

private:
  amLabelOverlap(const amLabelOverlap&) = delete;
  void operator=(const amLabelOverlap&) = delete;
};

#endif
