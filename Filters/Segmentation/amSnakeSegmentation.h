/**
 * @class   amSnakeSegmentation
 * @brief   Deformable-contour (level-set) segmentation of organs grown from user seeds.
 *
 * The paper's method: a user who knows anatomy places a few seeds; a snake grows from them.
 * Seeds come from AddSeed(x, y, z, label) (world coordinates, mm) and/or input port 1, a point
 * set whose point-data array "Label" (SeedLabelArrayName) gives each point's label (SeedLabel when
 * absent), so ParaView's point widgets and Python lists both work.
 *
 * For each label (the order its seeds first appear in is its precedence):
 * 1. the image is cropped to the seeds' bounding box grown by MaximumDistance (mm) and smoothed by
 *    a Gaussian of SmoothingSigma (mm);
 * 2. the intensity of the organ is sampled in balls of SeedRadius (mm) around its seeds; the
 *    accepted interval is mean ± max(IntensityTolerance x standard deviation,
 *    MinimumIntensityWindow), or [LowerThreshold, UpperThreshold] when AutomaticThresholds is off;
 * 3. the initial contour is the union of the seed balls (at least 2.5 voxels in radius, so
 *    curvature cannot collapse it at coarse spacing), and it evolves as a
 *    threshold level set (ITK ThresholdSegmentationLevelSetImageFilter): it expands where the
 *    smoothed intensity is in the interval, is held back elsewhere, and is kept smooth by
 *    CurvatureScaling, until NumberOfIterations, an RMS change below MaximumRMSError, or 20
 *    iterations that leave the number of voxels inside unchanged (on a noisy scan the front
 *    settles into a two-state cycle whose RMS change never falls below the bound); in 3-D with
 *    CoarseToFine, the contour first evolves on the image at twice the voxel size, and the full
 *    resolution continues from there; in 3-D a full-resolution evolution runs on the box of its
 *    starting contour grown by 12 voxels (the same front as on the whole region, which it takes
 *    instead when the front ends within 6 voxels of the box's side);
 * 4. with RefineToHalfContrast, the intensity of a 2-voxel shell outside the contour (beyond
 *    twice SmoothingSigma) gives the
 *    surroundings' level; the threshold facing it moves half-way (the partial-volume boundary)
 *    and the contour evolves again from where it stopped.
 * Organs never overlap. Where their regions do (two chambers of the same contrast joined by a
 * valve's opening, or by a streak of contrast across a septum), with SeedsCompete (default on)
 * each voxel goes to the organ whose seeds reach it first along a path inside its own region,
 * the earlier organ on a tie (amSeedCompetition), and a voxel no front reaches (cut off from its
 * seeds by the other organs) to none. A path is as long as its steps, each step lengthened by the
 * smoothed intensity where it nears the edge of its organ's interval (the level-set contours; by
 * up to 51 times at the edge), so a wall the regions both run over (a septum thinned by partial
 * volume) parts two pools where it is, and an opening without a wall (a valve's) between the
 * seeds: a click in the left atrium parts it from the LV's click, and the ventricles part at the
 * septum wherever their clicks lie. With SeedsCompete off, the earlier organ keeps every voxel it
 * claims.
 * Mode ThreeD (default) evolves one 3-D surface. Mode SliceBySlice is the paper's propagation:
 * each seed's slice (along SliceAxis) is segmented in 2-D, then each next slice starts from the
 * previous contour (eroded by one pixel) and keeps only what overlaps it; propagation stops in a
 * direction when the section vanishes (area < MinimumSliceArea mm^2) or its area changes by more
 * than MaximumAreaChange times from one slice to the next (the structure ends, or merges with
 * another one: an abrupt topology change).
 *
 * ContourModel Polar (slice by slice only) replaces the level set of each section by a star-shaped
 * snake found by dynamic programming (amPolarContour): bounded by OutsideThreshold (fat, lung) where
 * the structure meets them and by edges elsewhere, at most MaximumRadius from its centre, and
 * changing by at most MaximumGrowth mm from one slice to the next. Each seed starts its own track
 * in its slice; each next slice is centred on the last section's centroid, and a track stops as
 * above, where its section's mean intensity falls to MinimumSectionContrast of its seed section's
 * (above OutsideThreshold), or where more than half its section is already segmented (it has met
 * another track). A
 * seed whose section earlier tracks already cover (90 %) starts none; others do, so a seed where
 * two tracks meet in a section that no star-shaped contour covers (the aortic arch) joins them.
 * For vessels whose contents do not have one intensity (a dissection's false lumen, thrombus, the
 * wall) next to tissue of the same intensity, which no intensity interval separates.
 *
 * Output: a label map on the input's grid (scalars "Labels", uint8), field data
 * "SegmentedVolumes" (mm^3 per label) and "Thresholds" (the interval used per label).
 * Errors: no seeds, a seed outside the image, a seed in air (CT below -950 HU, unless
 * AllowAirSeeds), an empty or non-scalar image, a label outside 1..255.
 *
 * References: the CEMRACS 2004 paper (snakes propagated slice by slice from seeds); J. A. Sethian,
 * Level Set Methods and Fast Marching Methods, 1999 (ITK's threshold level set).
 *
 * @sa amIntensityClassifier amMorphologyCleaning amLabelOverlap
 */
