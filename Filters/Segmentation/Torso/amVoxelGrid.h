/**
 * @file    amVoxelGrid.h
 * @brief   Plain operations on voxel masks and label maps that the torso segmentation chains:
 *          connected components, hole filling, erosion and opening, Gaussian smoothing, the
 *          Euclidean distance transform, and the hand-over of dropped voxels to their neighbours.
 *
 * Voxels are stored x fastest, as VTK stores image scalars: index (k * N[1] + j) * N[0] + i.
 * Distances and Gaussian widths are in millimetres (per-axis spacing).
 */
#ifndef amVoxelGrid_h
#define amVoxelGrid_h

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

struct amVoxelGrid
{
  int N[3] = { 0, 0, 0 };
  double Spacing[3] = { 1.0, 1.0, 1.0 };

  std::size_t Size() const { return static_cast<std::size_t>(this->N[0]) * this->N[1] * this->N[2]; }
  std::size_t Index(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * this->N[1] + j) * this->N[0] + i;
  }
  void Ijk(std::size_t id, int ijk[3]) const
  {
    ijk[0] = static_cast<int>(id % this->N[0]);
    ijk[1] = static_cast<int>((id / this->N[0]) % this->N[1]);
    ijk[2] = static_cast<int>(id / (static_cast<std::size_t>(this->N[0]) * this->N[1]));
  }
  double VoxelVolume() const { return this->Spacing[0] * this->Spacing[1] * this->Spacing[2]; }
  /// Calls f(neighbour id) for the 6 face neighbours inside the grid.
  template<typename F>
  void FaceNeighbours(std::size_t id, F&& f) const
  {
    int c[3];
    this->Ijk(id, c);
    const std::size_t step[3] = { 1, static_cast<std::size_t>(this->N[0]),
      static_cast<std::size_t>(this->N[0]) * this->N[1] };
    for (int a = 0; a < 3; ++a)
    {
      if (c[a] > 0)
        f(id - step[a]);
      if (c[a] + 1 < this->N[a])
        f(id + step[a]);
    }
  }
  /// Calls f(neighbour id) for the up to 26 neighbours inside the grid.
  template<typename F>
  void AllNeighbours(std::size_t id, F&& f) const
  {
    int c[3];
    this->Ijk(id, c);
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
        {
          const int i = c[0] + di, j = c[1] + dj, k = c[2] + dk;
          if ((di || dj || dk) && i >= 0 && j >= 0 && k >= 0 && i < this->N[0] && j < this->N[1] && k < this->N[2])
            f(this->Index(i, j, k));
        }
  }
};

using amVoxelMask = std::vector<std::uint8_t>;

