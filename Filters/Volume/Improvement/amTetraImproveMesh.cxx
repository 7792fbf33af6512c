#include "amTetraImproveMesh.h"

namespace amTetraImprove
{
bool Mesh::Ring(int u, int v, std::vector<int>& tets, std::vector<int>& ring, size_t most) const
{
  tets.clear();
  ring.clear();
  // Kept between calls: the improvement asks for rings millions of times.
  thread_local std::vector<int> around;
  thread_local std::vector<char> used;
  around.clear();
  for (int t : this->Inc[u])
    if (this->Has(t, v))
      around.push_back(t);
  if (around.size() < 3 || around.size() > most)
    return false;
  auto others = [&](int t, int& a, int& b) {
    a = b = -1;
    for (int w : this->T[t])
      if (w != u && w != v)
        (a < 0 ? a : b) = w;
  };
  int a, b;
  others(around[0], a, b);
  if (amTetraGeometry::SignedVolume(this->X(u), this->X(v), this->X(a), this->X(b)) < 0)
    std::swap(a, b);
  tets.push_back(around[0]);
  ring.push_back(a);
  used.assign(around.size(), 0);
  used[0] = 1;
  int current = b;
  while (current != a)
  {
    bool found = false;
    for (size_t k = 1; k < around.size() && !found; ++k)
    {
      if (used[k])
        continue;
      int x, y;
      others(around[k], x, y);
      if (x == current || y == current)
      {
        used[k] = 1;
        tets.push_back(around[k]);
        ring.push_back(current);
        current = x == current ? y : x;
        found = true;
      }
    }
    if (!found)
      return false;
  }
  return tets.size() == around.size();
}
}