#ifndef amSnakeSegmentation_h
#define amSnakeSegmentation_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro
#include "vtkImageAlgorithm.h"

#include <string>
#include <vector>

class ANATOMESHFILTERSSEGMENTATION_EXPORT amSnakeSegmentation : public vtkImageAlgorithm
{
public:
  static amSnakeSegmentation* New();
  vtkTypeMacro(amSnakeSegmentation, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    ThreeD = 0,
    SliceBySlice = 1
  };

  /// Add a seed at world position (x, y, z) mm for organ label (1..255).
  void AddSeed(double x, double y, double z, double label);
  void RemoveAllSeeds();
  int GetNumberOfSeeds() { return static_cast<int>(this->Seeds.size() / 4); }

  /// Connect a point set of seeds (point data SeedLabelArrayName gives labels).
  void SetSeedConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSeedData(vtkDataObject* seeds) { this->SetInputData(1, seeds); }

  ///@{
  /// ThreeD (0, default) or SliceBySlice (1).
  vtkSetClampMacro(Mode, int, ThreeD, SliceBySlice);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /// Slice-by-slice: the index axis slices are taken across (default 2, axial for most scans).
  vtkSetClampMacro(SliceAxis, int, 0, 2);
  vtkGetMacro(SliceAxis, int);
  ///@}

  ///@{
  /// Label of seed-input points without a label array (default 1).
  vtkSetClampMacro(SeedLabel, int, 1, 255);
  vtkGetMacro(SeedLabel, int);
  vtkSetStringMacro(SeedLabelArrayName);
  vtkGetStringMacro(SeedLabelArrayName);
  ///@}

  ///@{
  /// Gaussian smoothing before segmentation, mm (default 1).
  vtkSetClampMacro(SmoothingSigma, double, 0.0, 20.0);
  vtkGetMacro(SmoothingSigma, double);
  ///@}

  ///@{
  /// Radius of the seed balls (intensity sampling and initial contour), mm (default 3).
  vtkSetClampMacro(SeedRadius, double, 0.1, 50.0);
  vtkGetMacro(SeedRadius, double);
  ///@}

  ///@{
  /// Automatic interval: mean +/- max(IntensityTolerance x sd, MinimumIntensityWindow)
  /// (defaults 3 and 100, input units: HU for CT). On an image that carries the window it was
  /// stored through (field data "IntensityWindow", amImageReader's IntensityWindow), this filter's
  /// intensities (MinimumIntensityWindow, LowerThreshold, UpperThreshold, OutsideThreshold,
  /// EdgeContrast) are HU, converted to the image's 0..255.
  vtkSetMacro(AutomaticThresholds, bool);
  vtkGetMacro(AutomaticThresholds, bool);
  vtkBooleanMacro(AutomaticThresholds, bool);
  vtkSetClampMacro(IntensityTolerance, double, 0.0, 100.0);
  vtkGetMacro(IntensityTolerance, double);
  vtkSetClampMacro(MinimumIntensityWindow, double, 0.0, 1e6);
  vtkGetMacro(MinimumIntensityWindow, double);
  ///@}

