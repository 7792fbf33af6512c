#include "amLabelCorners.h"

#include <algorithm>

namespace amLabelCorners
{
namespace
{
// The 12 faces inside the 2x2x2 block around a corner: f = axis * 4 + bitA + 2 * bitB, with
// A = axis + 1, B = axis + 2 (mod 3); the face separates the two octants that differ in 'axis'.
inline int FaceOf(int axis, int octant)
{
  return axis * 4 + Bit(octant, (axis + 1) % 3) + 2 * Bit(octant, (axis + 2) % 3);
}

inline int Octant(int axis, int bitAxis, int bitA, int bitB)
{
  int b[3];
  b[axis] = bitAxis;
  b[(axis + 1) % 3] = bitA;
  b[(axis + 2) % 3] = bitB;
  return b[0] | (b[1] << 1) | (b[2] << 2);
}

/// The four octants around the half-line from a corner along -m (s = 0) or +m (s = 1), in cyclic
/// order, and their labels.
const int kCycle[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
inline void HalfLine(const int lab[8], int m, int s, int oct[4], int q[4])
{
  for (int t = 0; t < 4; ++t)
  {
    oct[t] = Octant(m, s, kCycle[t][0], kCycle[t][1]);
    q[t] = lab[oct[t]];
  }
}

/// Union-find over at most 12 items (the block's faces or octants).
struct UnionFind12
{
  int Parent[12];
  UnionFind12()
  {
    for (int i = 0; i < 12; ++i)
      this->Parent[i] = i;
  }
  int Find(int a)
  {
    while (this->Parent[a] != a)
      a = this->Parent[a] = this->Parent[this->Parent[a]];
    return a;
  }
  void Join(int a, int b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
      this->Parent[std::max(a, b)] = std::min(a, b);
  }
};

}

int CornerCopies(const int lab[8], int comp[12])
{
  bool present[12];
  int any = 0;
  for (int f = 0; f < 12; ++f)
  {
    const int axis = f / 4, bitA = f & 1, bitB = (f >> 1) & 1;
    present[f] = lab[Octant(axis, 0, bitA, bitB)] != lab[Octant(axis, 1, bitA, bitB)];
    any += present[f];
    comp[f] = -1;
  }
  if (!any)
    return 0;
  UnionFind12 uf;
  for (int m = 0; m < 3; ++m)
  {
    const int a = (m + 1) % 3, b = (m + 2) % 3;
    for (int s = 0; s < 2; ++s)
    {
      int oct[4], q[4];
      HalfLine(lab, m, s, oct, q);
      int face[4]; // face between oct[t] and oct[t+1]
      for (int t = 0; t < 4; ++t)
      {
        const int u = (t + 1) % 4;
        const int axis = kCycle[t][0] != kCycle[u][0] ? a : b;
        face[t] = FaceOf(axis, oct[t]);
      }
      const int diag = ResolveEdge(q);
      if (diag < 0)
      {
        int first = -1;
        for (int t = 0; t < 4; ++t)
          if (present[face[t]])
          {
            if (first < 0)
              first = face[t];
            else
              uf.Join(first, face[t]);
          }
      }
      else
      {
        // Connected label on the diagonal 'diag': the faces wrap the two other voxels.
        const int w0 = diag == 0 ? 1 : 0, w1 = w0 + 2; // wrapped positions
        uf.Join(face[(w0 + 3) % 4], face[w0]);
        uf.Join(face[(w1 + 3) % 4], face[w1]);
      }
    }
  }
  int copies = 0;
  int rootComp[12];
  for (int f = 0; f < 12; ++f)
    rootComp[f] = -1;
  for (int f = 0; f < 12; ++f)
    if (present[f])
    {
      const int r = uf.Find(f);
      if (rootComp[r] < 0)
        rootComp[r] = copies++;
      comp[f] = rootComp[r];
    }
  return copies;
}

// A label touching itself only here joins separate fans through other regions' interfaces (e.g.
// octants 0 and 7 of one label with two other labels filling the rest); the octant relabelled
// takes the most frequent other label among its three face neighbours in the block.
int CornerPinch(const int lab[8], const int comp[12], int& newLabel)
{
  // Octants of one label connected through faces or through resolved (kept-connected) edges.
  UnionFind12 octants;
  for (int o = 0; o < 8; ++o)
    for (int k = 0; k < 3; ++k)
      if (lab[o] == lab[o ^ (1 << k)])
        octants.Join(o, o ^ (1 << k));
  for (int m = 0; m < 3; ++m)
    for (int s = 0; s < 2; ++s)
    {
      int oct[4], q[4];
      HalfLine(lab, m, s, oct, q);
      const int diag = ResolveEdge(q);
      if (diag >= 0)
        octants.Join(oct[diag], oct[diag + 2]);
    }
  // The copy of each octant: that of any of its present faces.
  int copyOf[8];
  for (int o = 0; o < 8; ++o)
  {
    copyOf[o] = -1;
    for (int k = 0; k < 3 && copyOf[o] < 0; ++k)
    {
      const int f = FaceOf(k, o);
      if (comp[f] >= 0)
        copyOf[o] = comp[f];
    }
  }
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      if (lab[a] == lab[b] && octants.Find(a) != octants.Find(b) && copyOf[a] >= 0 && copyOf[a] == copyOf[b])
      {
        int best = -1, bestCount = 0;
        for (int k = 0; k < 3; ++k)
        {
          const int c = lab[b ^ (1 << k)];
          if (c == lab[b])
            continue;
          int count = 0;
          for (int j = 0; j < 3; ++j)
            count += lab[b ^ (1 << j)] == c;
          if (count > bestCount || (count == bestCount && c < best))
          {
            best = c;
            bestCount = count;
          }
        }
        if (best < 0)
          continue;
        newLabel = best;
        return b;
      }
  return -1;
}
}
