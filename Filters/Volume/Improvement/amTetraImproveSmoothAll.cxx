#include "amTetraImproveMesh.h"

#include "vtkSMPTools.h"

namespace amTetraImprove
{
long SmoothAll(Mesh& m, size_t n)
{
  // No two vertices of a colour share an element: each one's choice reads the positions of its
  // neighbours, of other colours, and writes its own position and its star's objectives only.
  // So a colour's vertices are smoothed on the threads at once, and the mesh is the serial
  // loop's over the colours in turn whatever the threads. The flags its moves set are set
  // after it, before the next colour reads them.
  const std::vector<std::vector<int>> colours = SmoothingColours(m, n);
  std::vector<char> moved;
  long moves = 0;
  for (const std::vector<int>& vertices : colours)
  {
    moved.assign(vertices.size(), 0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(vertices.size()), 256, [&](vtkIdType i0, vtkIdType i1) {
      thread_local std::vector<double> q;
      for (vtkIdType i = i0; i < i1; ++i)
      {
        const int v = vertices[i];
        if (!m.Dirty[v])
          continue;
        m.Dirty[v] = 0;
        double to[3];
        q.resize(m.Inc[v].size());
        if (!SmoothTarget(m, v, to, q.data()))
          continue;
        PlaceVertex(m, v, to, q.data());
        moved[i] = 1;
      }
    });
    for (size_t i = 0; i < vertices.size(); ++i)
      if (moved[i])
      {
        ++moves;
        MarkStarDirty(m, vertices[i]);
      }
  }
  return moves;
}
}
