#include "amTetraImproveMesh.h"

#include <algorithm>

namespace amTetraImprove
{
/// Splits the free face f (a 2-6 split: both tetrahedra on it in three), then moves the new
/// vertex where its star is best. A sliver with three faces on the surface has every edge fixed,
/// so no edge split reaches it; its one free face does. The new vertex takes the place of the
/// face's corners in turn, so the six tetrahedra keep the orientation of the two they replace.
/// Undone unless every element around the new vertex is better than the worst of the two and
/// reaches 'goal'.
bool SplitFace(Mesh& m, const Tri& f, double goal)
{
  if (m.FixedFaces.count(f))
    return false;
  int t = -1, s = -1;
  for (int u : m.Inc[f[0]])
    if (m.Has(u, f[1]) && m.Has(u, f[2]))
      (t < 0 ? t : s) = u;
  if (s < 0 || m.R[s] != m.R[t])
    return false;
  const double old = std::min(m.Objectives[t], m.Objectives[s]);
  double centroid[3];
  for (int k = 0; k < 3; ++k)
    centroid[k] = (m.X(f[0])[k] + m.X(f[1])[k] + m.X(f[2])[k]) / 3.0;
  const int w = m.AddPoint(centroid);
  const int region = m.R[t];
  const std::vector<Tet> before = { m.T[t], m.T[s] };
  m.Kill(t);
  m.Kill(s);
  for (const Tet& b : before)
    for (int k = 0; k < 4; ++k)
      if (b[k] == f[0] || b[k] == f[1] || b[k] == f[2])
      {
        Tet y = b;
        y[k] = w;
        m.Add(y, region);
      }
  return KeepInsertion(m, w, before, region, old, goal);
}
}
