#include "amTetraImproveMesh.h"

#include "vtkSMPTools.h"

namespace amTetraImprove
{
namespace
{
const int Edges[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
}

bool Mend(Mesh& m, int t, double split, int maxRing, Report& report, std::vector<int>& ringTets, std::vector<int>& ring)
{
  bool done = false;
  for (int e = 0; e < 6 && !done; ++e)
    done = RemoveEdge(m, m.T[t][Edges[e][0]], m.T[t][Edges[e][1]], maxRing, ringTets, ring);
  if (done)
  {
    ++report.EdgeRemovals;
    return true;
  }
  for (int i = 0; i < 4 && !done; ++i)
    done = Flip23(m, t, i);
  if (done)
  {
    ++report.Flips23;
    return true;
  }
  // The last resort for the worst elements: split a free edge (the longest first).
  if (m.Objectives[t] < split)
  {
    std::array<std::pair<double, int>, 6> order;
    for (int e = 0; e < 6; ++e)
    {
      const Vec d = amTetraGeometry::Sub(m.X(m.T[t][Edges[e][0]]), m.X(m.T[t][Edges[e][1]]));
      order[e] = { -amTetraGeometry::Dot(d, d), e };
    }
    std::sort(order.begin(), order.end());
    const Tet x = m.T[t];
    for (int k = 0; k < 6 && !done; ++k)
      done = SplitEdge(m, x[Edges[order[k].second][0]], x[Edges[order[k].second][1]], split, ringTets, ring);
    if (done)
    {
      ++report.EdgeSplits;
      return true;
    }
    // A sliver with three faces on the surface has no free edge: its free face is split.
    for (int i = 0; i < 4 && !done; ++i)
      done = SplitFace(m, Sorted(x[(i + 1) % 4], x[(i + 2) % 4], x[(i + 3) % 4]), split);
    if (done)
    {
      ++report.FaceSplits;
      return true;
    }
  }
  m.Tried[t] = 1;
  return false;
}

namespace
{
/// Mend's choice for t without the change, where it is a flip or nothing.
struct Plan
{
  enum Kind : char
  {
    None,    // not planned: done at its turn
    Nothing, // no flip mends it, and no split is tried: marked tried
    EdgeRemoval,
    Flip,
  } What = None;
  std::vector<int> Killed;
  std::vector<Tet> Made;
  int Region = 0;
};

void PlanMend(const Mesh& m, int t, double split, int maxRing, Plan& plan, std::vector<int>& ring)
{
  plan.What = Plan::None;
  for (int e = 0; e < 6; ++e)
    if (PlanEdgeRemoval(m, m.T[t][Edges[e][0]], m.T[t][Edges[e][1]], maxRing, plan.Killed, ring, plan.Made))
    {
      plan.What = Plan::EdgeRemoval;
      plan.Region = m.R[plan.Killed[0]];
      return;
    }
  for (int i = 0; i < 4; ++i)
  {
    int other;
    if (PlanFlip23(m, t, i, other, plan.Made))
    {
      plan.What = Plan::Flip;
      plan.Killed = { t, other };
      plan.Region = m.R[t];
      return;
    }
  }
  if (!(m.Objectives[t] < split))
    plan.What = Plan::Nothing;
}
}

long TopologyPass(Mesh& m, double bad, double split, int maxRing, Report& report)
{
  // A plan reads the stars of t's vertices: their tetrahedra, those tetrahedra's vertices'
  // positions and objectives. Every change stamps the vertices of the tetrahedra it makes: the
  // removed ones' vertices are all among them, and the one vertex a change moves is a new one,
  // in them too. So a star that lost or gained a tetrahedron, or one whose vertex moved, has its
  // centre stamped, and a plan is still the serial loop's own when no vertex of t is.
  const size_t block = 4096;
  std::vector<Plan> plans(block);
  std::vector<size_t> touched(m.Inc.size(), 0);
  std::vector<int> ringTets, ring;
  long changes = 0;
  size_t id = 0;
  const size_t limit = m.T.size();
  auto wanted = [&](size_t t) { return m.Alive[t] && !m.Tried[t] && m.Objectives[t] < bad; };
  auto clean = [&](int t) {
    for (int x : m.T[t])
      if (touched[x] == id)
        return false;
    return true;
  };
  // The tetrahedra wanted when the pass starts, in order: at its turn one of them may have left
  // (killed, or marked tried by its own Mend), but none joins (a change only makes new ones, past
  // 'limit', and moves only new vertices). The blocks are blocks of these: each keeps both cores
  // busy, and a pass with a few bad elements left starts the threads once, not once per 4096.
  std::vector<size_t> list;
  for (size_t t = 0; t < limit; ++t)
    if (wanted(t))
      list.push_back(t);
  for (size_t b0 = 0; b0 < list.size(); b0 += block)
  {
    ++id;
    const size_t b1 = std::min(list.size(), b0 + block);
    vtkSMPTools::For(static_cast<vtkIdType>(b0), static_cast<vtkIdType>(b1), 128, [&](vtkIdType i0, vtkIdType i1) {
      thread_local std::vector<int> planRing;
      for (vtkIdType i = i0; i < i1; ++i)
      {
        Plan& plan = plans[static_cast<size_t>(i) - b0];
        plan.What = Plan::None;
        const size_t t = list[static_cast<size_t>(i)];
        if (wanted(t))
          PlanMend(m, static_cast<int>(t), split, maxRing, plan, planRing);
      }
    });
    for (size_t i = b0; i < b1; ++i)
    {
      const size_t t = list[i];
      if (!wanted(t))
        continue;
      const Plan& plan = plans[i - b0];
      const size_t before = m.T.size();
      bool changed;
      if (plan.What == Plan::None || !clean(static_cast<int>(t)))
        changed = Mend(m, static_cast<int>(t), split, maxRing, report, ringTets, ring);
      else if (plan.What == Plan::Nothing)
      {
        m.Tried[t] = 1;
        changed = false;
      }
      else
      {
        Replace(m, plan.Killed, plan.Made, plan.Region);
        ++(plan.What == Plan::EdgeRemoval ? report.EdgeRemovals : report.Flips23);
        changed = true;
      }
      if (touched.size() < m.Inc.size())
        touched.resize(m.Inc.size(), 0);
      for (size_t s = before; s < m.T.size(); ++s)
        for (int x : m.T[s])
          touched[x] = id;
      changes += changed;
    }
  }
  return changes;
}
}
