/**
 * @class   amTorsoSegmentation
 * @brief   Segments the whole simulation domain of a chest CT into one label map: body, fat,
 *          lungs, bone, myocardium, and the organs segmented from seeds.
 *
 * Input 0 is the CT in Hounsfield units, or windowed to 0..255 (InputWindow, or the window the
 * image carries from amImageReader's IntensityWindow: the width and level in HU that made it; 0
 * below the window is read as air, -1000 HU, 255 above it as bone, +1000 HU, as the classes need).
 * Input 1 (optional) is a label map on the same grid of organs segmented from seeds, e.g.
 * amSnakeSegmentation's blood pools and aorta; its labels are kept as they are and take precedence
 * over every tissue below.
 *
 * The output uses the thorax phantom's label scheme (names in field data "LabelNames"):
 * 0 outside the body, 1 soft tissue, 2 fat, 3 right lung, 4 left lung, 5 myocardium, 6 LV blood,
 * 7 RV blood, 8 aorta, 9 spine, 10 ribs (and other bone), and 11 the atria's blood where input 1
 * holds it (a click in the left atrium, label 11: SnakeSegmentation parts it from the LV's; no wall
 * is built round it, and the simulation takes it as blood that the ventricles' base opens into),
 * and 12 the trachea and the main bronchi (Airway; FindAirway).
 * Steps:
 * 0. a scan noisier than MaximumNoise is smoothed to four fifths of it (the least Gaussian); its
 *    bone is read from the unsmoothed intensities (five noise deviations above the class below, and
 *    the voxels beside it more than half bone), as the smoothing takes thin bones below the bone class;
 * 1. voxels are classed as air, lung, fat, soft tissue, contrast blood or bone: with
 *    AutomaticClasses (default), by the classes read from this scan's own histogram
 *    (amIntensityClassifier's Automatic mode: a Gaussian mixture with each class's centre held in
 *    its anatomical range; field data "TissueClasses" gives the centres, spreads and boundaries
 *    found, and a warning names a class a chest CT shows that this scan does not: lung, fat,
 *    bone); without it, by amIntensityClassifier's fixed CT ranges; the patient table is no part
 *    of the body: it is made along the scanner's axis, where the body's outline changes from slice
 *    to slice, so its shells (thin plates of fat's density or more, at most 12 mm thick, at least
 *    100 mm across or 50 where the image cuts them, beside air) lie at the same place, within a
 *    voxel, in at least 90 % of the slices across the head-feet axis, and its foam core (the lung
 *    class, as constant) between them (a scan
 *    of fewer than 20 slices or 60 mm is not searched; field data "PatientTable" gives its volume,
 *    mm^3); the table and the air connected to the sides of the first two index axes are the
 *    exterior (through no gap of the body wall narrower than twice BodyGapClosing: by default none,
 *    or 15 mm where InputWindow starts above fat), everything else is the body (soft tissue unless
 *    a step below says otherwise);
 * 2. fat is the fat class opened by the 6-neighbour cross: the one-voxel sheets that partial
 *    volume leaves where lung meets soft tissue are not fat, and go to their neighbours;
 * 3. the lungs are the two largest components of air inside the body (opened by a ball of
 *    LungOpening mm when it is set: by default where InputWindow starts above fat, 12 mm) whose
 *    voxels are mostly of the lung class where the scan tells aerated lung from gas (gas in the
 *    stomach or bowel is never lung), right and left by their centres' world x (x towards the
 *    patient's left). Air under the lungs across the diaphragm is not lung: the air is cut into
 *    the basins of its depth (parts joined by necks at least two voxels thinner than their own
 *    deepest point), and a basin that lies, for more than half its voxels, under air of a larger
 *    basin with tissue between (down the index axis closest to the patient's head-feet axis) is
 *    gas or abdominal fat joined to a lung through a narrow passage; where one component holds
 *    both (joined at the trachea), it is parted where the lungs meet: its deepest parts, at the
 *    least depth where they fall into two lungs, and every voxel to the nearer (where no depth
 *    parts it, at the body's mid-plane, with a warning). Other air inside the body goes to its
 *    neighbours, or is fat when InputWindow starts above fat's -100 HU (fat then reads as air).
 *    Where the scan tells gas from aerated lung, FindAirway labels the trachea and the main
 *    bronchi: the gas of a component that leaves the field at its top slice (along the index axis
 *    closest to the head) with a section of 50 to 1000 mm^2 and enters a lung, where it lies
 *    outside both lungs (each lung's parenchyma, the lung class away from that gas, closed by a
 *    ball of 12 mm: the bronchi inside it are lung), with the voxels darker than half-way from gas
 *    to soft tissue in two rings round it outside the lungs (its partial volume). The oesophagus's
 *    gas enters no lung, the stomach's and the bowel's leave no field at its top; a field that
 *    holds the larynx and the mouth shows no trachea leaving it;
 * 4. bone is the bone class, the voxels beside it more than half bone, and the trabecular bone it
 *    encloses (what a cortical ring encloses in a slice across any of the three axes, a deviation
 *    brighter than soft tissue's centre); never the contrast blood connected to the seeded blood
 *    pools (BloodPoolLabels; brighter than half a deviation below the blood class's centre, through
 *    the scan opened by the 6-neighbour cross) nor the two voxels around it; where InputWindow's
 *    ceiling lies below cortical bone (700 HU), bone is the cortex (two deviations above the blood's
 *    centre) away from that blood and not bordered mostly by lung, and the marrow it reaches
 *    within 12 mm (brighter than the vessels' level). The spine is the vertebral column within the
 *    largest bone component: slice by slice across the head-feet axis, the bone within 35 mm of
 *    the column's centre along the left-right axis (the median of the deepest bone within 60 mm of
 *    the body's centre and 20 mm above and below: the vertebral bodies), in pieces that hold a
 *    vertebral body, and the pieces beyond that end within 20 mm (transverse processes); the ribs
 *    joined to the vertebrae at their joints, and every other bone component, are ribs (or other
 *    bone);
 * 5. the organs of input 1 are written over these; where the scan shows contrast blood, FindAorta
 *    labels the aorta from the contrast in front of the spine (where input 1 holds an aorta, the
 *    part its clicks' snake did not reach), and follows its ascending part down through the atria's
 *    label (their snake takes it where the aortic root touches the left atrium);
 * 6. the ventricles end at the heart's base: where the LV's pool meets the atria or the aorta, the
 *    plane through those voxels, its normal towards the pool's farthest voxel (the apex), is the
 *    base, and the RV's pool more than 10 mm above it (its snake's run into the right atrium) goes
 *    to the atria; no wall grows more than 10 mm above it, and below it the fat and lung within
 *    RightVentricleWallThickness of a pool are wall (a ventricle's blood lies inside its wall,
 *    which partial volume hides where it is 3-4 mm thick);
 *    the myocardium: a CT cannot tell heart muscle (about 50 HU) from the soft tissue around it
 *    (about 40 HU) voxel by voxel, but it can on average. The intensity is averaged by a
 *    Gaussian of WallSmoothingSigma mm (at least 1.5 voxels) over soft tissue alone (its voxels
 *    whose 26 neighbours are all soft tissue and that are darker than half-way to the pools, so
 *    partial volume with blood or lung does not bias it); the Gaussian grows by half, up to two
 *    and a half times, while the contrast below stands less than four times above the average's
 *    noise. The wall's level is
 *    the median of that average 3-6 mm from the blood pools (BloodPoolLabels of input 1); the
 *    surroundings' level the median 0-10 mm beyond MaximumWallThickness. The myocardium is the
 *    soft tissue connected to the pools, within MaximumWallThickness of them, whose average lies
 *    on the wall's side of the half-way level, and the soft tissue within MinimumWallThickness of
 *    them (a ventricle's blood lies inside its wall), with its cavities filled; lung, fat, bone and
 *    other organs stop it. Its outline is then the heart's (pools and wall) averaged over the same
 *    Gaussian and cut at one half: the average resolves nothing finer than its width, so the
 *    threshold's bumps and dents of that size are its noise (a convex outline moves in by about the
 *    width squared over its radius). Where the two levels differ by less than MinimumWallContrast (or twice
 *    the average's noise), intensity cannot tell the wall: a warning says so and the wall is the
 *    soft tissue within WallThickness of the pools (RightVentricleWallThickness of the RV's, the
 *    second of BloodPoolLabels). Field data "MyocardiumLevels": wall level,
 *    surroundings' level, threshold, noise (HU), 1 where intensity told the wall (else 0), the
 *    blood pools' level (HU; pools not brighter than the wall by MinimumWallContrast give a
 *    warning: a scan without contrast, or a seed outside the blood pool), and the Gaussian
 *    used (mm);
 * 7. every voxel left undecided goes to the most frequent label among its neighbours (never to a
 *    lung when it is less than half air, brighter than half-way from the lung class to soft tissue,
 *    nor to the airway when brighter than half-way from gas to soft tissue, nor to bone when darker
 *    than soft tissue, while another label reaches it); components
 *    smaller than MinimumComponentVolume are handed to their neighbours the same way, and every
 *    organ but soft tissue, fat, spine and ribs keeps only its largest component.
 * Field data "LabelVolumes" (label, mm^3). Warnings name the organ: no lungs, the lungs split at the
 * mid-plane, no blood pools (no myocardium), pools no brighter than the wall, a pool at the image's border (a
 * scan that cuts the heart), an empty myocardium, a label of input 1 lost.
 * Errors: an empty or non-scalar CT, a non-finite voxel, input 1 on another grid or not a label map.
 *
 * @sa amIntensityClassifier amSnakeSegmentation amMorphologyCleaning amLabelOverlap
 */