  ///@{
  /// Explicit interval when AutomaticThresholds is off (defaults 100 and 600 HU: contrast blood).
  vtkSetMacro(LowerThreshold, double);
  vtkGetMacro(LowerThreshold, double);
  vtkSetMacro(UpperThreshold, double);
  vtkGetMacro(UpperThreshold, double);
  ///@}

  ///@{
  /// Level-set weights: propagation (default 1), curvature (smoothness, default 1) and the
  /// Laplacian edge attraction (default 0).
  vtkSetClampMacro(PropagationScaling, double, 0.0, 100.0);
  vtkGetMacro(PropagationScaling, double);
  vtkSetClampMacro(CurvatureScaling, double, 0.0, 100.0);
  vtkGetMacro(CurvatureScaling, double);
  vtkSetClampMacro(EdgeWeight, double, 0.0, 100.0);
  vtkGetMacro(EdgeWeight, double);
  ///@}

  ///@{
  /// Evolution limits: iterations (default 800) and RMS change for convergence (default 0.002).
  vtkSetClampMacro(NumberOfIterations, int, 1, 100000);
  vtkGetMacro(NumberOfIterations, int);
  vtkSetClampMacro(MaximumRMSError, double, 0.0, 1.0);
  vtkGetMacro(MaximumRMSError, double);
  ///@}

  ///@{
  /// How far (mm) an organ may extend beyond its seeds' bounding box (default 150).
  vtkSetClampMacro(MaximumDistance, double, 1.0, 10000.0);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /// Slice-by-slice stopping rule: the largest area ratio between neighbouring slices (default
  /// 2) and the smallest section, mm^2 (default 4).
  vtkSetClampMacro(MaximumAreaChange, double, 1.01, 1000.0);
  vtkGetMacro(MaximumAreaChange, double);
  vtkSetClampMacro(MinimumSliceArea, double, 0.0, 1e6);
  vtkGetMacro(MinimumSliceArea, double);
  ///@}

  ///@{
  /// Automatic thresholds only: after a first evolution, sample the intensity just outside the
  /// contour and move the facing threshold half-way between organ and surroundings (where
  /// partial volume puts the boundary), then evolve again (default on).
  vtkSetMacro(RefineToHalfContrast, bool);
  vtkGetMacro(RefineToHalfContrast, bool);
  vtkBooleanMacro(RefineToHalfContrast, bool);
  ///@}

  ///@{
  /// 3-D mode: the first evolution runs on the image at twice the voxel size (means of 2x2x2
  /// voxels) and the full resolution continues from its contour, which then moves only by a voxel
  /// or two (default on). A part too thin for the coarse grid still grows at full resolution.
  vtkSetMacro(CoarseToFine, bool);
  vtkGetMacro(CoarseToFine, bool);
  vtkBooleanMacro(CoarseToFine, bool);
  ///@}

  ///@{
  /// Slice-by-slice with automatic thresholds: each seed slice's interval comes from its own
  /// seeds, each later slice's from the section found in the previous slice (for vessels whose
  /// contrast changes along their length), instead of all seeds pooled; with
  /// RefineToHalfContrast each section is also refined to half contrast against a ring 2..4
  /// pixels outside it (default off).
  vtkSetMacro(AdaptiveSliceStatistics, bool);
  vtkGetMacro(AdaptiveSliceStatistics, bool);
  vtkBooleanMacro(AdaptiveSliceStatistics, bool);
  ///@}

  enum ContourModels
  {
    LevelSet = 0,
    Polar = 1
  };

  ///@{
  /// LevelSet (0, default): threshold level sets, in either mode. Polar (1): slice by slice only,
  /// each section a star-shaped snake (see the class description).
  vtkSetClampMacro(ContourModel, int, LevelSet, Polar);
  vtkGetMacro(ContourModel, int);
  ///@}

