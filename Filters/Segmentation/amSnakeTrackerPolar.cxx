#include "amSnakeTracker.h"

#include "amPolarContour.h"

// One track per seed: a star-shaped snake (amPolarContour) in the seed's slice, then slice after
// slice around the last section's centroid, the last contour as prior.
bool amSnakeTracker::RunPolar()
{
  const int* rd = this->Size;
  const float* fv = this->Feature.data();
  const int ax = this->P.SliceAxis, u = ax == 0 ? 1 : 0, v = ax == 2 ? 1 : 2;
  const int nu = rd[u], nv = rd[v], ns = rd[ax];
  const double pixelArea = this->Spacing[u] * this->Spacing[v];
  amPolarContour::Parameters pp;
  pp.OutsideThreshold = this->P.OutsideThreshold;
  pp.EdgeContrast = this->P.EdgeContrast;
  pp.MaximumRadius = this->P.MaximumRadius;
  pp.MaximumGrowth = this->P.MaximumGrowth;
  pp.AreaCost = this->P.AreaCost;
  std::vector<float> slice(static_cast<size_t>(nu) * nv);
  const auto load = [&](int is) {
    for (int iv = 0; iv < nv; ++iv)
      for (int iu = 0; iu < nu; ++iu)
        slice[static_cast<size_t>(iv) * nu + iu] = fv[this->AtSlice(iu, iv, is)];
  };
  const amPolarContour contour(slice.data(), nu, nv, this->Spacing[u], this->Spacing[v]);
  std::vector<unsigned char> section(slice.size()), previous;
  // Pixels of the section in slice is, and how many of them earlier tracks already have.
  const auto measure = [&](int is, size_t& area, size_t& taken) {
    area = taken = 0;
    for (int iv = 0; iv < nv; ++iv)
      for (int iu = 0; iu < nu; ++iu)
        if (section[static_cast<size_t>(iv) * nu + iu])
        {
          ++area;
          taken += this->InsideMask[this->AtSlice(iu, iv, is)];
        }
  };
  const auto store = [&](int is) {
    for (int iv = 0; iv < nv; ++iv)
      for (int iu = 0; iu < nu; ++iu)
        if (section[static_cast<size_t>(iv) * nu + iu])
          this->InsideMask[this->AtSlice(iu, iv, is)] = 1;
  };
  size_t started = 0;
  for (const auto& sd : this->Seeds)
  {
    ++started;
    const int s0 = std::min(ns - 1, std::max(0, static_cast<int>(std::lround(sd[ax])) - this->Lo[ax]));
    const double cu = sd[u] - this->Lo[u], cv = sd[v] - this->Lo[v];
    load(s0);
    std::fill(section.begin(), section.end(), 0);
    contour.Fill(cu, cv, contour.Find(cu, cv, {}, pp), section.data());
    size_t area0, taken;
    measure(s0, area0, taken);
    // A seed whose section earlier tracks already cover (90 %) adds nothing; one that
    // covers more (where a vessel's section is not star-shaped, as in the arch) goes on.
    if (area0 == 0 || area0 * pixelArea < this->P.MinimumSliceArea || 10 * taken >= 9 * area0)
      continue;
    store(s0);
    const std::vector<unsigned char> seedSection = section;
    // The section's mean contrast above OutsideThreshold; the seed's sets the scale.
    const auto contrast = [&]() {
      double sum = 0;
      size_t c = 0;
      for (size_t q = 0; q < section.size(); ++q)
        if (section[q])
        {
          sum += slice[q];
          ++c;
        }
      return c ? sum / c - this->P.OutsideThreshold : 0.0;
    };
    const double seedContrast = contrast();
    for (int dir : { -1, 1 })
    {
      previous = seedSection;
      size_t previousArea = area0;
      for (int is = s0 + dir; is >= 0 && is < ns; is += dir)
      {
        double mu = 0, mv = 0;
        size_t c = 0;
        for (int iv = 0; iv < nv; ++iv)
          for (int iu = 0; iu < nu; ++iu)
            if (previous[static_cast<size_t>(iv) * nu + iu])
            {
              mu += iu;
              mv += iv;
              ++c;
            }
        mu /= c;
        mv /= c;
        const std::vector<double> prior = contour.RadiiOf(previous.data(), mu, mv, pp.MaximumRadius);
        load(is);
        std::fill(section.begin(), section.end(), 0);
        contour.Fill(mu, mv, contour.Find(mu, mv, prior, pp), section.data());
        size_t area;
        measure(is, area, taken);
        // The stopping rule, or the section no longer looks like the structure (a heart's
        // section entering the liver).
        if (this->Ends(area, previousArea, pixelArea) || contrast() < this->P.MinimumSectionContrast * seedContrast)
          break;
        store(is);
        if (2 * taken > area)
          break; // met another track
        previous = section;
        previousArea = area;
        if ((this->Abort && this->Abort()))
          return false;
      }
    }
    this->Report((0.15 + 0.85 * started / this->Seeds.size()));
  }
  return true;
}
