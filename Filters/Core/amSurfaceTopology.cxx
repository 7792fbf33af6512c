#include "amSurfaceTopology.h"

#include "amUnits.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

namespace
{
struct DirectedEdge
{
  vtkIdType Lo, Hi;
  int Forward;                  // 1 when traversed Lo -> Hi
  vtkIdType CornerLo, CornerHi; // corner nodes (3 * local triangle + k) of Lo and Hi
  bool operator<(const DirectedEdge& o) const
  {
    return this->Lo != o.Lo ? this->Lo < o.Lo : (this->Hi != o.Hi ? this->Hi < o.Hi : this->Forward < o.Forward);
  }
};

vtkIdType Find(std::vector<vtkIdType>& parent, vtkIdType a)
{
  while (parent[a] != a)
  {
    parent[a] = parent[parent[a]];
    a = parent[a];
  }
  return a;
}
/// The surface's triangles, checked: triangles only, one label pair each, finite points; the problem, or "".
std::string ReadTriangles(vtkPolyData* surface, vtkDataArray* labels, std::vector<std::array<vtkIdType, 3>>& tri)
{
  if (surface->GetNumberOfVerts() + surface->GetNumberOfLines() + surface->GetNumberOfStrips() > 0)
    return "The surface has vertex, line or strip cells; only triangles are analysed.";
  vtkCellArray* polys = surface->GetPolys();
  const vtkIdType nTri = polys->GetNumberOfCells();
  if (labels->GetNumberOfTuples() != nTri)
    return "The labels array does not have one tuple per triangle.";
  tri.resize(static_cast<size_t>(nTri));
  {
    vtkIdType t = 0, npts;
    const vtkIdType* pts;
    for (polys->InitTraversal(); polys->GetNextCell(npts, pts); ++t)
    {
      if (npts != 3)
        return "Cell " + std::to_string(t) + " has " + std::to_string(npts) + " points; only triangles are analysed.";
      tri[t] = { pts[0], pts[1], pts[2] };
    }
  }
  vtkPoints* points = surface->GetPoints();
  const vtkIdType nPts = points ? points->GetNumberOfPoints() : 0;
  for (vtkIdType i = 0; i < nPts; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      return "Point " + std::to_string(i) + " has a NaN or infinite coordinate.";
  }
  return "";
}

/// One region's counts, area and enclosed volume from its triangles (index, or -index-1 where the
/// region sees the triangle reversed).
void AnalyseRegion(const std::vector<vtkIdType>& ts, const std::vector<std::array<vtkIdType, 3>>& tri,
  vtkPoints* points, amSurfaceTopology::Region& out)
{
  out.Triangles = static_cast<long long>(ts.size());
  std::vector<DirectedEdge> edges;
  edges.reserve(ts.size() * 3);
  std::vector<vtkIdType> verts;
  verts.reserve(ts.size() * 3);
  double ref[3] = { 0, 0, 0 };
  if (!ts.empty())
  {
    const vtkIdType t0 = ts[0] >= 0 ? ts[0] : -ts[0] - 1;
    points->GetPoint(tri[t0][0], ref);
  }
  vtkIdType local = 0;
  for (vtkIdType code : ts)
  {
    const bool reversed = code < 0;
    const auto& c = tri[reversed ? -code - 1 : code];
    const vtkIdType v[3] = { c[0], reversed ? c[2] : c[1], reversed ? c[1] : c[2] };
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(v[k], p[k]);
      for (int d = 0; d < 3; ++d)
        p[k][d] -= ref[d];
      verts.push_back(v[k]);
      const vtkIdType a = v[k], b = v[(k + 1) % 3];
      const vtkIdType ca = 3 * local + k, cb = 3 * local + (k + 1) % 3;
      edges.push_back({ std::min(a, b), std::max(a, b), a < b ? 1 : 0, a < b ? ca : cb, a < b ? cb : ca });
    }
    const double e1[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double e2[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
    out.Area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    ++local;
    out.Volume +=
      (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
        p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) /
      6.0;
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  out.Vertices = static_cast<long long>(verts.size());
  std::sort(edges.begin(), edges.end());
  // Components: union-find over the region's vertices (local numbering).
  std::vector<vtkIdType> parent(verts.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto localIndex = [&](vtkIdType v) {
    return static_cast<vtkIdType>(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin());
  };
  // Fans: the corners of the triangles around a vertex joined across its manifold edges; a
  // vertex whose corners form more than one group is a non-manifold (pinched) vertex.
  std::vector<vtkIdType> corner(3 * ts.size());
  std::iota(corner.begin(), corner.end(), 0);
  std::vector<vtkIdType> cornerVertex(3 * ts.size());
  for (const auto& e : edges)
  {
    cornerVertex[e.CornerLo] = e.Lo;
    cornerVertex[e.CornerHi] = e.Hi;
  }
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    int forward = 0;
    while (j < edges.size() && edges[j].Lo == edges[i].Lo && edges[j].Hi == edges[i].Hi)
    {
      forward += edges[j].Forward;
      ++j;
    }
    const size_t count = j - i;
    ++out.Edges;
    if (count == 1)
      ++out.BoundaryEdges;
    else if (count > 2)
      ++out.NonManifoldEdges;
    else if (forward != 1)
      ++out.MisorientedEdges;
    if (count == 2)
      for (vtkIdType* c : { &edges[i].CornerLo, &edges[i].CornerHi })
      {
        const vtkIdType x = Find(corner, *c),
                        y = Find(corner, *(c == &edges[i].CornerLo ? &edges[i + 1].CornerLo : &edges[i + 1].CornerHi));
        if (x != y)
          corner[std::max(x, y)] = std::min(x, y);
      }
    const vtkIdType a = Find(parent, localIndex(edges[i].Lo)), b = Find(parent, localIndex(edges[i].Hi));
    if (a != b)
      parent[std::max(a, b)] = std::min(a, b);
    i = j;
  }
  for (size_t v = 0; v < parent.size(); ++v)
    if (Find(parent, static_cast<vtkIdType>(v)) == static_cast<vtkIdType>(v))
      ++out.Components;
  std::vector<std::pair<vtkIdType, vtkIdType>> fans; // (vertex, fan root)
  for (size_t c = 0; c < corner.size(); ++c)
    fans.emplace_back(cornerVertex[c], Find(corner, static_cast<vtkIdType>(c)));
  std::sort(fans.begin(), fans.end());
  fans.erase(std::unique(fans.begin(), fans.end()), fans.end());
  for (size_t f = 1; f < fans.size(); ++f)
    out.NonManifoldVertices += fans[f].first == fans[f - 1].first && (f < 2 || fans[f - 2].first != fans[f].first);
  out.Euler = out.Vertices - out.Edges + out.Triangles;
}
}

bool amSurfaceTopology::Analyse(
  vtkPolyData* surface, std::vector<Region>& regions, std::string& why, int background, const char* labelsName)
{
  regions.clear();
  if (!surface || !surface->GetPolys())
  {
    why = "The surface is empty.";
    return false;
  }
  vtkDataArray* labels = surface->GetCellData()->GetArray(labelsName);
  if (!labels || labels->GetNumberOfComponents() != 2)
  {
    why = std::string("The surface has no 2-component cell array \"") + labelsName + "\".";
    return false;
  }
  std::vector<std::array<vtkIdType, 3>> tri;
  why = ReadTriangles(surface, labels, tri);
  if (!why.empty())
    return false;
  vtkPoints* points = surface->GetPoints();

  // Triangles of each region, with their orientation as seen from the region.
  std::map<int, std::vector<vtkIdType>> byRegion; // triangle index, negative-1 encoded when reversed
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(tri.size()); ++t)
  {
    const int a = static_cast<int>(labels->GetComponent(t, 0));
    const int b = static_cast<int>(labels->GetComponent(t, 1));
    if (a != background)
      byRegion[a].push_back(t);
    if (b != background && b != a)
      byRegion[b].push_back(-t - 1);
  }
  regions.resize(byRegion.size());
  std::vector<std::pair<int, const std::vector<vtkIdType>*>> work;
  for (const auto& kv : byRegion)
    work.emplace_back(kv.first, &kv.second);

  vtkSMPTools::For(0, static_cast<vtkIdType>(work.size()), [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType r = first; r < last; ++r)
    {
      regions[r].Label = work[r].first;
      AnalyseRegion(*work[r].second, tri, points, regions[r]);
    }
  });
  return true;
}

