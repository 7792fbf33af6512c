#include "amTetraFaces.h"

#include "vtkSMPTools.h"

#include <algorithm>

namespace
{
// Faces of tetrahedron (0 1 2 3), each outward when the tetrahedron is positive.
const int FaceOf[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

/// A face of a tetrahedron, its nodes sorted: the lowest is its bucket's (not kept here).
template<typename Id>
struct Entry
{
  Id Middle, High;
  Id Tetra;
  int Side;
  bool operator<(const Entry& o) const
  {
    return this->Middle != o.Middle ? this->Middle < o.Middle
                                    : (this->High != o.High ? this->High < o.High : this->Tetra < o.Tetra);
  }
  bool SameFace(const Entry& o) const { return this->Middle == o.Middle && this->High == o.High; }
};

template<typename Id>
std::array<Id, 3> SortedFace(const std::array<Id, 4>& tet, int f)
{
  std::array<Id, 3> v = { tet[FaceOf[f][0]], tet[FaceOf[f][1]], tet[FaceOf[f][2]] };
  if (v[0] > v[1])
    std::swap(v[0], v[1]);
  if (v[1] > v[2])
    std::swap(v[1], v[2]);
  if (v[0] > v[1])
    std::swap(v[0], v[1]);
  return v;
}

/// Calls visit(low, first, end) for every distinct face of the tetrahedra, its lowest node 'low'
/// and its entries [first, end) (one per tetrahedron it belongs to, in their order), the faces in
/// the order of their sorted node triples. They are bucketed by their lowest node (a counting
/// sort) and each bucket, a few dozen faces, is sorted on the threads: no two entries compare
/// equal, so the order is the one a sort of the whole would give, whatever the threads.
template<typename Id, typename Visit>
void ForEachFace(const std::vector<std::array<Id, 4>>& tetrahedra, Visit&& visit)
{
  Id nodes = 0;
  for (const auto& tet : tetrahedra)
    for (Id v : tet)
      nodes = std::max(nodes, static_cast<Id>(v + 1));
  std::vector<vtkIdType> start(static_cast<std::size_t>(nodes) + 1, 0);
  for (const auto& tet : tetrahedra)
    for (int f = 0; f < 4; ++f)
      ++start[SortedFace(tet, f)[0] + 1];
  for (Id v = 0; v < nodes; ++v)
    start[v + 1] += start[v];
  std::vector<Entry<Id>> entries(4 * tetrahedra.size());
  {
    std::vector<vtkIdType> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < tetrahedra.size(); ++t)
      for (int f = 0; f < 4; ++f)
      {
        const std::array<Id, 3> v = SortedFace(tetrahedra[t], f);
        entries[fill[v[0]]++] = { v[1], v[2], static_cast<Id>(t), f };
      }
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(nodes), 4096, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
      std::sort(entries.begin() + start[v], entries.begin() + start[v + 1]);
  });
  for (Id v = 0; v < nodes; ++v)
    for (vtkIdType k = start[v]; k < start[v + 1];)
    {
      vtkIdType e = k + 1;
      while (e < start[v + 1] && entries[e].SameFace(entries[k]))
        ++e;
      visit(v, entries.data() + k, entries.data() + e);
      k = e;
    }
}

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
  auto labelOf = [&](vtkIdType t) { return labels ? labels[t] : 0; };
  std::vector<Face> faces;
  ForEachFace(tetrahedra, [&](vtkIdType, const Entry<vtkIdType>* begin, const Entry<vtkIdType>* end) {
    const Entry<vtkIdType>* first = begin;
    const Entry<vtkIdType>* second = end - begin == 2 ? begin + 1 : nullptr; // > 2: non-manifold, taken as boundary
    const int a = labelOf(first->Tetra);
    const int b = second ? labelOf(second->Tetra) : Outside();
    if (second && a == b)
      return;
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
  });
  return faces;
}

std::vector<std::array<int, 3>> amTetraFaces::Boundary(const std::vector<std::array<int, 4>>& tetrahedra)
{
  std::vector<std::array<int, 3>> faces;
  ForEachFace(tetrahedra, [&](int low, const Entry<int>* begin, const Entry<int>* end) {
    if (end - begin == 1)
      faces.push_back({ low, begin->Middle, begin->High });
  });
  return faces;
}
