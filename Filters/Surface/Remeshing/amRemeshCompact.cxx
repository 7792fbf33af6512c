#include "amRemesher.h"

namespace amRemesh
{
namespace
{
/// Keeps the entries of a per-vertex (or per-slot) array whose index 'kept' maps (>= 0), in
/// their order; an array shorter than the map keeps those of its own length. The capacity
/// stays: vertices and triangles added later reuse it.
template<typename T>
void KeepMapped(std::vector<T>& a, const std::vector<int>& kept)
{
  size_t j = 0;
  for (size_t i = 0; i < a.size() && i < kept.size(); ++i)
    if (kept[i] >= 0)
    {
      if (j != i) // (a vector moved onto itself would be left empty)
        a[j] = std::move(a[i]);
      ++j;
    }
  a.resize(j);
}
}

void Remesher::Compact()
{
  Surface& S = this->Mesh;
  // New ids in the order of the old ones: every comparison of ids (the passes' tie-breaks, the
  // order of each star and bin) comes out as before.
  std::vector<int> vertexOf(S.P.size(), -1), triangleOf(S.T.size(), -1);
  int nv = 0, nt = 0;
  for (size_t v = 0; v < S.P.size(); ++v)
    if (S.VAlive[v])
      vertexOf[v] = nv++;
  for (size_t t = 0; t < S.T.size(); ++t)
    if (S.T[t].Alive)
      triangleOf[t] = nt++;
  if (static_cast<size_t>(nv) == S.P.size() && static_cast<size_t>(nt) == S.T.size())
    return;
  for (Triangle& t : S.T)
    if (t.Alive)
      for (int& v : t.V)
        v = vertexOf[v];
  KeepMapped(S.T, triangleOf);
  for (auto& star : S.VT)
    for (int& t : star)
      t = triangleOf[t];
  // A hint to a dead triangle matches no triangle of any star: the same as none.
  for (auto& cluster : S.Cluster)
    for (ClusterEntry& entry : cluster)
      entry.Hint = entry.Hint >= 0 ? triangleOf[entry.Hint] : -1;
  KeepMapped(S.P, vertexOf);
  KeepMapped(S.M, vertexOf);
  KeepMapped(S.Kind, vertexOf);
  KeepMapped(S.VAlive, vertexOf);
  KeepMapped(S.Held, vertexOf);
  KeepMapped(S.VT, vertexOf);
  KeepMapped(S.Cluster, vertexOf);
  KeepMapped(S.Anchor, vertexOf);
  KeepMapped(S.Merged, vertexOf);
  KeepMapped(S.Dirty, vertexOf);
  KeepMapped(S.FlipDirty, vertexOf);
  KeepMapped(this->Parts.Of, vertexOf);
  for (Worker& w : this->Workers)
  {
    std::fill(w.Stamp.begin(), w.Stamp.end(), 0);
    w.StampValue = 0;
    w.LastHit = -1;
    w.PendingHints.clear();
  }
  this->Hausdorff.Forget();
  this->Grid.Rebin();
}
}
