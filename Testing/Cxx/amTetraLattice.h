// A tetrahedral lattice for the element improvement's tests (amTetraImproveMesh.h).
#ifndef amTetraLattice_h
#define amTetraLattice_h
#include "amTetraGeometry.h"
#include "amTetraImproveMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace amTest
{
using amTetraImprove::Tet;
/// A lattice of n^3 vertices, each cube in six tetrahedra (region 1), the inner vertices
/// jittered by up to 'jitter' (a fixed sequence), the outer ones fixed.
inline void Lattice(int n, double jitter, std::vector<double>& p, amTetraImprove::Mesh& m)
{
  std::uint64_t state = 12345;
  auto random = [&state]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
  };
  auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  auto outer = [n](
                 int i, int j, int k) { return i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double d = outer(i, j, k) ? 0 : 2 * jitter;
        p.push_back(i + d * random());
        p.push_back(j + d * random());
        p.push_back(k + d * random());
      }
  const size_t nv = p.size() / 3;
  m.Inc.resize(nv);
  m.FixedVertex.assign(nv, 0);
  m.Dirty.assign(nv, 1);
  static const int axes[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i)
        for (const auto& a : axes)
        {
          int c[3] = { i, j, k };
          Tet t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[a[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          if (amTetraGeometry::SignedVolume(&p[3 * t[0]], &p[3 * t[1]], &p[3 * t[2]], &p[3 * t[3]]) < 0)
            std::swap(t[2], t[3]);
          m.Add(t, 1);
        }
  for (int v = 0; v < static_cast<int>(nv); ++v)
    m.FixedVertex[v] = outer(v % n, (v / n) % n, v / (n * n));
}
}
#endif
