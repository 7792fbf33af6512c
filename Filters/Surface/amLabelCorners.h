/**
 * @file    amLabelCorners.h
 * @brief   The surface of a label map around one voxel corner: which of the 12 faces of the 2x2x2
 *          block around it separate two labels, how they group into copies of the corner's vertex
 *          (one per connected fan), which voxel edges must stay connected for one label, and where
 *          a label touches itself only at the corner (a pinch no vertex split can make manifold).
 *
 * Private to the label surface extractor (amLabelSurfaceExtractor).
 */
#ifndef amLabelCorners_h
#define amLabelCorners_h

namespace amLabelCorners
{
// Octant o of a voxel corner V: the voxel V - 1 + (o & 1, o >> 1 & 1, o >> 2 & 1).
inline int Bit(int o, int axis)
{
  return (o >> axis) & 1;
}

/// Around a voxel edge, four voxels in cyclic order. Returns -1 when the surface is manifold
/// there, 0 when the label of q0 = q2 must stay connected through the edge, 1 for q1 = q3.
inline int ResolveEdge(const int q[4])
{
  const bool d0 = q[0] == q[2] && q[1] != q[0] && q[3] != q[0];
  const bool d1 = q[1] == q[3] && q[0] != q[1] && q[2] != q[1];
  if (d0 && d1)
    return q[0] > q[1] ? 0 : 1;
  return d0 ? 0 : (d1 ? 1 : -1);
}

/// The surface around one voxel corner (lab: the labels of its 8 octants): which of the 12 block
/// faces are present, and how they group into copies of the corner vertex (one copy per
/// connected fan of faces, comp[f] its copy, -1: absent). Returns the number of copies (0: no
/// surface here).
int CornerCopies(const int lab[8], int comp[12]);

/// Where a label touches itself only at the corner between other regions: the octant whose
/// voxel is to be relabelled (-1: none) and its new label.
int CornerPinch(const int lab[8], const int comp[12], int& newLabel);
}

#endif
