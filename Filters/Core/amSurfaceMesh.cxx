#include "amSurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

bool amSurfaceMesh::Build(vtkPolyData* surface, std::string& why, const char* labelsName)
{
  this->Points.clear();
  this->Triangles.clear();
  this->Labels.clear();
  if (!surface || !surface->GetPoints() || surface->GetNumberOfPolys() == 0)
  {
    why = "The surface has no triangles.";
    return false;
  }
  if (surface->GetNumberOfVerts() + surface->GetNumberOfLines() + surface->GetNumberOfStrips() > 0)
  {
    why = "The surface has vertex, line or strip cells; triangulate it first (vtkTriangleFilter).";
    return false;
  }
  const vtkIdType np = surface->GetNumberOfPoints();
  this->Points.resize(static_cast<size_t>(np));
  vtkPoints* pts = surface->GetPoints();
  for (vtkIdType i = 0; i < np; ++i)
  {
    pts->GetPoint(i, this->Points[i].data());
    for (double x : this->Points[i])
      if (!std::isfinite(x))
      {
        why = "Point " + std::to_string(i) + " has a NaN or infinite coordinate.";
        return false;
      }
  }
  vtkCellArray* polys = surface->GetPolys();
  this->Triangles.reserve(static_cast<size_t>(polys->GetNumberOfCells()));
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType cell = 0;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++cell)
  {
    if (npts != 3)
    {
      why = "Cell " + std::to_string(cell) + " has " + std::to_string(npts) +
        " points; triangulate the surface first (vtkTriangleFilter).";
      return false;
    }
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2])
    {
      why = "Triangle " + std::to_string(cell) + " repeats a vertex (degenerate).";
      return false;
    }
    this->Triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  if (vtkDataArray* labels = surface->GetCellData()->GetArray(labelsName))
  {
    if (labels->GetNumberOfComponents() == 2)
    {
      this->Labels.resize(this->Triangles.size());
      for (size_t t = 0; t < this->Triangles.size(); ++t)
        this->Labels[t] = { static_cast<int>(labels->GetComponent(static_cast<vtkIdType>(t), 0)),
          static_cast<int>(labels->GetComponent(static_cast<vtkIdType>(t), 1)) };
    }
  }
  this->BuildTopology();
  return true;
}

namespace
{
/// A half-edge in the bucket of its smaller vertex: the larger one and its triangle.
template<typename Index>
struct HalfEdge
{
  Index B, T;
};

/// The edges of the triangles (unique vertex pairs a < b, in the order of (a, b)) and each one's
/// triangles (in triangle order), from the half-edges: counted into buckets by a in triangle
/// order, each bucket (a vertex's few edges) sorted by b with a stable insertion sort, then the
/// edges of each vertex written at its place from a count per vertex, on the threads (a
/// comparison sort of all the half-edges is far slower). Index is 32-bit where the ids fit: the
/// half-edges are most of the memory this touches.
template<typename Index>
void FindEdges(const std::vector<std::array<vtkIdType, 3>>& triangles, vtkIdType np,
  std::vector<std::array<vtkIdType, 2>>& edges, std::vector<vtkIdType>& edgeTriangleStart,
  std::vector<vtkIdType>& edgeTriangles)
{
  const vtkIdType nt = static_cast<vtkIdType>(triangles.size());
  std::vector<vtkIdType> bucket(static_cast<size_t>(np + 1), 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      ++bucket[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (vtkIdType i = 0; i < np; ++i)
    bucket[i + 1] += bucket[i];
  std::vector<HalfEdge<Index>> half(static_cast<size_t>(3 * nt));
  {
    std::vector<vtkIdType> fill(bucket.begin(), bucket.end() - 1);
    for (vtkIdType t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType a = triangles[t][k], b = triangles[t][(k + 1) % 3];
        half[fill[std::min(a, b)]++] = { static_cast<Index>(std::max(a, b)), static_cast<Index>(t) };
      }
  }
  // Per vertex: its half-edges sorted, and how many edges they make.
  std::vector<vtkIdType> first(static_cast<size_t>(np + 1), 0);
  vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
    {
      for (vtkIdType i = bucket[v] + 1; i < bucket[v + 1]; ++i) // insertion sort: stable
        for (vtkIdType j = i; j > bucket[v] && half[j - 1].B > half[j].B; --j)
          std::swap(half[j - 1], half[j]);
      vtkIdType n = 0;
      for (vtkIdType i = bucket[v]; i < bucket[v + 1]; ++i)
        n += i == bucket[v] || half[i].B != half[i - 1].B;
      first[v + 1] = n;
    }
  });
  for (vtkIdType i = 0; i < np; ++i)
    first[i + 1] += first[i];
  const vtkIdType ne = first[np];
  edges.resize(static_cast<size_t>(ne));
  edgeTriangleStart.resize(static_cast<size_t>(ne + 1));
  edgeTriangles.resize(half.size());
  edgeTriangleStart[ne] = static_cast<vtkIdType>(half.size());
  vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
    {
      vtkIdType e = first[v];
      for (vtkIdType i = bucket[v]; i < bucket[v + 1]; ++i)
      {
        if (i == bucket[v] || half[i].B != half[i - 1].B)
        {
          edges[e] = { v, static_cast<vtkIdType>(half[i].B) };
          edgeTriangleStart[e++] = i;
        }
        edgeTriangles[i] = half[i].T;
      }
    }
  });
}
}

