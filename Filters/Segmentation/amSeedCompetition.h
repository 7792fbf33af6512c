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
  };

  /// Writes the organs' labels into out (the whole grid of dims, x fastest; 0 where no organ
  /// is), the organs in precedence order; returns each organ's voxels. A voxel one organ alone
  /// claims is that organ's; one that several claim goes to the first front to reach it (with
  /// competing off, or where no claimant's front reaches it, to the earliest claimant).
  static std::vector<std::size_t> Paste(
    const std::vector<Organ>& organs, const int dims[3], const double spacing[3], bool compete, unsigned char* out);
};

#endif
