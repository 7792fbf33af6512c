#include "amTetraRegions.h"

#include "amMessage.h"
#include "amSurfaceMesh.h"
#include "amTetraGeometry.h"
#include "amTetraSurfaceCheck.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <unordered_map>

namespace
{
using Vec = amTetraGeometry::Vec;
constexpr auto Cross = &amTetraGeometry::Cross;
constexpr auto Dot = &amTetraGeometry::Dot;
constexpr auto Sub = &amTetraGeometry::Sub;

struct FaceKey
{
  std::array<vtkIdType, 3> V;
  bool operator==(const FaceKey& o) const { return this->V == o.V; }
};
struct FaceHash
{
  size_t operator()(const FaceKey& k) const
  {
    uint64_t h = 1469598103934665603ull;
    for (vtkIdType v : k.V)
    {
      h ^= static_cast<uint64_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    }
    return static_cast<size_t>(h);
  }
};
FaceKey MakeKey(vtkIdType a, vtkIdType b, vtkIdType c)
{
  FaceKey k{ { a, b, c } };
  std::sort(k.V.begin(), k.V.end());
  return k;
}

}

bool amTetraRegions::Assign(const amSurfaceMesh& mesh, const amTetGenRun::Result& out, int background, std::string& why)
{
  const int bg = background;
  const vtkIdType nt = mesh.NumberOfTriangles(), nTets = out.NumberOfTetrahedra, nSub = out.NumberOfFaces;
  std::unordered_map<FaceKey, vtkIdType, FaceHash> subfaceOf;
  subfaceOf.reserve(static_cast<size_t>(nSub) * 2);
  // A face with a vertex off the surface is no subface: most are told so without a lookup.
  std::vector<char> onSurface(static_cast<size_t>(out.NumberOfPoints), 0);
  for (vtkIdType s = 0; s < nSub; ++s)
  {
    subfaceOf[MakeKey(out.Faces[3 * s], out.Faces[3 * s + 1], out.Faces[3 * s + 2])] = s;
    for (int k = 0; k < 3; ++k)
      onSurface[out.Faces[3 * s + k]] = 1;
  }
  auto sourceOf = [&out](vtkIdType s) { return SourceOf(out, s); };
  for (vtkIdType s = 0; s < nSub; ++s)
    if (sourceOf(s) < 0 || sourceOf(s) >= nt)
    {
      why = amMessage() << "TetGen returned a boundary triangle with no source triangle (marker " << out.FaceMarkers[s]
                        << ").";
      return false;
    }
  const int* tets = out.Tetrahedra.data();
  const double* P = out.Points.data();
  std::vector<int> component(static_cast<size_t>(nTets), -1);
  std::vector<int> componentLabel;
  std::vector<std::array<vtkIdType, 2>>& subfaceTet = this->SubfaceTet;
  subfaceTet.assign(static_cast<size_t>(nSub), { -1, -1 });
  std::vector<vtkIdType> stack;
  std::vector<vtkIdType> conflicting;
  for (vtkIdType seed = 0; seed < nTets; ++seed)
  {
    if (component[seed] >= 0)
      continue;
    const int c = static_cast<int>(componentLabel.size());
    componentLabel.push_back(INT32_MIN);
    component[seed] = c;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const vtkIdType t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i)
      {
        const int a = tets[4 * t + (i + 1) % 4], b = tets[4 * t + (i + 2) % 4], d = tets[4 * t + (i + 3) % 4];
        const auto it =
          onSurface[a] && onSurface[b] && onSurface[d] ? subfaceOf.find(MakeKey(a, b, d)) : subfaceOf.end();
        const int n = out.Neighbors[4 * t + i];
        if (it == subfaceOf.end())
        {
          if (n >= 0 && component[n] < 0)
          {
            component[n] = c;
            stack.push_back(n);
          }
          continue;
        }
        // A surface triangle: which side of its source is this tetrahedron on?
        const vtkIdType s = it->second, src = sourceOf(s);
        const auto& tri = mesh.Triangles[src];
        const double* q = P + 3 * tets[4 * t + i];
        const Vec nrm = Cross(Sub(mesh.Points[tri[1]].data(), mesh.Points[tri[0]].data()),
          Sub(mesh.Points[tri[2]].data(), mesh.Points[tri[0]].data()));
        const int side = Dot(nrm, Sub(q, mesh.Points[tri[0]].data())) > 0 ? 1 : 0;
        const int label = mesh.Labels[src][side];
        subfaceTet[s][side] = t;
        if (componentLabel[c] == INT32_MIN)
          componentLabel[c] = label;
        else if (componentLabel[c] != label)
          conflicting.push_back(src);
      }
    }
    if (componentLabel[c] == INT32_MIN)
      componentLabel[c] = bg; // bounded by no surface triangle: cannot happen for a valid PLC
  }
  if (!conflicting.empty())
  {
    std::sort(conflicting.begin(), conflicting.end());
    conflicting.erase(std::unique(conflicting.begin(), conflicting.end()), conflicting.end());
    why = amMessage() << "The surface's labels are inconsistent: a connected part of the volume is bounded "
                         "by triangles that give it different labels (triangles "
                      << amTetraSurfaceCheck::List(conflicting) << ").";
    return false;
  }
  this->Label.resize(static_cast<size_t>(nTets));
  for (vtkIdType t = 0; t < nTets; ++t)
    this->Label[t] = componentLabel[component[t]];
  return true;
}
