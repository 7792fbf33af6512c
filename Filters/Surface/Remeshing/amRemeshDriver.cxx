// The remesher's driver: iterations of collapses, flips and relaxation, then the Hausdorff bound
// enforced by insertions and the small angles cleaned where that keeps it.
#include "amRemesher.h"

#include <algorithm>

namespace amRemesh
{
Remesher::Result Remesher::Run(int iterations, const std::function<void(double)>& progress)
{
  auto report = [&progress](double fraction) {
    if (progress)
      progress(fraction);
  };
  for (int it = 0; it < iterations; ++it)
  {
    this->Grid.Rebuild();
    for (int pass = 0; pass < 8; ++pass)
    {
      if (pass > 0)
        this->Grid.RebuildIfStale();
      if (this->CollapsePass() == 0)
        break;
    }
    // Most slots are dead after the collapses: the passes, measures and undo copies that follow
    // read only the live ones.
    this->Compact();
    for (int pass = 0; pass < 3; ++pass)
      if (this->FlipPass(pass > 0) == 0)
        break;
    this->RelaxPass();
    report(0.05 + 0.75 * (it + 1) / iterations);
  }
  this->FlipPass();
  // The regions' volumes given back (amRemeshVolumes) before the bound is enforced: the guards
  // keep each moved star near the input, and the measure that follows sees the moved surface
  // once, finding and refining whatever still lies beyond the tolerance.
  if (this->KeepVolumes)
    this->PreserveVolumes(this->InputVolumes, 3);
  Result result;
  double& h = result.Hausdorff;
  double& upper = result.UpperBound;
  long long& inserted = result.Inserted;
  h = this->Enforce(upper, inserted);
  bool measured = true; // the last Measure saw the surface as it is (its per-triangle distances)
  report(0.85);
  // Triangles with small angles that the insertions left (no tetrahedron on them can be good):
  // removed where a flip or collapse allows it (junction vertices closing the strips of an
  // interface that narrows to nothing between two curves too), then the bound enforced again.
  // Kept only if the distance ends no worse than before (or within the tolerance), fewer
  // triangles have small angles or the smallest is larger, and no edge got much shorter (where
  // the bound cannot be met, more insertion rounds would only refine towards a point). Last,
  // the degenerate triangles alone, with collapses that may leave angles down to
  // MinimumNewAngle: the same checks undo that where it costs the bound.
  auto attempt = [&](double below, double floor) {
    long long smallBefore, smallAfter;
    double smallestBefore, smallestAfter, shortestBefore, shortestAfter;
    this->Mesh.AngleSummary(smallBefore, smallestBefore, shortestBefore);
    if (!(smallestBefore < below))
      return false; // nothing to clean: no copy of the surface for an undo
    Snapshot before = this->Save();
    // The per-triangle distances of the state saved, restored with it (no measure again).
    std::vector<double> localBefore = this->Hausdorff.TriangleDistances();
    const bool measuredBefore = measured;
    const double hBefore = h, upperBefore = upper;
    const long long insertedBefore = inserted;
    int cleaned = 0;
    this->LongestEdge = 2 * LongEdge;
    this->NewAngleFloor = floor;
    this->Approximation.CloseStrips = true;
    for (int round = 0; round < 3; ++round)
    {
      const int n = this->SmallAngleCleanup(below);
      cleaned += n;
      if (n == 0)
        break;
    }
    this->LongestEdge = LongEdge;
    this->NewAngleFloor = SmallAngle;
    this->Approximation.CloseStrips = false;
    if (cleaned == 0)
      return false;
    h = this->Enforce(upper, inserted);
    measured = true;
    this->Mesh.AngleSummary(smallAfter, smallestAfter, shortestAfter);
    if (h > std::max(hBefore, this->In.Eps) || (smallAfter >= smallBefore && !(smallestAfter > smallestBefore)) ||
      shortestAfter < 0.5 * shortestBefore)
    {
      this->Restore(std::move(before));
      this->Hausdorff.RestoreTriangleDistances(std::move(localBefore));
      measured = measuredBefore;
      h = hBefore;
      upper = upperBefore;
      inserted = insertedBefore;
      return false;
    }
    return true;
  };
  for (int n = 0; n < 3 && attempt(SmallAngle, SmallAngle); ++n)
    ;
  attempt(DegenerateAngle, MinimumNewAngle);
  if (!measured)
  {
    // The distances are not of the surface as it is: measured again (incrementally).
    std::vector<std::pair<int, Vec3>> insert;
    std::vector<int> edgeOf;
    h = this->Hausdorff.Measure(this->Mesh, this->In, upper, insert, edgeOf);
  }
  return result;
}

double Remesher::Enforce(double& upper, long long& inserted)
{
  std::vector<std::pair<int, Vec3>> insert;
  std::vector<int> edgeOf;
  double h = this->Hausdorff.Measure(this->Mesh, this->In, upper, insert, edgeOf);
  this->Grid.Rebuild();
  // How far beyond the tolerance the triangles to refine are, in sum: where a part is thinner
  // than the tolerance allows, the refinements only chase the same far point round after round
  // (a smaller triangle each time, as far from it as the last); the rounds stop when three in a
  // row bring neither h nor this sum down.
  auto excess = [&]() {
    const std::vector<double>& local = this->Hausdorff.TriangleDistances();
    double sum = 0;
    for (const auto& far : insert)
      if (far.first < static_cast<int>(local.size()))
        sum += std::max(0.0, local[far.first] - this->In.Eps);
    return sum;
  };
  double bestH = h, bestExcess = excess();
  int stalled = 0;
  for (int round = 0; round < 30 && !insert.empty() && stalled < 3; ++round)
  {
    long long done = 0;
    std::vector<int> blocked;
    for (size_t i = 0; i < insert.size(); ++i)
    {
      const int t = insert[i].first;
      // Longest-edge bisection towards the input first (it keeps the angles: the far point
      // itself, inserted, often lands near a corner or an edge and leaves slivers), the far
      // point itself where the bisection is refused (its edge split there when it lies on one,
      // else or where that is refused inserted, or a vertex moved onto it).
      const bool ok = this->Refine(t) > 0 || (edgeOf[i] >= 0 && this->SplitEdge(t, edgeOf[i], insert[i].second)) ||
        this->Insert(t, insert[i].second) || this->MoveVertexNearest(t, insert[i].second);
      done += ok;
      if (!ok)
      {
        blocked.push_back(insert[i].first);
        blocked.push_back(this->W().LastHit);
      }
    }
    // Refused where a triangle is in the way (or the new ones would fold): refine both, towards
    // the input where nothing crosses.
    for (int t : blocked)
      done += this->Refine(t);
    inserted += done;
    h = this->Hausdorff.Measure(this->Mesh, this->In, upper, insert, edgeOf);
    if (done == 0)
      break;
    const double e = excess();
    const bool better = h < bestH - 1e-6 * this->In.Eps || e < 0.99 * bestExcess;
    stalled = better ? 0 : stalled + 1;
    bestH = std::min(bestH, h);
    bestExcess = std::min(bestExcess, e);
  }
  return h;
}
}
