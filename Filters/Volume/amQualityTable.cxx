#include "amQualityTable.h"

#include "vtkSMPTools.h"

#include <algorithm>

void amQualityTable::Count(const std::vector<std::array<vtkIdType, 4>>& tets, const std::vector<int>& region,
  vtkIdType npoints, const double* q, const double* dmin, const double* dmax, const double* vol,
  std::map<int, Row>& rows, Row& all)
{
  const vtkIdType ne = static_cast<vtkIdType>(tets.size());
  // Faces: sorted (a, b, c, region) so that a face shared within a region appears twice in a row.
  struct Face
  {
    vtkIdType V[3];
    int Region;
    bool operator<(const Face& o) const
    {
      if (this->V[0] != o.V[0])
        return this->V[0] < o.V[0];
      if (this->V[1] != o.V[1])
        return this->V[1] < o.V[1];
      if (this->V[2] != o.V[2])
        return this->V[2] < o.V[2];
      return this->Region < o.Region;
    }
    bool SameFace(const Face& o) const { return this->V[0] == o.V[0] && this->V[1] == o.V[1] && this->V[2] == o.V[2]; }
  };
  // In that order without a sort of all of them: grouped by their smallest vertex (a counting
  // sort), then each group, a few dozen faces, sorted on the threads.
  std::vector<vtkIdType> start(static_cast<size_t>(npoints) + 1, 0);
  auto faceOf = [&](vtkIdType c, int i) {
    Face f;
    int k = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i)
        f.V[k++] = tets[c][j];
    std::sort(f.V, f.V + 3);
    f.Region = region[c];
    return f;
  };
  for (vtkIdType c = 0; c < ne; ++c)
    for (int i = 0; i < 4; ++i)
      ++start[std::min({ tets[c][(i + 1) % 4], tets[c][(i + 2) % 4], tets[c][(i + 3) % 4] }) + 1];
  for (vtkIdType v = 0; v < npoints; ++v)
    start[v + 1] += start[v];
  std::vector<Face> faces(static_cast<size_t>(4 * ne));
  {
    std::vector<vtkIdType> next(start.begin(), start.end() - 1);
    for (vtkIdType c = 0; c < ne; ++c)
      for (int i = 0; i < 4; ++i)
      {
        const Face f = faceOf(c, i);
        faces[next[f.V[0]]++] = f;
      }
  }
  vtkSMPTools::For(0, npoints, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
      std::sort(faces.begin() + start[v], faces.begin() + start[v + 1]);
  });

  rows.clear();
  all = Row();
  for (vtkIdType c = 0; c < ne; ++c)
    for (Row* r : { &rows[region[c]], &all })
    {
      ++r->ne;
      r->sumQ += q[c];
      r->minQ = std::min(r->minQ, q[c]);
      r->maxQ = std::max(r->maxQ, q[c]);
      r->minD = std::min(r->minD, dmin[c]);
      r->maxD = std::max(r->maxD, dmax[c]);
      r->volume += vol[c];
      r->inverted += vol[c] <= 0 ? 1 : 0;
    }
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i;
    while (j < faces.size() && faces[j].SameFace(faces[i]))
      ++j;
    // Faces i..j-1 are one geometric face; per region, a count of one means a boundary face.
    for (size_t k = i; k < j;)
    {
      size_t l = k;
      while (l < j && faces[l].Region == faces[k].Region)
        ++l;
      if (l - k == 1)
        ++rows[faces[k].Region].nt;
      k = l;
    }
    if (j - i == 1 || faces[i].Region != faces[j - 1].Region)
      ++all.nt;
    i = j;
  }
  {
    // Each vertex's regions, grouped by vertex (a counting sort): a vertex counts once in each
    // region it has a tetrahedron of.
    std::vector<vtkIdType> first(static_cast<size_t>(npoints) + 1, 0);
    for (vtkIdType c = 0; c < ne; ++c)
      for (vtkIdType v : tets[c])
        ++first[v + 1];
    for (vtkIdType v = 0; v < npoints; ++v)
      first[v + 1] += first[v];
    std::vector<int> regionsOf(static_cast<size_t>(4 * ne));
    std::vector<vtkIdType> next(first.begin(), first.end() - 1);
    for (vtkIdType c = 0; c < ne; ++c)
      for (vtkIdType v : tets[c])
        regionsOf[next[v]++] = region[c];
    std::vector<int> distinct;
    for (vtkIdType v = 0; v < npoints; ++v)
    {
      if (first[v] == first[v + 1])
        continue;
      distinct.assign(regionsOf.begin() + first[v], regionsOf.begin() + first[v + 1]);
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      for (int r : distinct)
        ++rows[r].np;
      ++all.np;
    }
  }
}
