/**
 * @class   amSeedPointsSource
 * @brief   Labelled seed points: the clicks that start a segmentation, one point per click.
 *
 * Each seed is a position (world coordinates, mm) and the label of the organ it marks; the output
 * is a vtkPolyData with one vertex per seed and point data "Label" (LabelArrayName), which
 * amSnakeSegmentation takes on its Seeds input. A seed without a label of its own gets its index
 * + 1 (each seed its own organ).
 *
 * In ParaView the positions are handles in the view (the Seeds panel: drag a handle, or add and
 * remove seeds in its table), the labels a list beside them. The defaults are the main job's four
 * seeds on the thorax phantom: the left and right ventricular blood pools (6, 7) and the aorta,
 * ascending and descending (8).
 *
 * Bad input (an error, no output): a label outside 1..255, a position that is not finite. More
 * labels than seeds (a seed removed in the GUI) is a warning: the extra labels are not used.
 *
 * @sa amSnakeSegmentation
 */
#ifndef amSeedPointsSource_h
#define amSeedPointsSource_h

#include "AnatomeshFiltersSourcesModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector>

class ANATOMESHFILTERSSOURCES_EXPORT amSeedPointsSource : public vtkPolyDataAlgorithm
{
public:
  static amSeedPointsSource* New();
  vtkTypeMacro(amSeedPointsSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The seeds' positions (mm): their number (new ones at the origin), and the i-th.
  void SetNumberOfSeeds(int n);
  int GetNumberOfSeeds() { return static_cast<int>(this->Positions.size() / 3); }
  void SetSeedPosition(int i, double x, double y, double z);
  double* GetSeedPosition(int i) VTK_SIZEHINT(3) { return &this->Positions.at(3 * i); }
  ///@}

  ///@{
  /// The seeds' labels (1..255): their number (at most the number of seeds), and the i-th.
  void SetNumberOfSeedLabels(int n);
  int GetNumberOfSeedLabels() { return static_cast<int>(this->Labels.size()); }
  void SetSeedLabel(int i, int label);
  int GetSeedLabel(int i) { return this->Labels.at(i); }
  ///@}

  ///@{
  /// Name of the point-data array of labels (default "Label", amSnakeSegmentation's default).
  vtkSetStringMacro(LabelArrayName);
  vtkGetStringMacro(LabelArrayName);
  ///@}

protected:
  amSeedPointsSource();
  ~amSeedPointsSource() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::vector<double> Positions; // x, y, z per seed
  std::vector<int> Labels;
  char* LabelArrayName;

private:
  amSeedPointsSource(const amSeedPointsSource&) = delete;
  void operator=(const amSeedPointsSource&) = delete;
};

#endif
