#include "amLabelSurface.h"

#include "amInputCheck.h"
#include "amProvenance.h"
#include "amSurfaceTopology.h"
#include "amThreading.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

vtkStandardNewMacro(amLabelSurface);

namespace
{
// Octant o of a voxel corner V: the voxel V - 1 + (o & 1, o >> 1 & 1, o >> 2 & 1).
inline int Bit(int o, int axis)
{
  return (o >> axis) & 1;
}

// The 12 faces inside the 2x2x2 block around a corner: f = axis * 4 + bitA + 2 * bitB, with
// A = axis + 1, B = axis + 2 (mod 3); the face separates the two octants that differ in 'axis'.
inline int FaceOf(int axis, int octant)
{
  return axis * 4 + Bit(octant, (axis + 1) % 3) + 2 * Bit(octant, (axis + 2) % 3);
}

inline int Octant(int axis, int bitAxis, int bitA, int bitB)
{
  int b[3];
  b[axis] = bitAxis;
  b[(axis + 1) % 3] = bitA;
  b[(axis + 2) % 3] = bitB;
  return b[0] | (b[1] << 1) | (b[2] << 2);
}

/// Around a voxel edge, four voxels in cyclic order. Returns -1 when the surface is manifold
/// there, 0 when the label of q0 = q2 must stay connected through the edge, 1 for q1 = q3.
inline int ResolveEdge(const int q[4])
{
  const bool d0 = q[0] == q[2] && q[1] != q[0] && q[3] != q[0];
  const bool d1 = q[1] == q[3] && q[0] != q[1] && q[2] != q[1];
  if (d0 && d1)
    return q[0] > q[1] ? 0 : 1;
  return d0 ? 0 : (d1 ? 1 : -1);
}

/// The four octants around the half-line from a corner along -m (s = 0) or +m (s = 1), in cyclic
/// order, and their labels.
const int kCycle[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
inline void HalfLine(const int lab[8], int m, int s, int oct[4], int q[4])
{
  for (int t = 0; t < 4; ++t)
  {
    oct[t] = Octant(m, s, kCycle[t][0], kCycle[t][1]);
    q[t] = lab[oct[t]];
  }
}

/// Union-find over at most 12 items (the block's faces or octants).
struct UnionFind12
{
  int Parent[12];
  UnionFind12()
  {
    for (int i = 0; i < 12; ++i)
      this->Parent[i] = i;
  }
  int Find(int a)
  {
    while (this->Parent[a] != a)
      a = this->Parent[a] = this->Parent[this->Parent[a]];
    return a;
  }
  void Join(int a, int b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
      this->Parent[std::max(a, b)] = std::min(a, b);
  }
};

/// The surface around one voxel corner: which of the 12 block faces are present, and how they
/// group into copies of the corner vertex (one copy per connected fan of faces). Returns the
/// number of copies (0: no surface here).
int CornerCopies(const int lab[8], int comp[12])
{
  bool present[12];
  int any = 0;
  for (int f = 0; f < 12; ++f)
  {
    const int axis = f / 4, bitA = f & 1, bitB = (f >> 1) & 1;
    present[f] = lab[Octant(axis, 0, bitA, bitB)] != lab[Octant(axis, 1, bitA, bitB)];
    any += present[f];
    comp[f] = -1;
  }
  if (!any)
    return 0;
  UnionFind12 uf;
  for (int m = 0; m < 3; ++m)
  {
    const int a = (m + 1) % 3, b = (m + 2) % 3;
    for (int s = 0; s < 2; ++s)
    {
      int oct[4], q[4];
      HalfLine(lab, m, s, oct, q);
      int face[4]; // face between oct[t] and oct[t+1]
      for (int t = 0; t < 4; ++t)
      {
        const int u = (t + 1) % 4;
        const int axis = kCycle[t][0] != kCycle[u][0] ? a : b;
        face[t] = FaceOf(axis, oct[t]);
      }
      const int diag = ResolveEdge(q);
      if (diag < 0)
      {
        int first = -1;
        for (int t = 0; t < 4; ++t)
          if (present[face[t]])
          {
            if (first < 0)
              first = face[t];
            else
              uf.Join(first, face[t]);
          }
      }
      else
      {
        // Connected label on the diagonal 'diag': the faces wrap the two other voxels.
        const int w0 = diag == 0 ? 1 : 0, w1 = w0 + 2; // wrapped positions
        uf.Join(face[(w0 + 3) % 4], face[w0]);
        uf.Join(face[(w1 + 3) % 4], face[w1]);
      }
    }
  }
  int copies = 0;
  int rootComp[12];
  for (int f = 0; f < 12; ++f)
    rootComp[f] = -1;
  for (int f = 0; f < 12; ++f)
    if (present[f])
    {
      const int r = uf.Find(f);
      if (rootComp[r] < 0)
        rootComp[r] = copies++;
      comp[f] = rootComp[r];
    }
  return copies;
}

/// A label that touches itself only at this corner through separate fans that the vertex copies
/// cannot separate (they are joined through other regions' interfaces, e.g. octants 0 and 7 of one
/// label with two other labels filling the rest). Returns the octant to relabel and its new label
/// (the most frequent other label among its three face neighbours in the block), or -1. comp is
/// CornerCopies' grouping of the block's faces.
int CornerPinch(const int lab[8], const int comp[12], int& newLabel)
{
  // Octants of one label connected through faces or through resolved (kept-connected) edges.
  UnionFind12 octants;
  for (int o = 0; o < 8; ++o)
    for (int k = 0; k < 3; ++k)
      if (lab[o] == lab[o ^ (1 << k)])
        octants.Join(o, o ^ (1 << k));
  for (int m = 0; m < 3; ++m)
    for (int s = 0; s < 2; ++s)
    {
      int oct[4], q[4];
      HalfLine(lab, m, s, oct, q);
      const int diag = ResolveEdge(q);
      if (diag >= 0)
        octants.Join(oct[diag], oct[diag + 2]);
    }
  // The copy of each octant: that of any of its present faces.
  int copyOf[8];
  for (int o = 0; o < 8; ++o)
  {
    copyOf[o] = -1;
    for (int k = 0; k < 3 && copyOf[o] < 0; ++k)
    {
      const int f = FaceOf(k, o);
      if (comp[f] >= 0)
        copyOf[o] = comp[f];
    }
  }
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      if (lab[a] == lab[b] && octants.Find(a) != octants.Find(b) && copyOf[a] >= 0 && copyOf[a] == copyOf[b])
      {
        int best = -1, bestCount = 0;
        for (int k = 0; k < 3; ++k)
        {
          const int c = lab[b ^ (1 << k)];
          if (c == lab[b])
            continue;
          int count = 0;
          for (int j = 0; j < 3; ++j)
            count += lab[b ^ (1 << j)] == c;
          if (count > bestCount || (count == bestCount && c < best))
          {
            best = c;
            bestCount = count;
          }
        }
        if (best < 0)
          continue;
        newLabel = best;
        return b;
      }
  return -1;
}

struct Grid
{
  int N[3];
  int Extent[6];
  double Origin[3], Spacing[3], Direction[9];
  // Each voxel holds the rank of its label among the distinct labels (ranks keep the order of
  // the values); Values[rank] is the label. Outside the image: the background's rank.
  std::vector<std::uint16_t> Labels;
  std::vector<int> Values;
  int Background; // rank of the background label

  int Label(int i, int j, int k) const
  {
    if (i < 0 || j < 0 || k < 0 || i >= this->N[0] || j >= this->N[1] || k >= this->N[2])
      return this->Background;
    return this->Labels[(static_cast<size_t>(k) * this->N[1] + j) * this->N[0] + i];
  }
  // Corner entries of one row of corners (fixed j, k), sorted by i.
  struct Entry
  {
    int I;
    int Copies;
    vtkIdType Base;
  };
  std::vector<vtkIdType> RowStart; // (N[1] + 1) * (N[2] + 1) + 1
  std::vector<Entry> Entries;
  const Entry* Find(int ci, int cj, int ck) const
  {
    const size_t row = static_cast<size_t>(ck) * (this->N[1] + 1) + cj;
    const Entry* b = this->Entries.data() + this->RowStart[row];
    const Entry* e = this->Entries.data() + this->RowStart[row + 1];
    const Entry* it = std::lower_bound(b, e, ci, [](const Entry& x, int v) { return x.I < v; });
    return (it != e && it->I == ci) ? it : nullptr;
  }
  void CornerLabels(int ci, int cj, int ck, int lab[8]) const
  {
    for (int o = 0; o < 8; ++o)
      lab[o] = this->Label(ci - 1 + Bit(o, 0), cj - 1 + Bit(o, 1), ck - 1 + Bit(o, 2));
  }
  /// True when the 8 voxels around the corner hold one label; otherwise fills lab.
  bool UniformCorner(int ci, int cj, int ck, int lab[8]) const
  {
    if (ci > 0 && cj > 0 && ck > 0 && ci < this->N[0] && cj < this->N[1] && ck < this->N[2])
    {
      // Interior corner: most are inside one region; test without bounds checks.
      const size_t sy = this->N[0], sz = static_cast<size_t>(this->N[0]) * this->N[1];
      const std::uint16_t* v =
        this->Labels.data() + ((static_cast<size_t>(ck) - 1) * this->N[1] + (cj - 1)) * this->N[0] + (ci - 1);
      const std::uint16_t l0 = v[0];
      if (v[1] == l0 && v[sy] == l0 && v[sy + 1] == l0 && v[sz] == l0 && v[sz + 1] == l0 && v[sz + sy] == l0 &&
        v[sz + sy + 1] == l0)
        return true;
    }
    this->CornerLabels(ci, cj, ck, lab);
    for (int o = 1; o < 8; ++o)
      if (lab[o] != lab[0])
        return false;
    return true;
  }
  vtkIdType Corner(int ci, int cj, int ck) const
  {
    return (static_cast<vtkIdType>(ck) * (this->N[1] + 1) + cj) * (this->N[0] + 1) + ci;
  }
  /// World position of a continuous voxel index (voxel centres at whole numbers).
  void World(const double ijk[3], float out[3]) const
  {
    double idx[3];
    for (int d = 0; d < 3; ++d)
      idx[d] = (ijk[d] + this->Extent[2 * d]) * this->Spacing[d];
    for (int r = 0; r < 3; ++r)
      out[r] = static_cast<float>(this->Origin[r] + this->Direction[3 * r] * idx[0] +
        this->Direction[3 * r + 1] * idx[1] + this->Direction[3 * r + 2] * idx[2]);
  }
};

struct SlabOutput
{
  std::vector<vtkIdType> Triangles; // 3 per triangle
  std::vector<int> Labels;          // 2 per triangle
  std::vector<std::array<int, 4>> Special; // axis, lower voxel (i, j, k) of faces on resolved edges
};
}

amLabelSurface::amLabelSurface()
  : BackgroundLabel(0)
  , ComputeTopology(true)
  , ResolvedEdges(0)
  , SplitCorners(0)
  , RelabelledVoxels(0)
{
  amThreading::Initialize();
  this->SetNumberOfOutputPorts(2);
}

amLabelSurface::~amLabelSurface() = default;

int amLabelSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

int amLabelSurface::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkTable");
  return 1;
}

int amLabelSurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkTable* table = vtkTable::GetData(outputVector, 1);
  this->ResolvedEdges = this->SplitCorners = 0;
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }

  Grid g;
  input->GetDimensions(g.N);
  input->GetExtent(g.Extent);
  input->GetOrigin(g.Origin);
  input->GetSpacing(g.Spacing);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      g.Direction[3 * r + c] = input->GetDirectionMatrix()->GetElement(r, c);
  for (int d = 0; d < 3; ++d)
    if (!(g.Spacing[d] > 0))
    {
      vtkErrorMacro("The label map's spacing along axis " << d << " is " << g.Spacing[d]
                                                          << "; it must be positive.");
      return 0;
    }
  const vtkIdType nVox = scalars->GetNumberOfTuples();
  const vtkIdType slice = static_cast<vtkIdType>(g.N[0]) * g.N[1];
  // Labels must be whole numbers: find the first offender and the distinct values, slice by slice.
  std::vector<vtkIdType> firstBad(static_cast<size_t>(g.N[2]), -1);
  std::vector<std::vector<int>> sliceValues(static_cast<size_t>(g.N[2]));
  auto readSlice = [&](vtkIdType k, std::vector<double>& row) {
    if (scalars->HasStandardMemoryLayout())
    {
      // Typed copy from the raw buffer (GetData/GetComponent go through virtual calls).
      switch (scalars->GetDataType())
      {
        vtkTemplateMacro({
          const VTK_TT* p = static_cast<const VTK_TT*>(scalars->GetVoidPointer(k * slice));
          std::copy(p, p + slice, row.begin());
        });
      }
      return;
    }
    vtkNew<vtkDoubleArray> buffer;
    buffer->SetArray(row.data(), slice, 1);
    scalars->GetData(k * slice, (k + 1) * slice - 1, 0, 0, buffer);
  };
  vtkSMPTools::For(0, g.N[2], [&](vtkIdType k0, vtkIdType k1) {
    std::vector<double> row(static_cast<size_t>(slice));
    for (vtkIdType k = k0; k < k1; ++k)
    {
      readSlice(k, row);
      std::vector<int>& vals = sliceValues[k];
      double last = std::numeric_limits<double>::quiet_NaN();
      for (vtkIdType i = 0; i < slice; ++i)
      {
        const double v = row[i];
        if (v == last)
          continue;
        if (!(std::fabs(v) < 2.0e9) || v != std::floor(v))
        {
          if (firstBad[k] < 0)
            firstBad[k] = k * slice + i;
          continue;
        }
        last = v;
        const int iv = static_cast<int>(v);
        auto it = std::lower_bound(vals.begin(), vals.end(), iv);
        if (it == vals.end() || *it != iv)
          vals.insert(it, iv);
      }
    }
  });
  for (vtkIdType bad : firstBad)
    if (bad >= 0)
    {
      vtkErrorMacro("Voxel " << bad << " of the label map has value " << scalars->GetComponent(bad, 0)
                             << ": labels must be whole numbers.");
      return 0;
    }
  for (const auto& vals : sliceValues)
    g.Values.insert(g.Values.end(), vals.begin(), vals.end());
  g.Values.push_back(this->BackgroundLabel);
  std::sort(g.Values.begin(), g.Values.end());
  g.Values.erase(std::unique(g.Values.begin(), g.Values.end()), g.Values.end());
  if (g.Values.size() == 1)
  {
    vtkErrorMacro("The label map has no voxel with a label other than the background ("
      << this->BackgroundLabel << "): there is no surface to extract.");
    return 0;
  }
  if (g.Values.size() > 65535)
  {
    vtkErrorMacro("The label map has " << g.Values.size() << " distinct labels; at most 65535 are supported.");
    return 0;
  }
  auto rankOf = [&](int v) {
    return static_cast<std::uint16_t>(std::lower_bound(g.Values.begin(), g.Values.end(), v) - g.Values.begin());
  };
  g.Background = rankOf(this->BackgroundLabel);
  g.Labels.resize(static_cast<size_t>(nVox));
  vtkSMPTools::For(0, g.N[2], [&](vtkIdType k0, vtkIdType k1) {
    std::vector<double> row(static_cast<size_t>(slice));
    for (vtkIdType k = k0; k < k1; ++k)
    {
      readSlice(k, row);
      double last = std::numeric_limits<double>::quiet_NaN();
      std::uint16_t lastRank = 0;
      for (vtkIdType i = 0; i < slice; ++i)
      {
        if (row[i] != last)
        {
          last = row[i];
          lastRank = rankOf(static_cast<int>(last));
        }
        g.Labels[k * slice + i] = lastRank;
      }
    }
  });
  this->UpdateProgress(0.1);

  // Pass 1: the corners on the surface and how many copies of each one's vertex, row by row.
  // The same scan finds the corners where a label touches itself through fans that no vertex
  // split can separate; if there are any, one voxel each is relabelled and the scan is redone
  // for the slabs of corners around the relabelled voxels only.
  const int cn[3] = { g.N[0] + 1, g.N[1] + 1, g.N[2] + 1 };
  std::vector<std::vector<Grid::Entry>> slabEntries(static_cast<size_t>(cn[2]));
  std::vector<std::vector<std::pair<size_t, std::uint16_t>>> changes(static_cast<size_t>(cn[2]));
  std::vector<char> dirty(static_cast<size_t>(cn[2]), 1);
  g.RowStart.assign(static_cast<size_t>(cn[1]) * cn[2] + 1, 0);
  this->RelabelledVoxels = 0;
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
            changes[ck].push_back({ (static_cast<size_t>(v[2]) * g.N[1] + v[1]) * g.N[0] + v[0],
              static_cast<std::uint16_t>(newLabel) });
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
    this->RelabelledVoxels += static_cast<vtkIdType>(apply.size());
  }
  if (this->RelabelledVoxels > 0)
    vtkWarningMacro(<< this->RelabelledVoxels
                    << " voxel(s) relabelled where a label touched itself only at a voxel corner "
                       "between other regions (no vertex split can make that manifold).");
  for (size_t r = 1; r < g.RowStart.size(); ++r)
    g.RowStart[r] += g.RowStart[r - 1]; // per-row counts -> offsets
  g.Entries.reserve(static_cast<size_t>(g.RowStart.back()));
  vtkIdType nBasePoints = 0;
  for (auto& slab : slabEntries)
  {
    for (Grid::Entry& e : slab)
    {
      e.Base = nBasePoints;
      nBasePoints += e.Copies;
      this->SplitCorners += e.Copies > 1;
      g.Entries.push_back(e);
    }
    std::vector<Grid::Entry>().swap(slab);
  }
  this->UpdateProgress(0.3);

  // Corner vertex positions; a split corner's copies move a little into their own side.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(nBasePoints);
  float* xyz = static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  vtkSMPTools::For(0, cn[2], [&](vtkIdType k0, vtkIdType k1) {
    int lab[8], comp[12];
    for (vtkIdType ck = k0; ck < k1; ++ck)
      for (int cj = 0; cj < cn[1]; ++cj)
      {
        const size_t row = static_cast<size_t>(ck) * cn[1] + cj;
        for (vtkIdType ei = g.RowStart[row]; ei < g.RowStart[row + 1]; ++ei)
        {
          const Grid::Entry& e = g.Entries[ei];
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
  this->UpdateProgress(0.45);

  // The vertex of a face at one of its corners (the corner's copy that owns this face).
  auto cornerVertex = [&](int axis, const int p[3], int a, int b) -> vtkIdType {
    int c[3];
    const int A = (axis + 1) % 3, B = (axis + 2) % 3;
    c[axis] = p[axis] + 1;
    c[A] = p[A] + a;
    c[B] = p[B] + b;
    const Grid::Entry* e = g.Find(c[0], c[1], c[2]);
    if (e->Copies == 1)
      return e->Base;
    int lab[8], comp[12];
    g.CornerLabels(c[0], c[1], c[2], lab);
    CornerCopies(lab, comp);
    return e->Base + comp[axis * 4 + (1 - a) + 2 * (1 - b)];
  };
  // The four voxels around the edge of a face from local corner (a0,b0) to (a1,b1), cyclic.
  struct EdgeInfo
  {
    int Axis;
    int Lo[3];       // corner at the lower end
    int Voxel[4][3]; // cyclic
    int Q[4];
  };
  auto edgeInfo = [&](int axis, const int p[3], int a0, int b0, int a1, int b1) {
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
      e.Q[t] = g.Label(e.Voxel[t][0], e.Voxel[t][1], e.Voxel[t][2]);
    }
    return e;
  };
  const int loop[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  const bool mirrored = input->GetDirectionMatrix()->Determinant() < 0;
  auto rank = [&](int l) -> long long {
    return l == g.Background ? std::numeric_limits<long long>::min() : static_cast<long long>(l);
  };

  // Pass 2: faces, slab by slab (slab s holds the faces whose lower voxel has k = s - 1).
  std::vector<SlabOutput> slabs(static_cast<size_t>(g.N[2] + 1));
  vtkSMPTools::For(0, g.N[2] + 1, [&](vtkIdType s0, vtkIdType s1) {
    for (vtkIdType s = s0; s < s1; ++s)
    {
      SlabOutput& out = slabs[s];
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
              const EdgeInfo e = edgeInfo(axis, p, loop[t][0], loop[t][1], loop[(t + 1) % 4][0],
                loop[(t + 1) % 4][1]);
              special = ResolveEdge(e.Q) >= 0;
            }
            if (special)
            {
              out.Special.push_back({ axis, pi, pj, pk });
              continue;
            }
            vtkIdType v[4];
            for (int t = 0; t < 4; ++t)
              v[t] = cornerVertex(axis, p, loop[t][0], loop[t][1]);
            // The loop's normal is +axis; it must point from the higher-ranked label.
            const bool flip = (rank(la) < rank(lb)) != mirrored;
            if (!flip)
              out.Triangles.insert(out.Triangles.end(), { v[0], v[1], v[2], v[0], v[2], v[3] });
            else
              out.Triangles.insert(out.Triangles.end(), { v[0], v[2], v[1], v[0], v[3], v[2] });
            const int hiL = rank(la) > rank(lb) ? la : lb, loL = hiL == la ? lb : la;
            out.Labels.insert(out.Labels.end(), { g.Values[hiL], g.Values[loL], g.Values[hiL], g.Values[loL] });
          }
      }
    }
  });
  this->UpdateProgress(0.7);

  // Faces on resolved edges (rare): a centre vertex and a fan, with each resolved edge bent
  // towards the voxel the face wraps. Done serially, in slab order, so ids are deterministic.
  std::vector<std::array<float, 3>> extraPoints;
  std::map<std::tuple<vtkIdType, int, vtkIdType>, vtkIdType> midpoints;
  std::vector<vtkIdType> specialTris;
  std::vector<int> specialLabels;
  std::map<std::pair<vtkIdType, int>, bool> resolvedEdgeSet;
  for (const SlabOutput& slab : slabs)
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
        poly.push_back(cornerVertex(axis, p, loop[t][0], loop[t][1]));
        const EdgeInfo e =
          edgeInfo(axis, p, loop[t][0], loop[t][1], loop[(t + 1) % 4][0], loop[(t + 1) % 4][1]);
        const int diag = ResolveEdge(e.Q);
        if (diag < 0)
          continue;
        const int connected = e.Q[diag];
        const int* wrapped = la != connected ? p : q;
        const vtkIdType edgeKey = g.Corner(e.Lo[0], e.Lo[1], e.Lo[2]);
        resolvedEdgeSet[{ edgeKey, e.Axis }] = true;
        const vtkIdType wrappedKey = ((static_cast<vtkIdType>(wrapped[2]) + 1) * (g.N[1] + 2) +
                                       (wrapped[1] + 1)) * (g.N[0] + 2) + (wrapped[0] + 1);
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
      const bool flip = (rank(la) < rank(lb)) != mirrored;
      const int hiL = rank(la) > rank(lb) ? la : lb, loL = hiL == la ? lb : la;
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
  if (!extraPoints.empty())
  {
    points->Resize(nBasePoints + static_cast<vtkIdType>(extraPoints.size()));
    points->SetNumberOfPoints(nBasePoints + static_cast<vtkIdType>(extraPoints.size()));
    for (size_t i = 0; i < extraPoints.size(); ++i)
      points->SetPoint(nBasePoints + static_cast<vtkIdType>(i), extraPoints[i][0], extraPoints[i][1],
        extraPoints[i][2]);
  }

  // Assemble the cells: slab triangles in slab order, then the special fans.
  std::vector<vtkIdType> slabStart(slabs.size() + 1, 0);
  for (size_t s = 0; s < slabs.size(); ++s)
    slabStart[s + 1] = slabStart[s] + static_cast<vtkIdType>(slabs[s].Triangles.size() / 3);
  const vtkIdType nRegular = slabStart.back();
  const vtkIdType nTri = nRegular + static_cast<vtkIdType>(specialTris.size() / 3);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(nTri + 1);
  connectivity->SetNumberOfTuples(3 * nTri);
  vtkNew<vtkIntArray> labelArray;
  labelArray->SetName("Labels");
  labelArray->SetNumberOfComponents(2);
  labelArray->SetNumberOfTuples(nTri);
  vtkIdType* off = offsets->GetPointer(0);
  vtkIdType* conn = connectivity->GetPointer(0);
  int* lab = labelArray->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(slabs.size()), [&](vtkIdType s0, vtkIdType s1) {
    for (vtkIdType s = s0; s < s1; ++s)
    {
      std::copy(slabs[s].Triangles.begin(), slabs[s].Triangles.end(), conn + 3 * slabStart[s]);
      std::copy(slabs[s].Labels.begin(), slabs[s].Labels.end(), lab + 2 * slabStart[s]);
      std::vector<vtkIdType>().swap(slabs[s].Triangles);
      std::vector<int>().swap(slabs[s].Labels);
    }
  });
  std::copy(specialTris.begin(), specialTris.end(), conn + 3 * nRegular);
  std::copy(specialLabels.begin(), specialLabels.end(), lab + 2 * nRegular);
  for (vtkIdType t = 0; t <= nTri; ++t)
    off[t] = 3 * t;
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(labelArray);
  vtkNew<vtkDoubleArray> voxelSize;
  voxelSize->SetName("VoxelSize");
  voxelSize->InsertNextValue(std::min({ g.Spacing[0], g.Spacing[1], g.Spacing[2] }));
  output->GetFieldData()->AddArray(voxelSize);
  std::ostringstream params;
  params << "BackgroundLabel=" << this->BackgroundLabel << " ResolvedEdges=" << this->ResolvedEdges
         << " SplitCorners=" << this->SplitCorners << " RelabelledVoxels=" << this->RelabelledVoxels;
  amProvenance::Record(output, input, "amLabelSurface", params.str());
  this->UpdateProgress(0.85);

  if (this->ComputeTopology)
  {
    std::vector<amSurfaceTopology::Region> regions;
    if (!amSurfaceTopology::Analyse(output, regions, why, this->BackgroundLabel))
    {
      vtkErrorMacro("Topology check failed: " << why);
      return 0;
    }
    // The voxel volume of each region, to compare with the enclosed volume.
    std::vector<vtkIdType> count(g.Values.size(), 0);
    for (std::uint16_t l : g.Labels)
      ++count[l];
    std::map<int, vtkIdType> voxels;
    for (size_t r = 0; r < g.Values.size(); ++r)
      voxels[g.Values[r]] = count[r];
    vtkSmartPointer<vtkTable> t = amSurfaceTopology::ToTable(regions);
    vtkNew<vtkDoubleArray> vv;
    vv->SetName("VoxelVolume");
    vv->SetNumberOfTuples(static_cast<vtkIdType>(regions.size()));
    const double voxelVolume = g.Spacing[0] * g.Spacing[1] * g.Spacing[2];
    for (size_t r = 0; r < regions.size(); ++r)
      vv->SetValue(static_cast<vtkIdType>(r), voxels[regions[r].Label] * voxelVolume);
    t->AddColumn(vv);
    table->ShallowCopy(t);
    for (const auto& r : regions)
      if (r.BoundaryEdges || r.NonManifoldEdges || r.MisorientedEdges)
        vtkWarningMacro("Region " << r.Label << " is not a closed oriented manifold: " << r.BoundaryEdges
                                  << " boundary, " << r.NonManifoldEdges << " non-manifold, "
                                  << r.MisorientedEdges << " misoriented edges.");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void amLabelSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundLabel: " << this->BackgroundLabel << "\n";
  os << indent << "ComputeTopology: " << this->ComputeTopology << "\n";
}
