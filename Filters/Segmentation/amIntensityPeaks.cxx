// The intensity populations of a region: the peaks of its smoothed histogram.
#include "amIntensityPeaks.h"

#include <algorithm>
#include <cmath>

amIntensityPeaks amIntensityPeaks::Find(const std::vector<float>& values, double minimumShare)
{
  amIntensityPeaks peaks;
  if (values.empty())
    return peaks;
  const auto range = std::minmax_element(values.begin(), values.end());
  const double lo = *range.first, hi = *range.second;
  if (!(hi > lo))
    return peaks;
  constexpr int bins = 512;
  const double width = (hi - lo) / bins;
  std::vector<double> h(bins, 0.0);
  for (const float v : values)
    h[std::min(bins - 1, static_cast<int>((v - lo) / width))] += 1.0;
  // Smoothed over two bins, so noise in the counts makes no peaks.
  std::vector<double> s(bins, 0.0);
  for (int b = 0; b < bins; ++b)
    for (int d = -6; d <= 6; ++d)
      if (b + d >= 0 && b + d < bins)
        s[b] += h[b + d] * std::exp(-0.125 * d * d);
  std::vector<int> maxima, minima{ 0 };
  for (int b = 1; b + 1 < bins; ++b)
  {
    if (s[b] > s[b - 1] && s[b] >= s[b + 1])
      maxima.push_back(b);
    else if (s[b] < s[b - 1] && s[b] <= s[b + 1])
      minima.push_back(b);
  }
  minima.push_back(bins - 1);
  const double total = static_cast<double>(values.size());
  for (const int m : maxima)
  {
    // The population between the minima on either side.
    const int left = *(std::upper_bound(minima.begin(), minima.end(), m) - 1);
    const int right = *std::lower_bound(minima.begin(), minima.end(), m);
    double mass = 0.0;
    for (int b = left; b <= right; ++b)
      mass += h[b];
    if (mass >= minimumShare * total)
    {
      peaks.Centres.push_back(lo + (m + 0.5) * width);
      peaks.BasinLow.push_back(lo + left * width);
      peaks.BasinHigh.push_back(lo + (right + 1) * width);
    }
  }
  return peaks;
}

bool amIntensityPeaks::Below(double mean, double ownReach, double& peak) const
{
  for (std::size_t i = this->Centres.size(); i-- > 0;)
    if (this->Centres[i] < mean - ownReach && !(this->BasinLow[i] <= mean && mean <= this->BasinHigh[i]))
    {
      peak = this->Centres[i];
      return true;
    }
  return false;
}

bool amIntensityPeaks::Above(double mean, double ownReach, double& peak) const
{
  for (std::size_t i = 0; i < this->Centres.size(); ++i)
    if (this->Centres[i] > mean + ownReach && !(this->BasinLow[i] <= mean && mean <= this->BasinHigh[i]))
    {
      peak = this->Centres[i];
      return true;
    }
  return false;
}