  ///@{
  /// Polar contours: the intensity below which a pixel is not the structure (default -30, HU:
  /// half-way between fat, -100, and soft tissue, +40); an outward intensity drop that counts as
  /// one unit of edge evidence, counted up to three units (default 40: every edge of 120 or more
  /// counts alike, so a dissection flap inside does not beat the wall outside); the largest radius, mm (default 30);
  /// the largest growth of a radius from one slice to the next, mm (default 2).
  vtkSetMacro(OutsideThreshold, double);
  vtkGetMacro(OutsideThreshold, double);
  vtkSetClampMacro(EdgeContrast, double, 1e-6, 1e9);
  vtkGetMacro(EdgeContrast, double);
  vtkSetClampMacro(MaximumRadius, double, 1.0, 1000.0);
  vtkGetMacro(MaximumRadius, double);
  vtkSetClampMacro(MaximumGrowth, double, 0.0, 100.0);
  vtkGetMacro(MaximumGrowth, double);
  ///@}

  ///@{
  /// Polar contours: the cost of a contour's radius per mm (default 0.4; per ray, against up to 9
  /// for an edge and 6 for the structure going on outside): what keeps a contour out of touching
  /// tissue of the structure's intensity. Lower it for organs much larger than a vessel.
  vtkSetClampMacro(AreaCost, double, 0.0, 100.0);
  vtkGetMacro(AreaCost, double);
  ///@}

  ///@{
  /// Polar contours: a track also stops where its section's mean intensity above OutsideThreshold
  /// falls below this fraction of its seed section's (default 0.5; 0 turns the rule off): the
  /// structure has ended in tissue of a duller intensity (a heart's section entering the liver).
  vtkSetClampMacro(MinimumSectionContrast, double, 0.0, 1.0);
  vtkGetMacro(MinimumSectionContrast, double);
  ///@}

  ///@{
  /// Where organs' regions overlap, each shared voxel goes to the organ whose seeds reach it first
  /// through its own region, a wall between them slowing each front (default on); off, to the
  /// organ whose seeds come first.
  vtkSetMacro(SeedsCompete, bool);
  vtkGetMacro(SeedsCompete, bool);
  vtkBooleanMacro(SeedsCompete, bool);
  ///@}

  ///@{
  /// Accept seeds whose neighbourhood is below -950 (air on CT) (default off).
  vtkSetMacro(AllowAirSeeds, bool);
  vtkGetMacro(AllowAirSeeds, bool);
  vtkBooleanMacro(AllowAirSeeds, bool);
  ///@}

protected:
  amSnakeSegmentation();
  ~amSnakeSegmentation() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The properties as recorded in the output's provenance.
  std::string ProvenanceParameters(std::size_t seedCount) const;

  int Mode;
  int SliceAxis;
  int SeedLabel;
  char* SeedLabelArrayName;
  double SmoothingSigma;
  double SeedRadius;
  bool AutomaticThresholds;
  double IntensityTolerance;
  double MinimumIntensityWindow;
  double LowerThreshold;
  double UpperThreshold;
  double PropagationScaling;
  double CurvatureScaling;
  double EdgeWeight;
  int NumberOfIterations;
  double MaximumRMSError;
  double MaximumDistance;
  double MaximumAreaChange;
  double MinimumSliceArea;
  bool AllowAirSeeds;
  bool SeedsCompete;
  bool RefineToHalfContrast;
  bool CoarseToFine;
  bool AdaptiveSliceStatistics;
  int ContourModel;
  double OutsideThreshold;
  double EdgeContrast;
  double MaximumRadius;
  double MaximumGrowth;
  double AreaCost;
  double MinimumSectionContrast;
  std::vector<double> Seeds; // x, y, z, label

private:
  amSnakeSegmentation(const amSnakeSegmentation&) = delete;
  void operator=(const amSnakeSegmentation&) = delete;
};

#endif
