#include "amLabelSurfaceExtractor.h"

#include "vtkSMPTools.h"

#include <array>
#include <limits>
#include <map>
#include <tuple>

using namespace amLabelCorners;

namespace
{
// A face's corners in loop order (normal +axis).
const int Loop[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
}

void amLabelSurfaceExtractor::Extract(const std::function<void(double)>& progress)
{
  auto report = [&progress](double fraction) {
    if (progress)
      progress(fraction);
  };
  this->ResolvedEdges = this->SplitCorners = this->RelabeledVoxels = 0;
  this->FindCorners();
  report(0.3);
  this->PlaceCorners();
  report(0.45);
  this->Faces();
  report(0.7);
  this->ResolvedEdgeFaces();
  this->Assemble();
}

void amLabelSurfaceExtractor::FindCorners()
{
  amLabelGrid& g = this->Grid;
  // Pass 1: the corners on the surface and how many copies of each one's vertex, row by row.
  // The same scan finds the corners where a label touches itself through fans that no vertex
  // split can separate; if there are any, one voxel each is relabelled and the scan is redone
  // for the slabs of corners around the relabelled voxels only.
  const int cn[3] = { g.N[0] + 1, g.N[1] + 1, g.N[2] + 1 };
  std::vector<std::vector<amLabelGrid::Entry>> slabEntries(static_cast<size_t>(cn[2]));
  std::vector<std::vector<std::pair<size_t, std::uint16_t>>> changes(static_cast<size_t>(cn[2]));
  std::vector<char> dirty(static_cast<size_t>(cn[2]), 1);
  g.RowStart.assign(static_cast<size_t>(cn[1]) * cn[2] + 1, 0);
  this->RelabeledVoxels = 0;
  for (int round = 0;; ++round)
  {
    vtkSMPTools::For(0, cn[2], [&](vtkIdType k0, vtkIdType k1) {
      int lab[8], comp[12];
      for (vtkIdType ck = k0; ck < k1; ++ck)
      {
        if (!dirty[ck])
          continue;
        slabEntries[ck].clear();
        changes[ck].clear();
        for (int cj = 0; cj < cn[1]; ++cj)
        {
          const size_t row = static_cast<size_t>(ck) * cn[1] + cj;
          const size_t before = slabEntries[ck].size();
          for (int ci = 0; ci < cn[0]; ++ci)
          {
            if (g.UniformCorner(ci, cj, static_cast<int>(ck), lab))
              continue;
            const int c = CornerCopies(lab, comp);
            slabEntries[ck].push_back({ ci, c, 0 });
            int newLabel;
            // With two labels every fan of one is a boundary of the other: no pinch is possible.
            int other = lab[0];
            bool third = false;
            for (int k = 1; k < 8 && !third; ++k)
            {
              if (other == lab[0])
                other = lab[k];
              third = lab[k] != lab[0] && lab[k] != other;
            }
            const int o = (c > 0 && third) ? CornerPinch(lab, comp, newLabel) : -1;
            if (o < 0)
              continue;
            const int v[3] = { ci - 1 + Bit(o, 0), cj - 1 + Bit(o, 1), static_cast<int>(ck) - 1 + Bit(o, 2) };
            if (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[0] >= g.N[0] || v[1] >= g.N[1] || v[2] >= g.N[2])
              continue; // outside the image: the background cannot change
            changes[ck].push_back(
              { (static_cast<size_t>(v[2]) * g.N[1] + v[1]) * g.N[0] + v[0], static_cast<std::uint16_t>(newLabel) });
          }
          g.RowStart[row + 1] = static_cast<vtkIdType>(slabEntries[ck].size() - before);
        }
      }
    });
    std::map<size_t, std::uint16_t> apply;
    for (const auto& c : changes)
      for (const auto& x : c)
        apply.emplace(x.first, x.second); // the first corner (in order) decides
    if (apply.empty() || round == 20)
      break;
    std::fill(dirty.begin(), dirty.end(), 0);
    const size_t slice = static_cast<size_t>(g.N[0]) * g.N[1];
    for (const auto& x : apply)
    {
      g.Labels[x.first] = x.second;
      const size_t k = x.first / slice; // corners k and k + 1 touch voxel slice k
      dirty[k] = dirty[k + 1] = 1;
    }
    this->RelabeledVoxels += static_cast<vtkIdType>(apply.size());
  }
  for (size_t r = 1; r < g.RowStart.size(); ++r)
    g.RowStart[r] += g.RowStart[r - 1]; // per-row counts -> offsets
  g.Entries.reserve(static_cast<size_t>(g.RowStart.back()));
  vtkIdType nBasePoints = 0;
  for (auto& slab : slabEntries)
  {
    for (amLabelGrid::Entry& e : slab)
    {
      e.Base = nBasePoints;
      nBasePoints += e.Copies;
      this->SplitCorners += e.Copies > 1;
      g.Entries.push_back(e);
    }
    std::vector<amLabelGrid::Entry>().swap(slab);
  }
  this->BasePoints = nBasePoints;
}

void amLabelSurfaceExtractor::PlaceCorners()
{
  const amLabelGrid& g = this->Grid;
  const int cn[3] = { g.N[0] + 1, g.N[1] + 1, g.N[2] + 1 };
  // Corner vertex positions; a split corner's copies move a little into their own side.
  const vtkIdType nBasePoints = this->BasePoints;
  this->Points.assign(3 * static_cast<size_t>(nBasePoints), 0.0f);
  float* xyz = this->Points.data();
  vtkSMPTools::For(0, cn[2], [&](vtkIdType k0, vtkIdType k1) {
    int lab[8], comp[12];
    for (vtkIdType ck = k0; ck < k1; ++ck)
      for (int cj = 0; cj < cn[1]; ++cj)
      {
        const size_t row = static_cast<size_t>(ck) * cn[1] + cj;
        for (vtkIdType ei = g.RowStart[row]; ei < g.RowStart[row + 1]; ++ei)
        {
          const amLabelGrid::Entry& e = g.Entries[ei];
          const int ci = e.I;
          const double corner[3] = { ci - 0.5, cj - 0.5, ck - 0.5 };
          if (e.Copies == 1)
          {
            g.World(corner, xyz + 3 * e.Base);
            continue;
          }
          g.CornerLabels(ci, cj, static_cast<int>(ck), lab);
          const int nc = CornerCopies(lab, comp);
          for (int cc = 0; cc < nc; ++cc)
          {
            double shift[3] = { 0, 0, 0 };
            int count = 0;
            for (int f = 0; f < 12; ++f)
              if (comp[f] == cc)
              {
                const int axis = f / 4;
                shift[(axis + 1) % 3] += (f & 1) ? 0.5 : -0.5;
                shift[(axis + 2) % 3] += ((f >> 1) & 1) ? 0.5 : -0.5;
                ++count;
              }
            double p[3];
            for (int d = 0; d < 3; ++d)
              p[d] = corner[d] + 0.3 * shift[d] / count;
            g.World(p, xyz + 3 * (e.Base + cc));
          }
        }
      }
  });
}

vtkIdType amLabelSurfaceExtractor::CornerVertex(int axis, const int p[3], int a, int b) const
{
  const amLabelGrid& g = this->Grid;
  int c[3];
  const int A = (axis + 1) % 3, B = (axis + 2) % 3;
  c[axis] = p[axis] + 1;
  c[A] = p[A] + a;
  c[B] = p[B] + b;
  const amLabelGrid::Entry* e = g.Find(c[0], c[1], c[2]);
  if (e->Copies == 1)
    return e->Base;
  int lab[8], comp[12];
  g.CornerLabels(c[0], c[1], c[2], lab);
  CornerCopies(lab, comp);
  return e->Base + comp[axis * 4 + (1 - a) + 2 * (1 - b)];
}

amLabelSurfaceExtractor::EdgeInfo amLabelSurfaceExtractor::EdgeAround(
  int axis, const int p[3], int a0, int b0, int a1, int b1) const
{
  EdgeInfo e;
  const int A = (axis + 1) % 3, B = (axis + 2) % 3;
  int c0[3], c1[3];
  c0[axis] = c1[axis] = p[axis] + 1;
  c0[A] = p[A] + a0;
  c0[B] = p[B] + b0;
  c1[A] = p[A] + a1;
  c1[B] = p[B] + b1;
  e.Axis = a0 != a1 ? A : B;
  for (int d = 0; d < 3; ++d)
    e.Lo[d] = std::min(c0[d], c1[d]);
  const int u = (e.Axis + 1) % 3, w = (e.Axis + 2) % 3;
  const int cyc[4][2] = { { -1, -1 }, { 0, -1 }, { 0, 0 }, { -1, 0 } };
  for (int t = 0; t < 4; ++t)
  {
    e.Voxel[t][e.Axis] = e.Lo[e.Axis];
    e.Voxel[t][u] = e.Lo[u] + cyc[t][0];
    e.Voxel[t][w] = e.Lo[w] + cyc[t][1];
    e.Q[t] = this->Grid.Label(e.Voxel[t][0], e.Voxel[t][1], e.Voxel[t][2]);
  }
  return e;
}

void amLabelSurfaceExtractor::Faces()
{
  const amLabelGrid& g = this->Grid;
  // Pass 2: faces, slab by slab (slab s holds the faces whose lower voxel has k = s - 1).
  this->Slabs.assign(static_cast<size_t>(g.N[2] + 1), Slab());
  vtkSMPTools::For(0, g.N[2] + 1, [&](vtkIdType s0, vtkIdType s1) {
    for (vtkIdType s = s0; s < s1; ++s)
    {
      Slab& out = this->Slabs[s];
      const int pk = static_cast<int>(s) - 1;
      for (int axis = 2; axis >= 0; --axis)
      {
        if (axis != 2 && pk < 0)
          continue;
        const int lo[3] = { axis == 0 ? -1 : 0, axis == 1 ? -1 : 0, pk };
        const int hi[3] = { g.N[0] - 1, g.N[1] - 1, pk };
        for (int pj = lo[1]; pj <= hi[1]; ++pj)
          for (int pi = lo[0]; pi <= hi[0]; ++pi)
          {
            const int p[3] = { pi, pj, pk };
            const int la = g.Label(pi, pj, pk);
            const int lb = g.Label(pi + (axis == 0), pj + (axis == 1), pk + (axis == 2));
            if (la == lb)
              continue;
            bool special = false;
            for (int t = 0; t < 4 && !special; ++t)
            {
              const EdgeInfo e =
                this->EdgeAround(axis, p, Loop[t][0], Loop[t][1], Loop[(t + 1) % 4][0], Loop[(t + 1) % 4][1]);
              special = ResolveEdge(e.Q) >= 0;
            }
            if (special)
            {
              out.Special.push_back({ axis, pi, pj, pk });
              continue;
            }
            vtkIdType v[4];
            for (int t = 0; t < 4; ++t)
              v[t] = this->CornerVertex(axis, p, Loop[t][0], Loop[t][1]);
            // The loop's normal is +axis; it must point from the higher-ranked label.
            const bool flip = (this->Rank(la) < this->Rank(lb)) != this->Mirrored;
            if (!flip)
              out.Triangles.insert(out.Triangles.end(), { v[0], v[1], v[2], v[0], v[2], v[3] });
            else
              out.Triangles.insert(out.Triangles.end(), { v[0], v[2], v[1], v[0], v[3], v[2] });
            const int hiL = this->Rank(la) > this->Rank(lb) ? la : lb, loL = hiL == la ? lb : la;
            out.Labels.insert(out.Labels.end(), { g.Values[hiL], g.Values[loL], g.Values[hiL], g.Values[loL] });
          }
      }
    }
  });
}

void amLabelSurfaceExtractor::ResolvedEdgeFaces()
{
  const amLabelGrid& g = this->Grid;
  const vtkIdType nBasePoints = this->BasePoints;
  const float* xyz = this->Points.data();
  // Faces on resolved edges (rare): a centre vertex and a fan, with each resolved edge bent
  // towards the voxel the face wraps. Done serially, in slab order, so ids are deterministic.
  std::vector<std::array<float, 3>> extraPoints;
  std::map<std::tuple<vtkIdType, int, vtkIdType>, vtkIdType> midpoints;
  std::vector<vtkIdType>& specialTris = this->SpecialTriangles;
  std::vector<int>& specialLabels = this->SpecialLabels;
  specialTris.clear();
  specialLabels.clear();
  std::map<std::pair<vtkIdType, int>, bool> resolvedEdgeSet;
  for (const Slab& slab : this->Slabs)
    for (const auto& sf : slab.Special)
    {
      const int axis = sf[0];
      const int p[3] = { sf[1], sf[2], sf[3] };
      int q[3] = { p[0], p[1], p[2] };
      q[axis] += 1;
      const int la = g.Label(p[0], p[1], p[2]), lb = g.Label(q[0], q[1], q[2]);
      std::vector<vtkIdType> poly;
      for (int t = 0; t < 4; ++t)
      {
        poly.push_back(this->CornerVertex(axis, p, Loop[t][0], Loop[t][1]));
        const EdgeInfo e =
          this->EdgeAround(axis, p, Loop[t][0], Loop[t][1], Loop[(t + 1) % 4][0], Loop[(t + 1) % 4][1]);
        const int diag = ResolveEdge(e.Q);
        if (diag < 0)
          continue;
        const int connected = e.Q[diag];
        const int* wrapped = la != connected ? p : q;
        const vtkIdType edgeKey = g.Corner(e.Lo[0], e.Lo[1], e.Lo[2]);
        resolvedEdgeSet[{ edgeKey, e.Axis }] = true;
        const vtkIdType wrappedKey =
          ((static_cast<vtkIdType>(wrapped[2]) + 1) * (g.N[1] + 2) + (wrapped[1] + 1)) * (g.N[0] + 2) +
          (wrapped[0] + 1);
        const auto key = std::make_tuple(edgeKey, e.Axis, wrappedKey);
        auto it = midpoints.find(key);
        if (it == midpoints.end())
        {
          double mid[3];
          for (int d = 0; d < 3; ++d)
          {
            const double m = e.Lo[d] - 0.5 + (d == e.Axis ? 0.5 : 0.0);
            mid[d] = m + 0.25 * (wrapped[d] - m);
          }
          std::array<float, 3> w;
          g.World(mid, w.data());
          it = midpoints.emplace(key, nBasePoints + static_cast<vtkIdType>(extraPoints.size())).first;
          extraPoints.push_back(w);
        }
        poly.push_back(it->second);
      }
      // Centre vertex: the mean of the polygon's vertices.
      std::array<float, 3> centre = { 0, 0, 0 };
      for (vtkIdType id : poly)
      {
        const float* x = id < nBasePoints ? xyz + 3 * id : extraPoints[id - nBasePoints].data();
        for (int d = 0; d < 3; ++d)
          centre[d] += x[d] / static_cast<float>(poly.size());
      }
      const vtkIdType c = nBasePoints + static_cast<vtkIdType>(extraPoints.size());
      extraPoints.push_back(centre);
      const bool flip = (this->Rank(la) < this->Rank(lb)) != this->Mirrored;
      const int hiL = this->Rank(la) > this->Rank(lb) ? la : lb, loL = hiL == la ? lb : la;
      for (size_t t = 0; t < poly.size(); ++t)
      {
        const vtkIdType a = poly[t], b = poly[(t + 1) % poly.size()];
        if (!flip)
          specialTris.insert(specialTris.end(), { a, b, c });
        else
          specialTris.insert(specialTris.end(), { b, a, c });
        specialLabels.insert(specialLabels.end(), { g.Values[hiL], g.Values[loL] });
      }
    }
  this->ResolvedEdges = static_cast<vtkIdType>(resolvedEdgeSet.size());
  for (const auto& x : extraPoints)
    this->Points.insert(this->Points.end(), x.begin(), x.end());
}

void amLabelSurfaceExtractor::Assemble()
{
  // Assemble the cells: slab triangles in slab order, then the special fans.
  std::vector<vtkIdType> slabStart(this->Slabs.size() + 1, 0);
  for (size_t s = 0; s < this->Slabs.size(); ++s)
    slabStart[s + 1] = slabStart[s] + static_cast<vtkIdType>(this->Slabs[s].Triangles.size() / 3);
  const vtkIdType nRegular = slabStart.back();
  const vtkIdType nTri = nRegular + static_cast<vtkIdType>(this->SpecialTriangles.size() / 3);
  this->Triangles.resize(3 * static_cast<size_t>(nTri));
  this->Labels.resize(2 * static_cast<size_t>(nTri));
  vtkIdType* conn = this->Triangles.data();
  int* lab = this->Labels.data();
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Slabs.size()), [&](vtkIdType s0, vtkIdType s1) {
    for (vtkIdType s = s0; s < s1; ++s)
    {
      std::copy(this->Slabs[s].Triangles.begin(), this->Slabs[s].Triangles.end(), conn + 3 * slabStart[s]);
      std::copy(this->Slabs[s].Labels.begin(), this->Slabs[s].Labels.end(), lab + 2 * slabStart[s]);
      std::vector<vtkIdType>().swap(this->Slabs[s].Triangles);
      std::vector<int>().swap(this->Slabs[s].Labels);
    }
  });
  std::copy(this->SpecialTriangles.begin(), this->SpecialTriangles.end(), conn + 3 * nRegular);
  std::copy(this->SpecialLabels.begin(), this->SpecialLabels.end(), lab + 2 * nRegular);
}
