#include "amTetraInterfaceUpdate.h"

#include "amTetraFaces.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <map>
#include <unordered_set>

namespace
{
std::array<int, 3> SortedKey(int a, int b, int c)
{
  std::array<int, 3> k{ { a, b, c } };
  std::sort(k.begin(), k.end());
  return k;
}
/// Whether (a, b, c) is (p, q, r) up to a rotation: the same orientation.
bool SameTurn(const std::array<int, 3>& t, const std::array<vtkIdType, 3>& f)
{
  for (int r = 0; r < 3; ++r)
    if (t[0] == f[r] && t[1] == f[(r + 1) % 3] && t[2] == f[(r + 2) % 3])
      return true;
  return false;
}
}

int amTetraInterfaceUpdate::Background(vtkPolyData* surface, const std::vector<int>& regions)
{
  const std::unordered_set<int> present(regions.begin(), regions.end());
  vtkDataArray* labels = surface->GetCellData()->GetArray("Labels");
  for (vtkIdType s = 0; labels && s < labels->GetNumberOfTuples(); ++s)
    for (int c = 0; c < 2; ++c)
    {
      const int l = static_cast<int>(labels->GetComponent(s, c));
      if (!present.count(l))
        return l;
    }
  return 0;
}

std::vector<std::array<int, 3>> amTetraInterfaceUpdate::Rebuild(vtkPolyData* surface, const std::vector<double>& points,
  const std::vector<std::array<int, 4>>& tets, const std::vector<int>& regions, int background)
{
  std::vector<std::array<vtkIdType, 4>> cells(tets.size());
  for (size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k)
      cells[t][k] = tets[t][k];
  const std::vector<amTetraFaces::Face> faces = amTetraFaces::Find(points.data(), cells, regions.data());
  std::map<std::array<int, 3>, size_t> faceOf;
  for (size_t f = 0; f < faces.size(); ++f)
    faceOf[SortedKey(static_cast<int>(faces[f].Points[0]), static_cast<int>(faces[f].Points[1]),
      static_cast<int>(faces[f].Points[2]))] = f;
  auto label = [background](int l) { return l == amTetraFaces::Outside() ? background : l; };

  vtkCellData* oldData = surface->GetCellData();
  vtkNew<vtkCellData> newData;
  newData->CopyAllocate(oldData, static_cast<vtkIdType>(faces.size()));
  vtkNew<vtkCellArray> polys;
  std::vector<std::array<int, 3>> result;
  std::vector<char> used(faces.size(), 0);
  std::vector<std::array<int, 2>> newLabels;
  for (vtkIdType s = 0; s < surface->GetNumberOfCells(); ++s)
  {
    vtkIdType n;
    const vtkIdType* ids;
    surface->GetCellPoints(s, n, ids);
    const std::array<int, 3> t{ { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) } };
    const auto it = faceOf.find(SortedKey(t[0], t[1], t[2]));
    if (n != 3 || it == faceOf.end())
      continue;
    const amTetraFaces::Face& f = faces[it->second];
    used[it->second] = 1;
    const bool same = SameTurn(t, f.Points);
    newData->CopyData(oldData, s, static_cast<vtkIdType>(result.size()));
    newLabels.push_back({ { label(same ? f.First : f.Second), label(same ? f.Second : f.First) } });
    result.push_back(t);
  }
  for (size_t f = 0; f < faces.size(); ++f)
  {
    if (used[f])
      continue;
    const vtkIdType id = static_cast<vtkIdType>(result.size());
    for (int a = 0; a < newData->GetNumberOfArrays(); ++a)
      if (vtkDataArray* array = newData->GetArray(a))
        for (int c = 0; c < array->GetNumberOfComponents(); ++c)
          array->InsertComponent(id, c, -1.0);
    newLabels.push_back({ { label(faces[f].First), label(faces[f].Second) } });
    result.push_back({ { static_cast<int>(faces[f].Points[0]), static_cast<int>(faces[f].Points[1]),
      static_cast<int>(faces[f].Points[2]) } });
  }
  for (const auto& t : result)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  if (vtkDataArray* labels = newData->GetArray("Labels"))
    for (size_t s = 0; s < result.size(); ++s)
      for (int c = 0; c < 2; ++c)
        labels->SetComponent(static_cast<vtkIdType>(s), c, newLabels[s][c]);
  surface->SetPolys(polys);
  surface->GetCellData()->ShallowCopy(newData);
  return result;
}