vtkSmartPointer<vtkTable> amSurfaceTopology::ToTable(const std::vector<Region>& regions)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  const char* intNames[] = { "Label", "Triangles", "Vertices", "Edges", "EulerCharacteristic", "Components",
    "BoundaryEdges", "NonManifoldEdges", "MisorientedEdges", "NonManifoldVertices" };
  for (const char* name : intNames)
  {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(static_cast<vtkIdType>(regions.size()));
    table->AddColumn(a);
  }
  for (const char* name : { "Area", "Volume" })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    amUnits::Set(a, name[0] == 'A' ? "mm2" : "mm3");
    a->SetNumberOfTuples(static_cast<vtkIdType>(regions.size()));
    table->AddColumn(a);
  }
  for (size_t r = 0; r < regions.size(); ++r)
  {
    const Region& g = regions[r];
    const long long v[] = { g.Label, g.Triangles, g.Vertices, g.Edges, g.Euler, g.Components, g.BoundaryEdges,
      g.NonManifoldEdges, g.MisorientedEdges, g.NonManifoldVertices };
    for (int c = 0; c < 10; ++c)
      vtkIdTypeArray::SafeDownCast(table->GetColumn(c))->SetValue(static_cast<vtkIdType>(r), v[c]);
    vtkDoubleArray::SafeDownCast(table->GetColumn(10))->SetValue(static_cast<vtkIdType>(r), g.Area);
    vtkDoubleArray::SafeDownCast(table->GetColumn(11))->SetValue(static_cast<vtkIdType>(r), g.Volume);
  }
  return table;
}
