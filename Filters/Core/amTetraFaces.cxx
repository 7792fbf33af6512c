#include "amTetraFaces.h"

#include "amThreading.h"

#include <algorithm>

namespace
{
// Faces of tetrahedron (0 1 2 3), each outward when the tetrahedron is positive.
const int FaceOf[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

struct Entry
{
  std::array<vtkIdType, 3> Sorted;
  vtkIdType Tetra;
  int Side;
  // Element by element (std::array's operators compare through memcmp, most of the sort's time).
  bool operator<(const Entry& o) const
  {
    for (int k = 0; k < 3; ++k)
      if (this->Sorted[k] != o.Sorted[k])
        return this->Sorted[k] < o.Sorted[k];
    return this->Tetra < o.Tetra;
  }
  bool SameFace(const Entry& o) const
  {
    return this->Sorted[0] == o.Sorted[0] && this->Sorted[1] == o.Sorted[1] && this->Sorted[2] == o.Sorted[2];
  }
};

bool Positive(const double* points, const std::array<vtkIdType, 4>& t)
{
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c)
      e[k][c] = points[3 * t[k + 1] + c] - points[3 * t[0] + c];
  const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  return det >= 0;
}
}

std::vector<amTetraFaces::Face> amTetraFaces::Find(
  const double* points, const std::vector<std::array<vtkIdType, 4>>& tetrahedra, const int* labels)
{
  std::vector<Entry> entries;
  entries.reserve(4 * tetrahedra.size());
  for (std::size_t t = 0; t < tetrahedra.size(); ++t)
    for (int f = 0; f < 4; ++f)
    {
      const auto& tet = tetrahedra[t];
      Entry e{ { tet[FaceOf[f][0]], tet[FaceOf[f][1]], tet[FaceOf[f][2]] }, static_cast<vtkIdType>(t), f };
      std::sort(e.Sorted.begin(), e.Sorted.end());
      entries.push_back(e);
    }
  // No two entries compare equal (a tetrahedron's faces differ), so the threads' sort gives the
  // one order.
  amThreading::Sort(entries.begin(), entries.end());

  auto labelOf = [&](vtkIdType t) { return labels ? labels[t] : 0; };
  std::vector<Face> faces;
  for (std::size_t k = 0; k < entries.size();)
  {
    std::size_t e = k + 1;
    while (e < entries.size() && entries[e].SameFace(entries[k]))
      ++e;
    const Entry* first = &entries[k];
    const Entry* second = e - k == 2 ? &entries[k + 1] : nullptr; // > 2: non-manifold, taken as boundary
    const int a = labelOf(first->Tetra);
    const int b = second ? labelOf(second->Tetra) : Outside();
    if (!second || a != b)
    {
      if (second && b > a)
        std::swap(first, second);
      const auto& tet = tetrahedra[first->Tetra];
      Face face;
      face.Points = { tet[FaceOf[first->Side][0]], tet[FaceOf[first->Side][1]], tet[FaceOf[first->Side][2]] };
      if (!Positive(points, tet))
        std::swap(face.Points[1], face.Points[2]); // a negative tetrahedron's FaceOf faces point inwards
      face.FirstTetra = first->Tetra;
      face.SecondTetra = second ? second->Tetra : -1;
      face.First = std::max(a, b);
      face.Second = std::min(a, b);
      faces.push_back(face);
    }
    k = e;
  }
  return faces;
}
