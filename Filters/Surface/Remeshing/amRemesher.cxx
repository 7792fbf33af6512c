#include "amRemesher.h"

#include "vtkSMPTools.h"

#include <map>
#include <utility>

namespace amRemesh
{
Remesher::Remesher()
  : Grid(Mesh)
  , Crossing(Mesh, Grid)
  , Approximation(Mesh, In, Curves)
{
}

void Remesher::Setup(const amSurfaceMesh& mesh, std::vector<Mat3> metric, double eps)
{
  Surface& S = this->Mesh;
  this->In.Eps = eps;
  this->InputVolumes = amRemesh::RegionVolumes(mesh);
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  S.P.resize(static_cast<size_t>(np));
  for (vtkIdType v = 0; v < np; ++v)
    S.P[v] = Vec3(mesh.Points[v].data());
  S.M = std::move(metric);
  S.Kind = mesh.Kind;
  S.VAlive.assign(static_cast<size_t>(np), 1);
  S.Held.assign(static_cast<size_t>(np), 0);
  // One sheet per interface: per pair of labels (unordered), numbered in the order they first
  // appear.
  std::map<std::pair<int, int>, int> sheetIds;
  const bool labelled = !mesh.Labels.empty();
  S.T.resize(static_cast<size_t>(nt));
  std::pair<int, int> last(1, 0); // no pair: the lookup's first key
  int lastSheet = -1;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    Triangle& tri = S.T[t];
    for (int k = 0; k < 3; ++k)
      tri.V[k] = static_cast<int>(mesh.Triangles[t][k]);
    tri.Labels[0] = labelled ? mesh.Labels[t][0] : 0;
    tri.Labels[1] = labelled ? mesh.Labels[t][1] : 0;
    const std::pair<int, int> key(std::min(tri.Labels[0], tri.Labels[1]), std::max(tri.Labels[0], tri.Labels[1]));
    if (key != last)
    {
      last = key;
      lastSheet = sheetIds.emplace(key, static_cast<int>(sheetIds.size())).first->second;
    }
    tri.Sheet = lastSheet;
    tri.Alive = true;
  }
  // Each vertex's star (its triangles in their order, as the input's topology lists them) and
  // its cluster: itself, on its interface when it is a surface vertex.
  S.VT.resize(static_cast<size_t>(np));
  S.Cluster.resize(static_cast<size_t>(np));
  vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
    {
      const vtkIdType r0 = mesh.VertexTriangleStart[v], r1 = mesh.VertexTriangleStart[v + 1];
      S.VT[v].assign(mesh.VertexTriangles.begin() + r0, mesh.VertexTriangles.begin() + r1);
      const int sheet = S.Kind[v] == amSurfaceMesh::Surface && r1 > r0 ? S.T[S.VT[v][0]].Sheet : -1;
      S.Cluster[v].assign(1, { static_cast<int>(v), sheet, -1 });
    }
  });
  this->In.Build(mesh, S.T, static_cast<int>(sheetIds.size()));
  this->Curves.Build(mesh, S);
}

Remesher::Snapshot Remesher::Save() const
{
  Snapshot s{ this->Mesh, {} };
  for (int w = 0; w < 2; ++w)
    s.Counters[w] = { this->Workers[w].Collapses, this->Workers[w].Moves, this->Workers[w].Flips };
  return s;
}

void Remesher::Restore(Snapshot&& snapshot)
{
  this->Mesh = std::move(snapshot.Mesh);
  // The bins list the triangles of the state given up: slots the restored surface does not have,
  // or has with other vertices. Operations follow a Restore (the degenerate-triangle cleanup after
  // a small-angle one undone), and the crossing guard reads the bins.
  this->Grid.Rebuild();
  for (int w = 0; w < 2; ++w)
  {
    this->Workers[w].Collapses = snapshot.Counters[w][0];
    this->Workers[w].Moves = snapshot.Counters[w][1];
    this->Workers[w].Flips = snapshot.Counters[w][2];
  }
}

void Remesher::Detach(int t)
{
  this->Grid.Remove(t);
  this->Mesh.T[t].Alive = false;
  for (int k = 0; k < 3; ++k)
  {
    auto& l = this->Mesh.VT[this->Mesh.T[t].V[k]];
    l.erase(std::remove(l.begin(), l.end(), t), l.end());
  }
}

int Remesher::AddTriangle(int a, int b, int c, const Triangle& like)
{
  Triangle t = like;
  t.V[0] = a;
  t.V[1] = b;
  t.V[2] = c;
  t.Alive = true;
  this->Mesh.T.push_back(t);
  const int id = static_cast<int>(this->Mesh.T.size()) - 1;
  this->Mesh.VT[a].push_back(id);
  this->Mesh.VT[b].push_back(id);
  this->Mesh.VT[c].push_back(id);
  this->Grid.Add(id);
  return id;
}

/// Whether the stars of a and b lie in zone z's bins.
bool Remesher::StarsInZone(int a, int b, int z) const
{
  if (!this->Mesh.VAlive[a] || !this->Mesh.VAlive[b])
    return false;
  Vec3 lo = this->Mesh.P[a], hi = this->Mesh.P[a];
  for (int v : { a, b })
    for (int t : this->Mesh.VT[v])
      for (int k = 0; k < 3; ++k)
      {
        lo = lo.cwiseMin(this->Mesh.P[this->Mesh.T[t].V[k]]);
        hi = hi.cwiseMax(this->Mesh.P[this->Mesh.T[t].V[k]]);
      }
  return this->Grid.BoxInZone(lo, hi, z);
}
}
