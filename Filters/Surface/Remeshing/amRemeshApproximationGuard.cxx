#include "amRemeshApproximationGuard.h"

#include <utility>

namespace amRemesh
{
bool ApproximationGuard::StarNear(const std::vector<std::array<int, 3>>& ids,
  const std::vector<std::array<Vec3, 3>>& pos, const std::vector<int>& sheets, int centre,
  const std::vector<int>& kept) const
{
  thread_local std::vector<std::pair<int, int>> sampled; // spokes done: far end, sheet
  sampled.clear();
  for (size_t n = 0; n < ids.size(); ++n)
  {
    const auto& p = pos[n];
    const int k = ids[n][0] == centre ? 0 : (ids[n][1] == centre ? 1 : (ids[n][2] == centre ? 2 : -1));
    if (k < 0)
    {
      if (!this->In.TriangleNear(sheets[n], p[0], p[1], p[2]))
        return false;
      continue;
    }
    const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!this->In.Near(sheets[n], (p[0] + p[1] + p[2]) / 3.0, normal))
      return false;
    for (int e : { 1, 2 })
    {
      const int o = ids[n][(k + e) % 3];
      const std::pair<int, int> spoke(o, sheets[n]);
      if (std::binary_search(kept.begin(), kept.end(), o) ||
        std::find(sampled.begin(), sampled.end(), spoke) != sampled.end())
        continue;
      sampled.push_back(spoke);
      const Vec3 &c = p[k], &q = p[(k + e) % 3];
      for (double f : { 0.5, 0.25, 0.75 })
        if (!this->In.Near(sheets[n], c + f * (q - c), normal))
          return false;
    }
  }
  return true;
}

bool ApproximationGuard::ClustersStayNear(const std::vector<int>& removed, const std::vector<std::array<int, 3>>& ids,
  const std::vector<std::array<Vec3, 3>>& pos, const std::vector<int>& sheets, const std::vector<int>& newIds,
  const std::vector<int>& affected, Worker& worker, int from, int into) const
{
  const Surface& S = this->S;
  const double eps2 = this->In.Eps * this->In.Eps;
  struct StarTriangle
  {
    int Sheet, Id;
    std::array<Vec3, 3> X;
  };
  thread_local std::vector<StarTriangle> star;
  thread_local std::vector<int> starSheets;
  auto& pending = worker.PendingHints;
  pending.clear();
  for (int w : affected)
  {
    // The star of w afterwards, gathered on the first search (most entries keep their hint).
    bool gathered = false;
    auto gather = [&]() {
      if (gathered)
        return;
      gathered = true;
      star.clear();
      for (int t : S.VT[w])
        if (std::find(removed.begin(), removed.end(), t) == removed.end())
          star.push_back({ S.T[t].Sheet, t, { S.P[S.T[t].V[0]], S.P[S.T[t].V[1]], S.P[S.T[t].V[2]] } });
      for (size_t n = 0; n < ids.size(); ++n)
        if (ids[n][0] == w || ids[n][1] == w || ids[n][2] == w)
          star.push_back({ sheets[n], newIds[n], pos[n] });
      starSheets.clear();
      for (const auto& q : star)
        starSheets.push_back(q.Sheet);
      std::sort(starSheets.begin(), starSheets.end());
      starSheets.erase(std::unique(starSheets.begin(), starSheets.end()), starSheets.end());
    };
    // A triangle of the star within Eps of x on the sheet (-1: none); 'first' is tried first: the
    // triangle that replaces the entry's hint keeps its id, and is most often still near. (Any
    // triangle within Eps will do: the order changes only the time taken.)
    auto near = [&](const Vec3& x, int sheet, int first) {
      double cl[3];
      auto within = [&](const StarTriangle& q) {
        return q.Sheet == sheet &&
          amTriangleLocator::ClosestPointOnTriangle(x.data(), q.X[0].data(), q.X[1].data(), q.X[2].data(), cl) <= eps2;
      };
      if (first >= 0)
        for (const auto& q : star)
          if (q.Id == first)
          {
            if (within(q))
              return q.Id;
            break;
          }
      for (const auto& q : star)
        if (q.Id != first && within(q))
          return q.Id;
      return -1;
    };
    // Or, where an interface narrows to nothing between two junction curves, its two regions
    // still within Eps of x (the Hausdorff measure's rule for such a strip).
    auto bothRegionsNear = [&](const Vec3& x, int sheet) {
      double cl[3];
      for (int label : this->In.SheetLabels[sheet])
      {
        bool found = false;
        for (const auto& q : star)
        {
          const auto& sides = this->In.SheetLabels[q.Sheet];
          if ((sides[0] == label || sides[1] == label) &&
            amTriangleLocator::ClosestPointOnTriangle(x.data(), q.X[0].data(), q.X[1].data(), q.X[2].data(), cl) <=
              eps2)
          {
            found = true;
            break;
          }
        }
        if (!found)
          return false;
      }
      return true;
    };
    for (int owner : { w, w == into ? from : -1 })
    {
      if (owner < 0)
        continue;
      const auto& cluster = S.Cluster[owner];
      for (size_t i = 0; i < cluster.size(); ++i)
      {
        const ClusterEntry& entry = cluster[i];
        const Vec3& x = this->In.Points[entry.Point];
        if (entry.Sheet >= 0)
        {
          // (Membership of w's star, not the triangle's own record: a hint may be stale, and a
          // stale hint's triangle may lie on the other worker's side.)
          if (owner == w && entry.Hint >= 0 && std::find(removed.begin(), removed.end(), entry.Hint) == removed.end() &&
            std::find(S.VT[w].begin(), S.VT[w].end(), entry.Hint) != S.VT[w].end())
            continue; // still within Eps of the same, untouched triangle
          gather();
          const int hit = near(x, entry.Sheet, entry.Hint);
          if (hit < 0)
            return false;
          pending.push_back({ owner, static_cast<int>(i), hit });
        }
        else
        {
          // Every interface the input point lies on, not only those still around the vertex: a
          // small patch of an interface must not vanish from between its junction curves.
          gather();
          const std::vector<int>& onInput = this->Curves.InputSheets[entry.Point];
          for (int sheet : onInput.empty() ? starSheets : onInput)
            if (near(x, sheet, -1) < 0 && !(this->CloseStrips && bothRegionsNear(x, sheet)))
              return false;
        }
      }
    }
  }
  return true;
}

void ApproximationGuard::KeepHints(Worker& worker) const
{
  for (const auto& h : worker.PendingHints)
    this->S.Cluster[h[0]][h[1]].Hint = h[2];
  worker.PendingHints.clear();
}
}
