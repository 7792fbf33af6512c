#include "amTetraImproveMesh.h"

#include "vtkSMPTools.h"

namespace amTetraImprove
{
std::vector<std::vector<int>> SmoothingColours(const Mesh& m, size_t n)
{
  // The candidates: the free vertices whose flag is set, and their free neighbours (a move
  // earlier in the pass sets theirs); each vertex decides for itself, on the threads.
  std::vector<char> candidate(n, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n), 1024, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
    {
      if (m.FixedVertex[v])
        continue;
      bool near = m.Dirty[v] != 0;
      for (size_t i = 0; i < m.Inc[v].size() && !near; ++i)
        for (int w : m.T[m.Inc[v][i]])
          near = near || (static_cast<size_t>(w) < n && m.Dirty[w] && !m.FixedVertex[w]);
      candidate[v] = near;
    }
  });
  // Greedy, in the order of the vertices: each takes the first colour none of its coloured
  // neighbours has (a bit set per colour taken, while there are at most 64).
  std::vector<int> colour(n, -1), takenBy;
  std::vector<std::vector<int>> classes;
  for (size_t v = 0; v < n; ++v)
  {
    if (!candidate[v])
      continue;
    const int self = static_cast<int>(v);
    std::uint64_t taken = 0;
    bool many = false;
    for (int t : m.Inc[v])
      for (int w : m.T[t])
        if (static_cast<size_t>(w) < n && colour[w] >= 0)
        {
          if (colour[w] < 64)
            taken |= std::uint64_t(1) << colour[w];
          else
          {
            many = true;
            takenBy[colour[w]] = self;
          }
        }
    size_t c = 0;
    while (c < classes.size() && (c < 64 ? (taken >> c) & 1 : many && takenBy[c] == self))
      ++c;
    if (c == classes.size())
    {
      classes.emplace_back();
      takenBy.push_back(-1);
    }
    colour[v] = static_cast<int>(c);
    classes[c].push_back(self);
  }
  return classes;
}
}
