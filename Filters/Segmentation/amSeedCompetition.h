/**
 * @file    amSeedCompetition.h
 * @brief   The label map of several organs whose regions may overlap: each voxel two or more
 *          organs claim goes to the organ whose seeds reach it first along a path inside that
 *          organ's own region.
 *
 * A snake grows from its seeds wherever the scan's intensity lies in its interval; two organs of
 * the same contents (a ventricle and its atrium, the two ventricles where a streak of contrast
 * crosses the septum) then claim each other's voxels, and a precedence rule (the earlier organ
 * keeps the voxel) gives the first organ the second one's cavity, seed and all. Competing fronts
 * do what a user who clicked both expects: the fronts start at the seeds, advance through their
 * own regions by path length (Dijkstra over face neighbours, in mm), and a shared voxel belongs to
 * the front that arrives first, the earlier organ on a tie; the boundary between two chambers
 * joined by an opening lies in the opening, between the seeds.
 *
 * Where the scan's intensity is given, a step costs its length times 1 + BoundaryCost m^4, m the
 * voxel's (smoothed) intensity's distance from the middle of the organ's interval in half-widths
 * (0 in the middle, 1 at its edge). Two pools whose intervals both take a thin wall between them
 * (a septum blurred by partial volume, which a streaky pool's wide interval reaches) then part at
 * the wall, which each front crosses slowly, instead of half-way between their seeds; through
 * an opening without a wall (a valve's) the fronts go at the pace of path length, as before.
 */
#ifndef amSeedCompetition_h
#define amSeedCompetition_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro

#include <array>
#include <cstddef>
#include <vector>

struct ANATOMESHFILTERSSEGMENTATION_EXPORT amSeedCompetition
{
  /// One organ: its label, its region (Inside, 1 where it claims the voxel, over the box at Lo of
  /// Size voxels) and its seeds (voxel indices in the whole grid).
  struct Organ
  {
    int Label = 0;
    int Lo[3] = { 0, 0, 0 };
    int Size[3] = { 0, 0, 0 };
    const std::vector<unsigned char>* Inside = nullptr;
    std::vector<std::array<int, 3>> Seeds;
    /// The organ's intensity interval; Upper <= Lower: its fronts go by path length alone.
    double Lower = 0.0, Upper = 0.0;
  };

  /// What a step through a voxel at the edge of an organ's interval costs beyond its length, in
  /// lengths (the cost grows as the fourth power of the distance from the interval's middle).
  static constexpr double BoundaryCost = 50.0;

  /// Writes the organs' labels into out (the whole grid of dims, x fastest; 0 where no organ
  /// is), the organs in precedence order; returns each organ's voxels. Competing, each voxel goes
  /// to the first front to reach it, and one no front reaches (cut off from its organ's seeds by
  /// the other fronts) to none; with competing off, a voxel one organ alone claims is that organ's
  /// and one that several claim the earliest claimant's.
  /// intensity: the scan over the box of all the organs' boxes (x fastest), or null (path length).
  static std::vector<std::size_t> Paste(const std::vector<Organ>& organs, const int dims[3], const double spacing[3],
    bool compete, unsigned char* out, const float* intensity = nullptr);
};

#endif
