/**
 * @class   amSnakeTracker
 * @brief   SnakeSegmentation's algorithm for one organ (one label) without the pipeline: from its
 *          seeds and a region of interest of the scan to the organ's voxels.
 *
 * The organ's intensity interval comes from balls around its seeds (mean +- IntensityTolerance
 * standard deviations, at least MinimumIntensityWindow wide) or is given. The contour grows from
 * the balls: as one 3-D threshold level set (ITK), slice after slice along SliceAxis (the CEMRACS
 * paper's propagation; each section starts from the previous one, eroded), or slice after slice
 * as star-shaped polar contours (amPolarContour). A refinement then moves the interval's edge
 * that faces the surroundings half-way to the surroundings' mean (where partial volume puts the
 * boundary) and evolves again. Plain C++ (ITK inside); amSnakeSegmentation converts, calls it per
 * label in order of precedence, and pastes.
 *
 * @sa amSnakeSegmentation amPolarContour
 */
#ifndef amSnakeTracker_h
#define amSnakeTracker_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

class ANATOMESHFILTERSSEGMENTATION_EXPORT amSnakeTracker
{
public:
  struct Parameters
  {
    enum ModeType
    {
      ThreeD = 0,
      SliceBySlice = 1
    };
    enum ContourModelType
    {
      LevelSet = 0,
      Polar = 1
    };
    int Mode = ThreeD;
    int SliceAxis = 2;
    int ContourModel = LevelSet;
    double SmoothingSigma = 1.0; // mm
    double SeedRadius = 3.0;     // mm
    bool AutomaticThresholds = true;
    double IntensityTolerance = 3.0;
    double MinimumIntensityWindow = 100.0;
    double LowerThreshold = 100.0, UpperThreshold = 600.0;
    double PropagationScaling = 1.0, CurvatureScaling = 1.0, EdgeWeight = 0.0, MaximumRMSError = 0.002;
    int NumberOfIterations = 800;
    // Stop a level set once its inside keeps its size (amSnakeLevelSet::Evolve), not only on RMS.
    bool StopOnStall = true;
    double MaximumAreaChange = 2.0;
    double MinimumSliceArea = 4.0; // mm^2
    bool RefineToHalfContrast = true;
    // 3-D only: the first evolution runs on the region at twice the voxel size, the full
    // resolution continuing from its contour.
    bool CoarseToFine = true;
    // 3-D only: the full resolution evolves on the box of its initial contour grown by this many
    // voxels (EvolveInBox); 6 or fewer: on the whole region.
    int BoxMargin = 12;
    bool AdaptiveSliceStatistics = false;
    // Polar contours.
    double OutsideThreshold = -30.0, EdgeContrast = 40.0, MaximumRadius = 30.0, MaximumGrowth = 2.0;
    double AreaCost = 0.4, MinimumSectionContrast = 0.5;
  };

  /// spacing: the scan's voxel size (mm).
  amSnakeTracker(const Parameters& parameters, const double spacing[3]);

  /// The region of interest: its first voxel's index in the scan (lo), its size, and its
  /// intensities (x fastest); smoothed here by SmoothingSigma.
  void SetRegion(const int lo[3], const int size[3], const std::vector<float>& intensities);
  /// The region of interest with intensities already smoothed (Smooth): organs whose regions
  /// overlap share one smoothing of the box that holds them all.
  void SetSmoothedRegion(const int lo[3], const int size[3], std::vector<float> smoothed);
  /// The intensities of a box (x fastest) smoothed by a Gaussian of sigma mm (none when sigma <= 0).
  static std::vector<float> Smooth(const int size[3], const double spacing[3], double sigma, std::vector<float> values);
  /// The organ's seeds (continuous indices in the scan): each one's ball statistics, and the
  /// pooled mean and standard deviation.
  void MeasureSeeds(const std::vector<std::array<double, 3>>& seeds);
  /// The mean intensity in seed i's ball.
  double SeedMean(size_t i) const { return this->SeedStats[i].first; }

  /// Segments the organ. imageMax: the scan's largest intensity (the polar contours' upper bound).
  /// progress (may be empty) is told the fraction done; abort (may be empty) stops the work.
  /// Returns false when a level set failed (Error says why) or the work was aborted (Error empty).
  bool Segment(double imageMax, const std::function<void(double)>& progress, const std::function<bool()>& abort);

