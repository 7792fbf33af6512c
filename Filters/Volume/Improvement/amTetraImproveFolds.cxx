// Faces where the mesh folds over itself: more than two tetrahedra on one face, or two with their
// fourth corners on the same side of it.
#include "amTetraImproveMesh.h"

#include "amTetraGeometry.h"

#include <algorithm>

namespace amTetraImprove
{
long FoldedFaces(const Mesh& m)
{
  struct Entry
  {
    Tri Face;
    int Apex;
  };
  std::vector<Entry> faces;
  faces.reserve(4 * m.T.size());
  for (size_t t = 0; t < m.T.size(); ++t)
    if (m.Alive[t])
      for (int i = 0; i < 4; ++i)
      {
        const Tet& x = m.T[t];
        faces.push_back({ Sorted(x[(i + 1) % 4], x[(i + 2) % 4], x[(i + 3) % 4]), x[i] });
      }
  std::sort(faces.begin(), faces.end(),
    [](const Entry& a, const Entry& b) { return a.Face != b.Face ? a.Face < b.Face : a.Apex < b.Apex; });
  long folded = 0;
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].Face == faces[i].Face)
      ++j;
    if (j - i > 2)
      ++folded;
    else if (j - i == 2)
    {
      const Tri& f = faces[i].Face;
      const double s0 = amTetraGeometry::SignedVolume(m.X(f[0]), m.X(f[1]), m.X(f[2]), m.X(faces[i].Apex));
      const double s1 = amTetraGeometry::SignedVolume(m.X(f[0]), m.X(f[1]), m.X(f[2]), m.X(faces[i + 1].Apex));
      folded += (s0 > 0) == (s1 > 0);
    }
    i = j;
  }
  return folded;
}
}