namespace amVoxel
{
/// 6-connected components of the mask: id[v] = component (0..n-1, in the order of their first
/// voxel), -1 outside the mask; sizes[c] = voxels in component c. Returns n.
int Components(const amVoxelGrid& g, const amVoxelMask& mask, std::vector<int>& id, std::vector<std::size_t>& sizes);

/// Sets every voxel outside the mask that no 6-connected path outside the mask links to the
/// border of the grid (a cavity), and returns how many it set.
std::size_t FillHoles(const amVoxelGrid& g, amVoxelMask& mask);

/// The voxel ids of slice s across axis, pixel by pixel: axis (axis + 1) % 3 runs fastest (the
/// slice's width, g.N[(axis + 1) % 3]), then (axis + 2) % 3. Into voxel (resized).
void SliceVoxels(const amVoxelGrid& g, int axis, int s, std::vector<std::size_t>& voxel);

/// The 4-connected pieces of the pixels of a slice (width pixels a row) where 'in' is set:
/// id[p] = piece (0..n-1, in the order of their first pixel), -1 elsewhere. Returns n.
int SlicePieces(const std::vector<char>& in, int width, std::vector<int>& id);

/// The holes of the mask within its slices across axis: the 4-connected pieces of a slice outside
/// the mask that do not reach the slice's border, of at most maximumVoxels (what a ring of the mask
/// encloses in a slice, such as a bone's marrow inside its cortex).
amVoxelMask SliceHoles(const amVoxelGrid& g, const amVoxelMask& mask, int axis, std::size_t maximumVoxels);

/// Voxels of the mask whose 26 neighbours are all in it (outside the grid counts as in it).
amVoxelMask Erode26(const amVoxelGrid& g, const amVoxelMask& mask);

/// Opening by the 6-neighbour cross: removes sheets and threads one voxel thick.
amVoxelMask Open6(const amVoxelGrid& g, const amVoxelMask& mask);

/// Dilation by rings of 26-neighbours (rings of them).
amVoxelMask Dilate26(const amVoxelGrid& g, const amVoxelMask& mask, int rings);

/// Separable Gaussian of standard deviation sigma (mm) in place, truncated at 3 sigma; the grid's
/// border is extended by its edge values.
void Gaussian(const amVoxelGrid& g, std::vector<float>& field, double sigma);

/// The noise of a scan (its standard deviation, robustly: from the median second difference of
/// neighbours along the first axis, where all three are above floor).
double NoiseLevel(const amVoxelGrid& g, const float* values, float floor);

/// The factor by which Gaussian(g, field, sigma) scales the standard deviation of white noise.
double GaussianNoiseFactor(const amVoxelGrid& g, double sigma);

/// The least Gaussian (mm, in steps of a twentieth of the finest voxel, at most four voxels) that
/// brings white noise of the given standard deviation down to target.
double GaussianForNoise(const amVoxelGrid& g, double noise, double target);

/// Exact Euclidean distance (mm) of every voxel centre to the nearest voxel of the mask (0 in it;
/// a large value everywhere when the mask is empty). Felzenszwalb-Huttenlocher, per axis.
std::vector<float> Distance(const amVoxelGrid& g, const amVoxelMask& mask);

/// Distance (as Distance) where it is at most reach (mm), the largest float beyond: computed over
/// the mask's box grown by reach alone.
std::vector<float> DistanceWithin(const amVoxelGrid& g, const amVoxelMask& mask, double reach);

/// The depth of each voxel of the region: its distance (mm) to the nearest voxel outside it (0
/// outside; the grid's border is not outside). Distance of the complement, over the region's box.
std::vector<float> Depth(const amVoxelGrid& g, const amVoxelMask& region);

/// The basins of a depth map over the mask (e.g. the distance to the mask's outside): a watershed
/// that floods from the deepest voxels down, 6-connected. Where two floods meet they merge unless
/// each has risen at least `dynamic` (the depth's unit) above the level where they meet, so a
/// basin is a part of the mask joined to the rest by a neck at least that much thinner than its
/// own deepest point. basin[v] = 0..n-1 (in the order of each basin's first voxel), -1 outside the
/// mask. Returns n.
int Basins(const amVoxelGrid& g, const amVoxelMask& mask, const std::vector<float>& depth, double dynamic,
  std::vector<int>& basin);

/// Hands every voxel whose label is Pending to the most frequent label among its 26 neighbours
/// that are not Pending, front by front (each front decided from the previous state, so the
/// result does not depend on the visiting order). Returns the voxels handed over. refuses(v, l),
/// when given, keeps label l from voxel v while another label can reach it (a voxel whose only
/// neighbours are refused takes them).
constexpr std::uint8_t Pending = 255;
std::size_t HandOver(const amVoxelGrid& g, std::vector<std::uint8_t>& labels,
  const std::function<bool(std::size_t, std::uint8_t)>& refuses = nullptr);

/// Marks Pending every component (6-connected) of a non-zero label smaller than minimumVoxels,
/// and every component but the largest of the labels flagged in single[label]; then hands them
/// over. Returns the voxels that changed label.
std::size_t DropSmallComponents(
  const amVoxelGrid& g, std::vector<std::uint8_t>& labels, std::size_t minimumVoxels, const std::vector<bool>& single);
}

#endif
