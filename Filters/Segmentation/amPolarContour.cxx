#include "amPolarContour.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
constexpr double TwoPi = 6.283185307179586;
constexpr double Forbidden = 1e12;
}

amPolarContour::amPolarContour(const float* image, int nu, int nv, double su, double sv)
  : Image(image)
  , Nu(nu)
  , Nv(nv)
  , Su(su)
  , Sv(sv)
{
}

double amPolarContour::Sample(double u, double v) const
{
  // Bilinear, clamped at the border.
  u = std::min(std::max(u, 0.0), this->Nu - 1.0);
  v = std::min(std::max(v, 0.0), this->Nv - 1.0);
  const int u0 = std::min(static_cast<int>(u), this->Nu - 2 < 0 ? 0 : this->Nu - 2);
  const int v0 = std::min(static_cast<int>(v), this->Nv - 2 < 0 ? 0 : this->Nv - 2);
  const int u1 = std::min(u0 + 1, this->Nu - 1), v1 = std::min(v0 + 1, this->Nv - 1);
  const double fu = u - u0, fv = v - v0;
  const auto at = [&](int a, int b) { return static_cast<double>(this->Image[static_cast<size_t>(b) * this->Nu + a]); };
  return (1 - fv) * ((1 - fu) * at(u0, v0) + fu * at(u1, v0)) + fv * ((1 - fu) * at(u0, v1) + fu * at(u1, v1));
}

std::vector<double> amPolarContour::Find(
  double cu, double cv, const std::vector<double>& previous, const Parameters& p) const
{
  const int nr = std::max(2, static_cast<int>(std::floor(p.MaximumRadius / RadialStep)) + 1); // r = n * step
  const int window = static_cast<int>(std::lround(3.0 / RadialStep));                         // 3 mm outside
  const int half = static_cast<int>(std::lround(1.5 / RadialStep));                           // edge over 3 mm
  const int ns = nr + window + half;                                                          // samples per ray
  const int na = NumberOfRays;
  // Costs per sample (RadialStep mm), as documented per mm.
  const double inside = 4.0 * RadialStep, outside = 2.0 * RadialStep, area = p.AreaCost * RadialStep,
               prior = p.PriorWeight * RadialStep, smooth = 2.0 * RadialStep;
  std::vector<double> cost(static_cast<size_t>(na) * nr);
  std::vector<double> profile(ns);
  std::vector<int> dark(ns + 1), bright(ns + 1);
  for (int a = 0; a < na; ++a)
  {
    const double t = TwoPi * a / na, ca = std::cos(t), sa = std::sin(t);
    for (int n = 0; n < ns; ++n)
      profile[n] = this->Sample(cu + ca * n * RadialStep / this->Su, cv + sa * n * RadialStep / this->Sv);
    dark[0] = bright[0] = 0; // prefix counts
    for (int n = 0; n < ns; ++n)
    {
      const bool isDark = profile[n] < p.OutsideThreshold;
      dark[n + 1] = dark[n] + (isDark ? 1 : 0);
      bright[n + 1] = bright[n] + (isDark ? 0 : 1);
    }
    for (int n = 0; n < nr; ++n)
    {
      const double r = n * RadialStep;
      double c = inside * dark[n + 1] + outside * (bright[n + 1 + window] - bright[n + 1]);
      const double drop = (profile[std::max(0, n - half)] - profile[n + half]) / p.EdgeContrast;
      c -= p.EdgeWeight * std::min(3.0, std::max(0.0, drop));
      c += area * n;
      if (!previous.empty())
      {
        c += prior * std::abs(r - previous[a]) / RadialStep;
        if (r > previous[a] + p.MaximumGrowth)
          c += Forbidden;
      }
      if (r < p.MinimumRadius)
        c += Forbidden;
      cost[static_cast<size_t>(a) * nr + n] = c;
    }
  }
  // Circular dynamic program, unrolled over three turns; between neighbouring rays the radius
  // changes by at most 1 mm or the arc between them (a slope of 45 degrees), whichever is more.
  const double arc = TwoPi / na; // radians between rays
  const int minStep = static_cast<int>(std::lround(1.0 / RadialStep));
  const int turns = 3, total = turns * na;
  std::vector<double> best(nr), next(nr);
  std::vector<int> back(static_cast<size_t>(total) * nr, 0);
  for (int n = 0; n < nr; ++n)
    best[n] = cost[n];
  for (int i = 1; i < total; ++i)
  {
    const double* row = &cost[static_cast<size_t>(i % na) * nr];
    for (int n = 0; n < nr; ++n)
    {
      double b = std::numeric_limits<double>::max();
      int arg = n;
      const int maxStep = std::max(minStep, static_cast<int>(std::floor(n * arc)));
      for (int s = -maxStep; s <= maxStep; ++s) // fixed order: ties go to the smallest radius
      {
        const int m = n + s;
        if (m < 0 || m >= nr)
          continue;
        const double v = best[m] + smooth * std::abs(s);
        if (v < b)
        {
          b = v;
          arg = m;
        }
      }
      next[n] = b + row[n];
      back[static_cast<size_t>(i) * nr + n] = arg;
    }
    std::swap(best, next);
  }
  int n = static_cast<int>(std::min_element(best.begin(), best.end()) - best.begin());
  std::vector<double> radii(na);
  for (int i = total - 1; i >= 0; --i)
  {
    if (i >= na && i < 2 * na)
      radii[i - na] = n * RadialStep;
    if (i > 0)
      n = back[static_cast<size_t>(i) * nr + n];
  }
  return radii;
}