void amSurfaceMesh::BuildTopology()
{
  const vtkIdType nt = this->NumberOfTriangles(), np = this->NumberOfPoints();
  if (np < std::numeric_limits<int>::max() && nt < std::numeric_limits<int>::max())
    FindEdges<int>(this->Triangles, np, this->Edges, this->EdgeTriangleStart, this->EdgeTriangles);
  else
    FindEdges<vtkIdType>(this->Triangles, np, this->Edges, this->EdgeTriangleStart, this->EdgeTriangles);
  const vtkIdType ne = static_cast<vtkIdType>(this->Edges.size());
  this->FeatureEdge.assign(static_cast<size_t>(ne), 0);
  const bool labelled = this->Labels.size() == this->Triangles.size();
  vtkSMPTools::For(0, ne, [&](vtkIdType e0, vtkIdType e1) {
    for (vtkIdType e = e0; e < e1; ++e)
    {
      const vtkIdType n = this->EdgeTriangleStart[e + 1] - this->EdgeTriangleStart[e];
      bool feature = n != 2;
      if (!feature && labelled)
      {
        auto a = this->Labels[this->EdgeTriangles[this->EdgeTriangleStart[e]]];
        auto b = this->Labels[this->EdgeTriangles[this->EdgeTriangleStart[e] + 1]];
        feature = std::min(a[0], a[1]) != std::min(b[0], b[1]) || std::max(a[0], a[1]) != std::max(b[0], b[1]);
      }
      this->FeatureEdge[e] = feature;
    }
  });
  // 1-rings through edges.
  this->RingStart.assign(static_cast<size_t>(np + 1), 0);
  for (const auto& e : this->Edges)
  {
    ++this->RingStart[e[0] + 1];
    ++this->RingStart[e[1] + 1];
  }
  for (vtkIdType i = 0; i < np; ++i)
    this->RingStart[i + 1] += this->RingStart[i];
  this->Ring.resize(static_cast<size_t>(this->RingStart.back()));
  this->RingEdge.resize(this->Ring.size());
  {
    std::vector<vtkIdType> fill(this->RingStart.begin(), this->RingStart.end() - 1);
    for (vtkIdType e = 0; e < ne; ++e)
    {
      const vtkIdType a = this->Edges[e][0], b = this->Edges[e][1];
      this->RingEdge[fill[a]] = e;
      this->Ring[fill[a]++] = b;
      this->RingEdge[fill[b]] = e;
      this->Ring[fill[b]++] = a;
    }
  }
  this->VertexTriangleStart.assign(static_cast<size_t>(np + 1), 0);
  for (const auto& t : this->Triangles)
    for (vtkIdType v : t)
      ++this->VertexTriangleStart[v + 1];
  for (vtkIdType i = 0; i < np; ++i)
    this->VertexTriangleStart[i + 1] += this->VertexTriangleStart[i];
  this->VertexTriangles.resize(static_cast<size_t>(this->VertexTriangleStart.back()));
  {
    std::vector<vtkIdType> fill(this->VertexTriangleStart.begin(), this->VertexTriangleStart.end() - 1);
    for (vtkIdType t = 0; t < nt; ++t)
      for (vtkIdType v : this->Triangles[t])
        this->VertexTriangles[fill[v]++] = t;
  }
  this->Kind.assign(static_cast<size_t>(np), Surface);
  vtkSMPTools::For(0, np, [&](vtkIdType v0, vtkIdType v1) {
    for (vtkIdType v = v0; v < v1; ++v)
    {
      int features = 0;
      for (vtkIdType r = this->RingStart[v]; r < this->RingStart[v + 1]; ++r)
        features += this->FeatureEdge[this->RingEdge[r]];
      this->Kind[v] = features == 0 ? Surface : (features == 2 ? Curve : Corner);
    }
  });
}

vtkIdType amSurfaceMesh::FindEdge(vtkIdType a, vtkIdType b) const
{
  for (vtkIdType r = this->RingStart[a]; r < this->RingStart[a + 1]; ++r)
    if (this->Ring[r] == b)
      return this->RingEdge[r];
  return -1;
}

std::array<double, 3> amSurfaceMesh::TriangleNormal(vtkIdType t) const
{
  const auto& p0 = this->Points[this->Triangles[t][0]];
  const auto& p1 = this->Points[this->Triangles[t][1]];
  const auto& p2 = this->Points[this->Triangles[t][2]];
  const double u[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double w[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  return { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
}
