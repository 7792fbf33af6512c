#include "amTetraImproveMesh.h"

#include "vtkSMPTools.h"

namespace amTetraImprove
{
long SmoothAll(Mesh& m, size_t n)
{
  // A block's choices are made on the mesh as the blocks before it left it, so a choice is
  // the serial loop's own unless a vertex of its star moved earlier in the same block: the
  // block's moves are stamped, and such a vertex is smoothed again at its turn.
  const size_t block = 4096;
  std::vector<char> found(block), evaluated(block);
  std::vector<double> to(3 * block);
  // Each choice's star objectives, taken with it (not computed again in the serial part).
  std::vector<std::vector<double>> q(block);
  std::vector<size_t> movedIn(n, 0); // the block (counted from 1) of a vertex's last move
  long moves = 0;
  size_t id = 0;
  for (size_t b0 = 0; b0 < n; b0 += block)
  {
    ++id;
    const size_t b1 = std::min(n, b0 + block);
    // A block with nothing to smooth when it starts (the sliver rounds' passes, which touch a few
    // stars) starts no threads: what an earlier move makes dirty in it is smoothed at its turn.
    bool any = false;
    for (size_t v = b0; v < b1 && !any; ++v)
      any = !m.FixedVertex[v] && m.Dirty[v];
    if (!any)
      std::fill(evaluated.begin(), evaluated.end(), 0);
    else
      vtkSMPTools::For(static_cast<vtkIdType>(b0), static_cast<vtkIdType>(b1), 256, [&](vtkIdType v0, vtkIdType v1) {
        for (vtkIdType v = v0; v < v1; ++v)
        {
          const size_t k = static_cast<size_t>(v) - b0;
          evaluated[k] = !m.FixedVertex[v] && m.Dirty[v];
          if (evaluated[k])
          {
            q[k].resize(m.Inc[v].size());
            found[k] = SmoothTarget(m, static_cast<int>(v), &to[3 * k], q[k].data());
          }
        }
      });
    for (size_t v = b0; v < b1; ++v)
    {
      if (m.FixedVertex[v] || !m.Dirty[v])
        continue;
      m.Dirty[v] = 0;
      const size_t k = v - b0;
      bool stale = !evaluated[k];
      for (size_t i = 0; i < m.Inc[v].size() && !stale; ++i)
        for (int w : m.T[m.Inc[v][i]])
          stale = stale || movedIn[w] == id;
      bool moved;
      if (stale)
        moved = Smooth(m, static_cast<int>(v));
      else if ((moved = found[k]))
        MoveVertex(m, static_cast<int>(v), &to[3 * k], q[k].data());
      if (moved)
      {
        movedIn[v] = id;
        ++moves;
      }
    }
  }
  return moves;
}
}