  /// Per voxel of the region: 1 inside the organ.
  const std::vector<unsigned char>& Inside() const { return this->InsideMask; }
  /// The intensity interval used at the end.
  double Lower() const { return this->Low; }
  double Upper() const { return this->High; }
  /// The level-set iterations the last Segment ran, over all its evolutions.
  long long Iterations() const { return this->Elapsed; }
  /// The full-resolution evolutions the last Segment ran in a box (EvolveInBox), not on the whole
  /// region.
  int BoxEvolutions() const { return this->Boxed; }
  std::string Error;

private:
  long long Elapsed = 0;
  int Boxed = 0;
  bool Run(double lo, double hi, const std::vector<unsigned char>* initial, double pa, double pb);
  bool RunThreeD(double lo, double hi, const std::vector<unsigned char>* initial, double pa, double pb);
  /// The first 3-D evolution on the region at twice the voxel size (2x2x2 means of the smoothed
  /// intensities), its inside given back on the full grid. False when the level set failed.
  bool RunCoarse(double lo, double hi, std::vector<unsigned char>& inside);
  /// The full-resolution evolution from 'initial' on the box of its inside grown by BoxMargin
  /// voxels (amSnakeTrackerBox.cxx): the region spans MaximumDistance around the seeds, mostly
  /// far from the organ, and each whole-image step of the level set (its speed image, its first
  /// front, the counts of its inside) then covers the box only. The sparse field reads and moves
  /// its values next to the front alone, so a front that stays clear of the box's sides evolves
  /// as on the whole region, voxel for voxel. BoxTooSmall: the box is the region, or the front
  /// ended within six voxels of a side of the box that is not the region's (the caller evolves
  /// on the whole region); BoxFailed: the level set failed (Error says why).
  enum BoxOutcome
  {
    BoxDone,
    BoxTooSmall,
    BoxFailed
  };
  int EvolveInBox(double lo, double hi, const std::vector<unsigned char>& initial, int iterations,
    const std::function<void(double)>& progress);
  bool RunSlices(double lo, double hi);
  bool RunPolar();
  /// Distance (mm) from voxel (i, j, k) of the region to seed s's centre.
  double BallDistance(size_t s, double i, double j, double k) const
  {
    const double dx = (i + this->Lo[0] - this->Seeds[s][0]) * this->Spacing[0],
                 dy = (j + this->Lo[1] - this->Seeds[s][1]) * this->Spacing[1],
                 dz = (k + this->Lo[2] - this->Seeds[s][2]) * this->Spacing[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  /// Distance (mm) from voxel (i, j, k) of the region to the nearest seed's centre.
  double NearestSeed(double i, double j, double k) const
  {
    double d = 1e30;
    for (size_t s = 0; s < this->Seeds.size(); ++s)
      d = std::min(d, this->BallDistance(s, i, j, k));
    return d;
  }
  /// Voxel (iu, iv) of slice is, in-slice axes u, v as RunSlices and RunPolar take them.
  size_t AtSlice(int iu, int iv, int is) const
  {
    const int ax = this->P.SliceAxis, u = ax == 0 ? 1 : 0, v = ax == 2 ? 1 : 2;
    int ijk[3];
    ijk[u] = iu;
    ijk[v] = iv;
    ijk[ax] = is;
    return this->At(ijk[0], ijk[1], ijk[2]);
  }
  /// The stopping rule of a propagation: the section vanished, or changed abruptly (the structure
  /// ended, or merged with another one).
  bool Ends(size_t area, size_t previousArea, double pixelArea) const
  {
    return area * pixelArea < this->P.MinimumSliceArea || area > this->P.MaximumAreaChange * previousArea ||
      area * this->P.MaximumAreaChange < previousArea;
  }
  void Report(double fraction) const
  {
    if (this->Progress)
      this->Progress(fraction);
  }
  size_t At(int i, int j, int k) const { return (static_cast<size_t>(k) * this->Size[1] + j) * this->Size[0] + i; }

  Parameters P;
  double Spacing[3];
  double InitialRadius;
  int Lo[3] = { 0, 0, 0 }, Size[3] = { 0, 0, 0 };
  std::vector<float> Feature; // the smoothed intensities of the region
  std::vector<std::array<double, 3>> Seeds;
  std::vector<std::pair<double, double>> SeedStats; // mean, standard deviation of each ball
  double Mean = 0, Deviation = 0;
  double Low = 0, High = 0;
  std::vector<unsigned char> InsideMask;
  std::function<void(double)> Progress;
  std::function<bool()> Abort;
};

#endif
