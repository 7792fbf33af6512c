/**
 * @class   amLeadFieldECG
 * @brief   A 12-lead ECG from the heart's transmembrane voltage by lead fields: one torso solve
 *          per electrode, then a weighted sum per frame (bidomain-consistent, anisotropic).
 *
 * Input 0 ("Mesh"): the whole tetrahedral mesh (cell data RegionArrayName "Region", the heart's
 * fibres FiberArrayName "Fibers" where it has them). Input 1 ("Heart"): the heart's solution, a
 * mesh with point data InputPointId (its points in input 0) and VoltageArrayName ("Vm", mV), e.g.
 * amReactionEikonalSolver's output; the heart's regions are its cells' labels; when it is
 * time-dependent every time step is read once. Input 2 ("Landmarks", optional): RA, LA, LL,
 * V1..V6 are the electrodes, else ElectrodePositions (the phantom's standard placement by default);
 * each is snapped to the nearest body-surface node, and one farther than MaximumElectrodeDistance
 * (20 mm) from the body is an error naming it.
 *
 * Conductivities in S/m: in the heart sigma_i = IntracellularConductivityFibre (0.17) along the
 * fibres and IntracellularConductivityTransverse (0.019) across, sigma_e = 0.62 and 0.24 (Clerc
 * 1976, as the N-version benchmark uses); elsewhere per region, RegionConductivities (label, sigma)
 * pairs, else Conductivity (defaults as TorsoPotential's: soft tissue 0.2, fat 0.04, lungs and
 * airway 0.05, blood 0.7, bone 0.02). amLeadFields solves div(sigma_b grad Z) = -delta_k for each electrode k
 * (RA is the ground) and each electrode's potential is then -(K_i Z_k) . Vm.
 *
 * The heart is read every SamplingInterval ms (1; 0: at its own time steps) from 0 to the end of
 * its time range: a reaction-eikonal heart answers any time exactly.
 *
 * Output 0 ("Leads"): a vtkTable with Time (ms) and the leads I, II, III, aVR, aVL, aVF, V1..V6 (mV);
 * field data Electrodes (the snapped positions, mm). Output 1 ("Features"): what a cardiologist reads
 * off them (amECGFeatures): per lead R, S and T amplitudes (mV) and the T wave's polarity; field
 * data QRSOnset, QRSDuration, QTInterval (ms).
 *
 * @sa amReactionEikonalSolver amTorsoPotential amVentricularFibres
 */
#ifndef amLeadFieldECG_h
#define amLeadFieldECG_h

#include "AnatomeshFiltersSimulationModule.h" // export macro
#include "vtkTableAlgorithm.h"

#include <memory>
#include <vector>

class vtkPolyData;
class vtkTable;
class vtkUnstructuredGrid;

class ANATOMESHFILTERSSIMULATION_EXPORT amLeadFieldECG : public vtkTableAlgorithm
{
public:
  static amLeadFieldECG* New();
  vtkTypeMacro(amLeadFieldECG, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetHeartConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetLandmarksConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }

  ///@{
  /// Arrays: region labels (cells, "Region"), fibres (cells, "Fibers"), the heart's voltage
  /// (points of input 1, "Vm", mV).
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  vtkSetStringMacro(FiberArrayName);
  vtkGetStringMacro(FiberArrayName);
  vtkSetStringMacro(VoltageArrayName);
  vtkGetStringMacro(VoltageArrayName);
  ///@}

  ///@{
  /// The heart's conductivities (S/m): intracellular along and across the fibres (0.17, 0.019),
  /// extracellular along and across (0.62, 0.24).
  vtkSetClampMacro(IntracellularConductivityFibre, double, 0.0, 1e3);
  vtkGetMacro(IntracellularConductivityFibre, double);
  vtkSetClampMacro(IntracellularConductivityTransverse, double, 0.0, 1e3);
  vtkGetMacro(IntracellularConductivityTransverse, double);
  vtkSetClampMacro(ExtracellularConductivityFibre, double, 0.0, 1e3);
  vtkGetMacro(ExtracellularConductivityFibre, double);
  vtkSetClampMacro(ExtracellularConductivityTransverse, double, 0.0, 1e3);
  vtkGetMacro(ExtracellularConductivityTransverse, double);
  ///@}

  ///@{
  /// The torso's conductivity where no per-region value is given (S/m, default 0.2), and (label,
  /// sigma) pairs.
  vtkSetClampMacro(Conductivity, double, 0.0, 1e3);
  vtkGetMacro(Conductivity, double);
  void AddRegionConductivity(double label, double sigma);
  void RemoveAllRegionConductivities();
  int GetNumberOfRegionConductivities() { return static_cast<int>(this->RegionConductivities.size() / 2); }
  double* GetRegionConductivity(int i) VTK_SIZEHINT(2) { return &this->RegionConductivities.at(2 * i); }
  ///@}

  ///@{
  /// Electrode positions (x y z triples, mm; RA, LA, LL, V1..V6) when no Landmarks are connected.
  void AddElectrode(double x, double y, double z);
  void RemoveAllElectrodes();
  int GetNumberOfElectrodes() { return static_cast<int>(this->ElectrodePositions.size() / 3); }
  double* GetElectrode(int i) VTK_SIZEHINT(3) { return &this->ElectrodePositions.at(3 * i); }
  /// The farthest an electrode may be from the body surface (mm, default 20).
  vtkSetClampMacro(MaximumElectrodeDistance, double, 0.0, 1e6);
  vtkGetMacro(MaximumElectrodeDistance, double);
  ///@}

  ///@{
  /// Time between the ECG's samples (ms, default 1; 0: the heart's own time steps).
  vtkSetClampMacro(SamplingInterval, double, 0.0, 1e6);
  vtkGetMacro(SamplingInterval, double);
  ///@}

  ///@{
  /// The last run's QRS duration and QT interval (ms; 0 when the leads could not be read).
  vtkGetMacro(QRSDuration, double);
  vtkGetMacro(QTInterval, double);
  ///@}

  ///@{
  /// Figures of the last run: mesh nodes, heart nodes, frames read, seconds of the lead fields.
  vtkGetMacro(NumberOfNodes, vtkIdType);
  vtkGetMacro(NumberOfHeartNodes, vtkIdType);
  vtkGetMacro(NumberOfFrames, int);
  vtkGetMacro(LeadFieldSeconds, double);
  ///@}

protected:
  amLeadFieldECG();
  ~amLeadFieldECG() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* RegionArrayName;
  char* FiberArrayName;
  char* VoltageArrayName;
  double IntracellularConductivityFibre, IntracellularConductivityTransverse;
  double ExtracellularConductivityFibre, ExtracellularConductivityTransverse;
  double Conductivity;
  std::vector<double> RegionConductivities;
  std::vector<double> ElectrodePositions;
  double MaximumElectrodeDistance;
  double SamplingInterval;
  double QRSDuration = 0, QTInterval = 0;
  vtkIdType NumberOfNodes, NumberOfHeartNodes;
  int NumberOfFrames;
  double LeadFieldSeconds;

private:
  amLeadFieldECG(const amLeadFieldECG&) = delete;
  void operator=(const amLeadFieldECG&) = delete;
  struct Model;
  std::unique_ptr<Model> State;
  int LoopIndex = -1;
  std::vector<double> LoopTimes;
  bool Prepare(vtkUnstructuredGrid* mesh, vtkUnstructuredGrid* heart, vtkPolyData* landmarks);
  bool Read(vtkUnstructuredGrid* heart, double time);
  void Measure(vtkTable* features);
};

#endif
