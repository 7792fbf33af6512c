/**
 * @file    amLabelModeFilter.h
 * @brief   The mode (majority) filter of a label map: each voxel takes the most frequent label of
 *          its (2r+1)^3 neighbourhood, its own on a tie; repeated, it removes the salt-and-pepper
 *          of a noisy intensity classification while boundaries move by at most r voxels per pass.
 */
#ifndef amLabelModeFilter_h
#define amLabelModeFilter_h

#include <cstddef>
#include <vector>

namespace amLabelMode
{
/// One pass over the labels (x fastest, dims[0] x dims[1] x dims[2]); outside the image counts as
/// nothing. Each voxel is decided from the labels before the pass, so the order does not matter.
/// Returns the number of voxels that changed.
std::size_t Pass(const int dims[3], int radius, std::vector<unsigned char>& labels);
}

#endif