#ifndef amTorsoSegmentation_h
#define amTorsoSegmentation_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro
#include "vtkImageAlgorithm.h"

#include <string>
#include <vector>

class ANATOMESHFILTERSSEGMENTATION_EXPORT amTorsoSegmentation : public vtkImageAlgorithm
{
public:
  static amTorsoSegmentation* New();
  vtkTypeMacro(amTorsoSegmentation, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The organs segmented from seeds (input port 1, optional).
  void SetOrganConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetOrganData(vtkDataObject* data) { this->SetInputData(1, data); }

  ///@{
  /// The tissue classes read from the scan's own histogram (default on) rather than fixed CT
  /// ranges (off: boundaries -925, -475, -30, 170, 400 HU).
  vtkSetMacro(AutomaticClasses, bool);
  vtkGetMacro(AutomaticClasses, bool);
  vtkBooleanMacro(AutomaticClasses, bool);
  ///@}

  ///@{
  /// The most noise (HU, standard deviation) the classes are read at (default 25): a noisier scan
  /// is smoothed by the least Gaussian that brings its noise (measured from neighbouring voxels'
  /// second differences) down to four fifths of this; field data "Noise" gives the noise measured
  /// and the Gaussian (mm).
  vtkSetClampMacro(MaximumNoise, double, 1.0, 1e6);
  vtkGetMacro(MaximumNoise, double);
  ///@}

  ///@{
  /// The window (width, level; HU) that mapped the input to 0..255, e.g. 400 40 for a mediastinal
  /// window (default 0 0: the window the input carries in its field data "IntensityWindow",
  /// amImageReader's IntensityWindow, or none: the input is in HU).
  vtkSetVector2Macro(InputWindow, double);
  vtkGetVector2Macro(InputWindow, double);
  ///@}

  ///@{
  /// Gaps in the body wall (mm) that the outside air may not pass; 0: none. A scan windowed above
  /// fat (its fat reads as air) shows the body wall as muscle and bone alone, with holes; closing
  /// them by this distance keeps the lungs inside the body. Default -1: automatic, 15 mm where
  /// InputWindow starts above fat's -100 HU, else 0.
  vtkSetClampMacro(BodyGapClosing, double, -1.0, 100.0);
  vtkGetMacro(BodyGapClosing, double);
  ///@}

  ///@{
  /// The lungs are the air inside the body opened by a ball of this radius, mm; 0: not opened.
  /// For scans windowed above fat, where the fat beside the lungs (a thinner layer) reads as air
  /// too. Default -1: automatic, 12 mm where InputWindow starts above fat's -100 HU, else 0.
  vtkSetClampMacro(LungOpening, double, -1.0, 100.0);
  vtkGetMacro(LungOpening, double);
  ///@}

  ///@{
  /// Components smaller than this are handed to their neighbours, mm^3 (default 50).
  vtkSetClampMacro(MinimumComponentVolume, double, 0.0, 1e12);
  vtkGetMacro(MinimumComponentVolume, double);
  ///@}

  ///@{
  /// Where the scan shows contrast blood, find the aorta (label 8): of the contrast blood outside
  /// every organ, bone and lung, opened by the 6-neighbour cross, the piece with the most voxels in
  /// front of the vertebral column within 45 mm of its centre, slice by slice (the descending aorta
  /// beside the vertebral bodies, with its arch and ascending part), if it runs there for at least
  /// 50 mm and holds at least 5 cm3 (default on). Where input 1 holds an aorta, this adds what its
  /// clicks' snake did not reach (a snake ends MaximumDistance from its clicks). Then each section
  /// of the aorta at least 20 mm wide is followed down, slice by slice, through the atria's label
  /// (11): the atria's voxels under it, within 1.2 times the tube's radius of the section above,
  /// become aorta while each section keeps 0.5 to 1.3 times the first one's area (the atria's snake
  /// takes the ascending aorta where the root touches the left atrium).
  vtkSetMacro(FindAorta, bool);
  vtkGetMacro(FindAorta, bool);
  vtkBooleanMacro(FindAorta, bool);
  ///@}

  ///@{
  /// Find the patient table and leave it out of the body (step 1; default on): off for a scan whose
  /// thin plates constant along the head-feet axis are the patient's own.
  vtkSetMacro(FindPatientTable, bool);
  vtkGetMacro(FindPatientTable, bool);
  vtkBooleanMacro(FindPatientTable, bool);
  ///@}

  ///@{
  /// Find the trachea and the main bronchi (label 12, Airway; step 3; default on): where the scan
  /// tells gas from aerated lung, the gas of a component that leaves the field at its top with a
  /// section of 50 to 1000 mm^2 and enters a lung, outside both lungs closed by a 12 mm ball, with its
  /// partial volume.
  /// Off for a label scheme that has no airway (the trachea is then lung where it joins them).
  vtkSetMacro(FindAirway, bool);
  vtkGetMacro(FindAirway, bool);
  vtkBooleanMacro(FindAirway, bool);
  ///@}

  /// The labels of input 1 that the myocardium wraps (default 6 7: the LV and RV blood pools).
  void SetBloodPoolLabels(int lv, int rv);
  void AddBloodPoolLabel(int label);
  void RemoveAllBloodPoolLabels();
  int GetNumberOfBloodPoolLabels() { return static_cast<int>(this->BloodPoolLabels.size()); }
  int GetBloodPoolLabel(int i) { return this->BloodPoolLabels.at(i); }

  ///@{
  /// The farthest the myocardium reaches from the blood pools, mm (default 40); the wall's
  /// thickness where intensity cannot tell it, mm (default 10), and the RV's there (the second of
  /// BloodPoolLabels; default 4: its free wall is a third of the LV's); the least wall, mm (default 3,
  /// the thinnest a ventricle's wall is: the soft tissue this near the pools is myocardium whatever
  /// its intensity, so a ventricle's blood lies inside its wall even where a thin wall's average reads
  /// as the tissue around it; 0: none).
  vtkSetClampMacro(MaximumWallThickness, double, 1.0, 200.0);
  vtkGetMacro(MaximumWallThickness, double);
  vtkSetClampMacro(WallThickness, double, 0.5, 200.0);
  vtkGetMacro(WallThickness, double);
  vtkSetClampMacro(RightVentricleWallThickness, double, 0.5, 200.0);
  vtkGetMacro(RightVentricleWallThickness, double);
  vtkSetClampMacro(MinimumWallThickness, double, 0.0, 200.0);
  vtkGetMacro(MinimumWallThickness, double);
  ///@}

  ///@{
  /// The Gaussian that averages the wall's intensity, mm (default 2), and the least difference
  /// between the wall's and the surroundings' levels that tells them apart, HU (default 5).
  vtkSetClampMacro(WallSmoothingSigma, double, 0.1, 20.0);
  vtkGetMacro(WallSmoothingSigma, double);
  vtkSetClampMacro(MinimumWallContrast, double, 0.0, 1e6);
  vtkGetMacro(MinimumWallContrast, double);
  ///@}

protected:
  amTorsoSegmentation();
  ~amTorsoSegmentation() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The settings of a run, for its provenance (window: the one used).
  std::string SettingsText(const double window[2]) const;

  bool AutomaticClasses;
  double MaximumNoise;
  double InputWindow[2];
  double BodyGapClosing;
  double LungOpening;
  double MinimumComponentVolume;
  bool FindAorta;
  bool FindPatientTable;
  bool FindAirway;
  std::vector<int> BloodPoolLabels;
  double MaximumWallThickness;
  double WallThickness;
  double RightVentricleWallThickness;
  double MinimumWallThickness;
  double WallSmoothingSigma;
  double MinimumWallContrast;

private:
  amTorsoSegmentation(const amTorsoSegmentation&) = delete;
  void operator=(const amTorsoSegmentation&) = delete;
};

#endif
