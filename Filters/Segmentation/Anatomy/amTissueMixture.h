/**
 * @file    amTissueMixture.h
 * @brief   A CT's tissue classes read from the scan itself: a Gaussian mixture fitted by
 *          expectation-maximisation to the histogram of the body's intensities, each class's centre
 *          held inside its anatomical range.
 *
 * The classes and the ranges their centres may take (HU; wide enough for any contrast phase,
 * kernel, noise and patient, narrow enough that no class can take another's place):
 *
 * | class | centre range   | what it is                                                   |
 * |-------|----------------|--------------------------------------------------------------|
 * | Air   | -1100 .. -950  | gas: trachea, bowel, and what a window's floor clips          |
 * | Lung  | -950 .. -400   | aerated lung parenchyma (inspiration about -850)              |
 * | Fat   | -200 .. -40    | adipose tissue                                                |
 * | Soft  | -20 .. 120     | muscle, organs, unenhanced blood, myocardium                  |
 * | Blood | 120 .. 600     | contrast-enhanced blood (arterial to late phase)              |
 * | Bone  | 400 .. 1600    | cortical bone (trabecular bone lies among soft and blood)     |
 *
 * A uniform component over the whole range takes the partial-volume voxels that lie between two
 * classes, so they do not widen the classes' spreads. A class is kept when it holds at least
 * MinimumWeight of the body and its centre did not end at the edge of its range: a centre pinned
 * at its edge is the tail of a neighbour (the soft tissue's upper tail in a scan without contrast,
 * the lung in a scan windowed above it whose floor clips lung, fat and air to one value); the fit
 * is then repeated without it. The class boundaries are half-way between neighbouring centres
 * (the partial-volume boundary of two tissues), except:
 * - Soft|Blood lies at least 2.5 spreads below the blood's centre, so that an enhanced wall
 *   (late phase) stays soft tissue;
 * - where the scan shows no bone peak (a crop without bone, thin bone blurred by coarse voxels),
 *   bone is still what lies beyond half-way from soft tissue to cortical bone (700 HU) and 3
 *   spreads above any contrast blood, or, in a scan without contrast, beyond 3 spreads above
 *   soft tissue (trabecular bone at coarse voxels): Found says there was no peak, the range is
 *   kept;
 * - the boundary below Bone lies half-way between soft tissue and bone (thin bones survive partial
 *   volume), raised to 3 spreads above the blood's centre where contrast is that bright.
 */
#ifndef amTissueMixture_h
#define amTissueMixture_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro

#include <array>
#include <cstddef>
#include <string>
#include <vector>

class ANATOMESHFILTERSSEGMENTATION_EXPORT amTissueMixture
{
public:
  /// The class ids are amIntensityClassifier's CT classes (0 air .. 5 bone).
  enum Class
  {
    Air = 0,
    Lung = 1,
    Fat = 2,
    Soft = 3,
    Blood = 4,
    Bone = 5,
    NumberOfClasses = 6
  };

  struct Component
  {
    double Mean = 0.0;   // HU
    double Sigma = 0.0;  // HU
    double Weight = 0.0; // fraction of the body
    bool Found = false;
  };

  struct Result
  {
    std::array<Component, NumberOfClasses> Classes;
    double Uniform = 0.0; // weight of the partial-volume component
    /// Upper boundary of each class (HU): class c is [Upper[c-1], Upper[c]) (Air from -inf, Bone to
    /// +inf); a class not found has an empty range, except bone.
    std::array<double, NumberOfClasses> Upper{};
    std::size_t Samples = 0;
    int Iterations = 0;
    /// Empty when the scan's classes were found; else why not (no body, no soft tissue).
    std::string Problem;
  };

  /// The anatomical range of a class's centre (HU) and its name.
  static void CentreRange(int c, double& low, double& high);
  static const char* Name(int c);

  /// Fits the mixture to the histogram of the values (HU) where mask is non-zero (every value when
  /// mask is null). Deterministic: the same values give the same result on any thread count.
  static Result Fit(const float* values, const unsigned char* mask, std::size_t n, double minimumWeight = 0.002);
  static Result Fit(const double* values, const unsigned char* mask, std::size_t n, double minimumWeight = 0.002);

  /// The fit on a histogram of the module's bins (4 HU from -1100 HU), holding samples values.
  static Result FitHistogram(const std::vector<double>& histogram, std::size_t samples, double minimumWeight);

  /// The class (0..5) of a value under the result's boundaries.
  static int Classify(const Result& r, double value);
};

#endif