std::vector<double> amPolarContour::RadiiOf(const unsigned char* mask, double cu, double cv, double maximumRadius) const
{
  std::vector<double> radii(NumberOfRays, 0.0);
  const int nr = static_cast<int>(std::floor(maximumRadius / RadialStep));
  for (int a = 0; a < NumberOfRays; ++a)
  {
    const double t = TwoPi * a / NumberOfRays, ca = std::cos(t), sa = std::sin(t);
    for (int n = 1; n <= nr; ++n)
    {
      const int u = static_cast<int>(std::lround(cu + ca * n * RadialStep / this->Su));
      const int v = static_cast<int>(std::lround(cv + sa * n * RadialStep / this->Sv));
      if (u < 0 || v < 0 || u >= this->Nu || v >= this->Nv)
        break;
      if (mask[static_cast<size_t>(v) * this->Nu + u])
        radii[a] = n * RadialStep; // the farthest inside, should the mask not be star-shaped from here
    }
  }
  return radii;
}

void amPolarContour::Fill(double cu, double cv, const std::vector<double>& radii, unsigned char* mask) const
{
  double rmax = 0;
  for (double r : radii)
    rmax = std::max(rmax, r);
  const int u0 = std::max(0, static_cast<int>(std::floor(cu - rmax / this->Su)));
  const int u1 = std::min(this->Nu - 1, static_cast<int>(std::ceil(cu + rmax / this->Su)));
  const int v0 = std::max(0, static_cast<int>(std::floor(cv - rmax / this->Sv)));
  const int v1 = std::min(this->Nv - 1, static_cast<int>(std::ceil(cv + rmax / this->Sv)));
  const int na = static_cast<int>(radii.size());
  for (int v = v0; v <= v1; ++v)
    for (int u = u0; u <= u1; ++u)
    {
      const double dx = (u - cu) * this->Su, dy = (v - cv) * this->Sv, rho = std::sqrt(dx * dx + dy * dy);
      double t = std::atan2(dy, dx);
      if (t < 0)
        t += TwoPi;
      const double x = t / TwoPi * na;
      const int a = static_cast<int>(std::floor(x)) % na, b = (a + 1) % na;
      const double f = x - std::floor(x), r = (1 - f) * radii[a] + f * radii[b];
      if (rho <= r)
        mask[static_cast<size_t>(v) * this->Nu + u] = 1;
    }
}
