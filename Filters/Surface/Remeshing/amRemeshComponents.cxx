#include "amRemeshComponents.h"

#include <numeric>

namespace amRemesh
{
void Components::Find(const Surface& S, const Bins& bins, std::array<Worker, 2>& workers)
{
  std::vector<int> parent(S.P.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](int v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Triangle& t : S.T)
    if (t.Alive)
      for (int k = 1; k < 3; ++k)
      {
        const int r0 = root(t.V[0]), r1 = root(t.V[k]);
        if (r0 != r1)
          parent[std::max(r0, r1)] = std::min(r0, r1);
      }
  this->Of.assign(S.P.size(), -1);
  this->Count.clear();
  std::vector<int> id(S.P.size(), -1);
  for (size_t v = 0; v < S.P.size(); ++v)
    if (S.VAlive[v] && !S.VT[v].empty())
    {
      int& c = id[root(static_cast<int>(v))];
      if (c < 0)
      {
        c = static_cast<int>(this->Count.size());
        this->Count.push_back({ 0, 0, 0 });
      }
      this->Of[v] = c;
      const int zone = bins.ZoneAt(S.P[v]);
      if (zone < 2)
        ++this->Count[c][zone];
      ++this->Count[c][2];
    }
  for (Worker& w : workers)
    w.Removed.assign(this->Count.size(), 0);
}
}
