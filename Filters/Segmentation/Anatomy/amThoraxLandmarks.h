/**
 * @file    amThoraxLandmarks.h
 * @brief   The landmarks of a segmented thorax that a simulation needs, computed rather than
 *          typed: the left ventricle's long axis, apex and base, a stimulus site at the apex, and
 *          the standard 12-lead ECG electrodes on the segmented skin.
 *
 * The label map uses the thorax phantom's scheme (amThoraxPhantomModel: 0 outside, 3/4 lungs,
 * 5 myocardium, 6 LV blood, 7 RV blood). Positions are world millimetres in the patient's LPS frame
 * (x to the left, y posterior, z superior), so the rules below are anatomical, whatever the storage
 * order of the voxels:
 * - long axis: the principal axis of the ventricles' mass (myocardium and pools), pointed to the
 *   patient's left, anterior and inferior (where every heart's apex points);
 * - endocardial apex: the LV pool's farthest voxel along the axis; epicardial apex: the
 *   myocardium's farthest voxel beyond it within 15 mm of the axis through it; base: the centre of
 *   the pool's voxels within 5 mm of its other end (the valve plane); stimulus: half-way between
 *   the two apices (mid-wall);
 * - sternum: at V1's level, the bone (labels 9, 10) in front of the heart's centre that spans the
 *   skin's mid-line (of the bone within 30 mm of it, the run along x that holds it, 10-60 mm wide),
 *   within half an intercostal space above and below;
 * - electrodes on the trunk's skin (the basin of the body's depth that holds the LV's pool, parts
 *   joined by necks 10 mm thinner than their deepest point being basins of their own; its voxels
 *   beside the outside or another basin: arms apart from the trunk or against it carry none): V4
 *   where the line from the apex
 *   straight forward meets the skin (the apex beat, 5th intercostal space, mid-clavicular); V1 and V2
 *   an intercostal space (25 mm) higher, at the sternum's right and left borders (where no sternum is
 *   found, 25 mm right and left of the body's mid-line), on the front;
 *   V6 the skin's leftmost point at V4's level (mid-axillary), V5 half-way round from V4 to V6 (the
 *   angle about the body's centre at that level), V3 half-way round from V2 to V4; the limb
 *   electrodes on the torso as Mason and Likar place them: RA and LA below the clavicles (at the
 *   lungs' top, 60 % of the way from the mid-line to the side, on the front), LL on the left lower
 *   front 50 mm below the lungs' bottom (or the body's lowest level).
 */
#ifndef amThoraxLandmarks_h
#define amThoraxLandmarks_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class ANATOMESHFILTERSSEGMENTATION_EXPORT amThoraxLandmarks
{
public:
  struct Grid
  {
    int N[3] = { 0, 0, 0 };
    /// World position of voxel (i, j, k): Row[r][0] i + Row[r][1] j + Row[r][2] k + Row[r][3].
    double Row[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
  };

  struct Point
  {
    std::string Name;
    std::array<double, 3> X;
  };

  struct Result
  {
    /// RA, LA, LL, V1..V6 (the order of amTorsoPotential's ElectrodePositions), then
    /// LVApexEndocardium, LVApexEpicardium, LVBase, Stimulus, and Sternum where it is found (the
    /// centre of its bone at V1's level).
    std::vector<Point> Points;
    std::array<double, 3> LongAxis{}; // unit, base to apex
    double LongAxisLength = 0.0;      // mm, base to epicardial apex
    std::string Problem;              // why the landmarks cannot be found; empty when they are
  };

  static Result Find(const Grid& grid, const std::vector<std::uint8_t>& labels);

  /// The position of a named point of the result (false when it has none).
  static bool Get(const Result& r, const std::string& name, double x[3]);
};

#endif
