/**
 * @class   amVentricularFibres
 * @brief   Ventricular surface tags and rule-based fibres and sheets on a tetrahedral mesh, from
 *          its region labels alone.
 *
 * The heart is the cells whose RegionArrayName ("Region") is in HeartRegions (default 5, the
 * myocardium). Its boundary triangles are tagged from the region across them
 * (amVentricularTags): LVBloodRegions (default 6) give the LV endocardium (tag 1),
 * RVBloodRegions (default 7) the RV endocardium (2), BaseRegions (default 8 and 11, the aorta and
 * the atria; add the pulmonary artery where the label map has it) the base (4), anything else the
 * epicardium (3). Fibres and sheets then follow Laplace-Dirichlet rules (amRuleBasedFibres, after
 * Bayer et al. 2012): the helix angle goes linearly with the transmural depth from
 * HelixEndocardium (+60 degrees) to HelixEpicardium (-60 degrees), the sheets' transverse angle from
 * TransverseEndocardium to TransverseEpicardium (0, 0).
 *
 * The apex-to-base axis: from the optional Landmarks input (amCardiacLandmarks' output; its
 * LVApexEpicardium to LVBase), else ApexToBase when it is not zero, else the main axis of the LV
 * endocardium turned towards the base triangles, or, with none (a heart meshed without its outflow
 * tracts and atria), towards the patient's right, back and head (LPS), where a base lies.
 *
 * Output 0 ("Mesh"): the input with cell data Fibers and Sheets (unit vectors, zero outside the
 * heart) and point data TransmuralDepth (0 endocardium to 1 epicardium), ApicoBasal (0 apex to 1
 * base) and Ventricle (0 LV, 1 RV), -1 off the heart. Output 1 ("Tags"): the heart's boundary
 * triangles (vtkPolyData, normals out of the heart) with cell data VentricularTag, point data
 * InputPointId (the point's id in the mesh) and field data TagNames.
 *
 * Errors: no heart cells, a non-tetrahedral heart cell, no LV endocardium, no epicardium, no axis.
 * Warning: ventricular blood touching a region other than the heart, the other pool or the base (a
 * hole in the segmented wall), each pair with its triangles.
 *
 * Reference: J. D. Bayer et al., Ann. Biomed. Eng. 40(10):2243-2254, 2012.
 *
 * @sa amFitzHughNagumoSolver amReactionEikonalSolver amCardiacLandmarks
 */
#ifndef amVentricularFibres_h
#define amVentricularFibres_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <map>
#include <utility>
#include <vector>

class ANATOMESHFILTERSSIMULATION_EXPORT amVentricularFibres : public vtkUnstructuredGridAlgorithm
{
public:
  static amVentricularFibres* New();
  vtkTypeMacro(amVentricularFibres, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Optional input 1: landmarks with named points LVApexEpicardium and LVBase.
  void SetLandmarksConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  ///@{
  /// Cell array of region labels (default "Region").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  ///@{
  /// The regions of the heart muscle (default 5), of the LV blood (6), of the RV blood (7) and of
  /// what the base opens into (8).
  void AddHeartRegion(int label);
  void RemoveAllHeartRegions();
  void AddLVBloodRegion(int label);
  void RemoveAllLVBloodRegions();
  void AddRVBloodRegion(int label);
  void RemoveAllRVBloodRegions();
  void AddBaseRegion(int label);
  void RemoveAllBaseRegions();
  int GetNumberOfHeartRegions() { return static_cast<int>(this->HeartRegions.size()); }
  int GetHeartRegion(int i) { return this->HeartRegions.at(i); }
  int GetNumberOfLVBloodRegions() { return static_cast<int>(this->LVBloodRegions.size()); }
  int GetLVBloodRegion(int i) { return this->LVBloodRegions.at(i); }
  int GetNumberOfRVBloodRegions() { return static_cast<int>(this->RVBloodRegions.size()); }
  int GetRVBloodRegion(int i) { return this->RVBloodRegions.at(i); }
  int GetNumberOfBaseRegions() { return static_cast<int>(this->BaseRegions.size()); }
  int GetBaseRegion(int i) { return this->BaseRegions.at(i); }
  ///@}

  ///@{
  /// Helix angles at the endocardium and the epicardium (degrees, defaults 60 and -60) and the
  /// sheets' transverse angles (degrees, defaults 0 and 0).
  vtkSetClampMacro(HelixEndocardium, double, -90.0, 90.0);
  vtkGetMacro(HelixEndocardium, double);
  vtkSetClampMacro(HelixEpicardium, double, -90.0, 90.0);
  vtkGetMacro(HelixEpicardium, double);
  vtkSetClampMacro(TransverseEndocardium, double, -90.0, 90.0);
  vtkGetMacro(TransverseEndocardium, double);
  vtkSetClampMacro(TransverseEpicardium, double, -90.0, 90.0);
  vtkGetMacro(TransverseEpicardium, double);
  ///@}

  ///@{
  /// The apex-to-base axis when no Landmarks input is connected (default 0 0 0: found from the
  /// LV endocardium and the base, or the patient's frame).
  vtkSetVector3Macro(ApexToBase, double);
  vtkGetVector3Macro(ApexToBase, double);
  /// The unit apex-to-base axis of the last run, wherever it came from.
  vtkGetVector3Macro(UsedApexToBase, double);
  ///@}

  ///@{
  /// Figures of the last run: heart tetrahedra, triangles per tag (1..4).
  vtkGetMacro(NumberOfHeartCells, vtkIdType);
  /// Triangles where ventricular blood touches a region other than the heart, the other pool or the
  /// base: holes in the segmented wall (a warning names each pair).
  vtkGetMacro(NumberOfWallHoles, vtkIdType);
  vtkIdType GetNumberOfTaggedTriangles(int tag) { return tag >= 1 && tag <= 4 ? this->TagCounts[tag] : 0; }
  ///@}

protected:
  amVentricularFibres();
  ~amVentricularFibres() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* RegionArrayName;
  std::vector<int> HeartRegions, LVBloodRegions, RVBloodRegions, BaseRegions;
  double HelixEndocardium, HelixEpicardium, TransverseEndocardium, TransverseEpicardium;
  double ApexToBase[3];
  double UsedApexToBase[3] = { 0, 0, 0 };
  vtkIdType NumberOfHeartCells;
  vtkIdType NumberOfWallHoles = 0;
  vtkIdType TagCounts[5];

private:
  vtkIdType WarnOfWallHoles(const std::map<std::pair<int, int>, vtkIdType>& holes);
  amVentricularFibres(const amVentricularFibres&) = delete;
  void operator=(const amVentricularFibres&) = delete;
};

#endif
