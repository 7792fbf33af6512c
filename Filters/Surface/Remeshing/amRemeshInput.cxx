#include "amRemeshInput.h"

#include "vtkSMPTools.h"

#include <limits>
#include <set>
#include <utility>

namespace amRemesh
{
void Input::Build(const amSurfaceMesh& mesh, const std::vector<Triangle>& triangles, int nSheets)
{
  const size_t np = mesh.Points.size();
  this->Points.resize(np);
  for (size_t v = 0; v < np; ++v)
    this->Points[v] = Vec3(mesh.Points[v].data());
  this->Ref.resize(static_cast<size_t>(nSheets));
  this->Samples.resize(static_cast<size_t>(nSheets));
  this->SheetLabels.assign(static_cast<size_t>(nSheets), { { 0, 0 } });
  for (const Triangle& t : triangles)
    this->SheetLabels[t.Sheet] = { { t.Labels[0], t.Labels[1] } };
  std::vector<std::vector<std::array<vtkIdType, 3>>> tris(static_cast<size_t>(nSheets));
  for (const Triangle& t : triangles)
    tris[t.Sheet].push_back({ t.V[0], t.V[1], t.V[2] });
  const auto& P = this->Points;
  auto samples = [&]() {
    // Each edge of an interface once: an edge inside one interface is flagged; a junction edge
    // (few) is looked up with its interface.
    std::vector<char> edgeSeen(mesh.Edges.size(), 0);
    std::set<std::pair<vtkIdType, int>> junctionSeen;
    // Each vertex once per interface: the interfaces are sampled one after another, so one stamp
    // per vertex (the last interface that took it) does, where a flag per vertex and interface
    // took interfaces x vertices bytes (2.6 GB for 700 labels).
    std::vector<int> stamp(np, -1);
    for (int sheet = 0; sheet < nSheets; ++sheet)
    {
      std::vector<Vec3>& out = this->Samples[sheet];
      for (const auto& t : tris[sheet])
      {
        out.push_back((P[t[0]] + P[t[1]] + P[t[2]]) / 3.0);
        for (int k = 0; k < 3; ++k)
        {
          const vtkIdType e = mesh.FindEdge(t[k], t[(k + 1) % 3]);
          const bool first = mesh.FeatureEdge[e] ? junctionSeen.insert({ e, sheet }).second : !edgeSeen[e];
          edgeSeen[e] = 1;
          if (first)
            out.push_back(0.5 * (P[t[k]] + P[t[(k + 1) % 3]]));
        }
        for (int k = 0; k < 3; ++k)
          if (stamp[t[k]] != sheet)
          {
            stamp[t[k]] = sheet;
            out.push_back(P[t[k]]);
          }
      }
      out.shrink_to_fit(); // kept for the whole run: no doubling's slack
    }
  };
  vtkSMPTools::For(0, 2, 1, [&](vtkIdType j0, vtkIdType j1) {
    for (vtkIdType j = j0; j < j1; ++j)
      if (j == 0)
        for (int s = 0; s < nSheets; ++s)
          this->Ref[s].Build(mesh.Points, tris[s]);
      else
        samples();
  });
}

bool Input::Near(int sheet, const Vec3& x, const Vec3& normal) const
{
  // The input triangle the last query (on this thread) found: queries come in runs at nearby
  // points, and most end there.
  thread_local std::pair<int, vtkIdType> hint(-1, -1);
  if (hint.first != sheet)
    hint = { sheet, -1 };
  return this->Ref[sheet].WithinDistance(x.data(), this->Eps * this->Eps, normal.data(), &hint.second);
}

bool Input::TriangleNear(int sheet, const Vec3& a, const Vec3& b, const Vec3& c) const
{
  const Vec3 n = (b - a).cross(c - a);
  if (!(this->Near(sheet, (a + b + c) / 3.0, n) && this->Near(sheet, 0.5 * (a + b), n) &&
        this->Near(sheet, 0.5 * (b + c), n) && this->Near(sheet, 0.5 * (c + a), n)))
    return false;
  // The quarter points too: with midpoints alone, edges bent over a crease of the input pass
  // and leave far samples that no insertion can reach.
  for (double f : { 0.25, 0.75 })
    if (!this->Near(sheet, a + f * (b - a), n) || !this->Near(sheet, b + f * (c - b), n) ||
      !this->Near(sheet, c + f * (a - c), n))
      return false;
  return true;
}
}
