// The tissue classes of one CT: expectation-maximisation of a Gaussian mixture on the body's
// histogram, with each centre held in its anatomical range.
#include "amTissueMixture.h"

#include <algorithm>
#include <cmath>

namespace
{
constexpr double HistogramLow = -1100.0;
constexpr double HistogramHigh = 1700.0;
constexpr double BinWidth = 4.0;
constexpr int Bins = static_cast<int>((HistogramHigh - HistogramLow) / BinWidth);
constexpr double TwoPi = 6.283185307179586;
// Cortical bone in an adult (HU): the far side of the soft-tissue/bone boundary where the scan
// shows no bone peak of its own.
constexpr double CorticalBone = 700.0;

struct Prior
{
  double Low, High;          // the centre's anatomical range, HU
  double Sigma;              // the spread the fit starts from, HU
  double MinSigma, MaxSigma; // the spreads it may take, HU
};

// Spreads: the least is a quiet scan's (no class is narrower than a bin); the largest lets the
// class take noise of 60 HU and a soft kernel's partial volume, no more (a wider class would take
// its neighbours).
const Prior Priors[amTissueMixture::NumberOfClasses] = {
  { -1100.0, -950.0, 20.0, 2.0, 80.0 },  // air
  { -950.0, -400.0, 60.0, 2.0, 200.0 },  // lung
  { -200.0, -40.0, 20.0, 2.0, 70.0 },    // fat
  { -20.0, 120.0, 20.0, 2.0, 70.0 },     // soft tissue
  { 120.0, 600.0, 30.0, 2.0, 80.0 },     // contrast blood
  { 400.0, 1600.0, 150.0, 20.0, 300.0 }, // cortical bone
};

const char* const Names[amTissueMixture::NumberOfClasses] = { "Air", "Lung", "Fat", "SoftTissue", "ContrastBlood",
  "Bone" };

double Centre(int b)
{
  return HistogramLow + (b + 0.5) * BinWidth;
}

// The class's peak in its range: the highest local maximum of the histogram (smoothed over three
// bins) inside [low, high], not at its edges (a slope there is a neighbour's tail), and the share
// of the histogram between the valleys on either side of it; share 0 when there is no peak.
void Peak(const std::vector<double>& h, double total, double low, double high, double& mode, double& share)
{
  std::vector<double> s(Bins, 0.0);
  for (int b = 0; b < Bins; ++b)
    for (int d = -9; d <= 9; ++d)
      if (b + d >= 0 && b + d < Bins)
        s[b] += h[b + d] * std::exp(-d * d / 18.0);
  int best = -1;
  for (int b = 1; b + 1 < Bins; ++b)
  {
    const double x = Centre(b);
    if (x <= low + BinWidth || x >= high - BinWidth)
      continue;
    if (s[b] > s[b - 1] && s[b] >= s[b + 1] && (best < 0 || s[b] > s[best]))
      best = b;
  }
  share = 0.0;
  mode = 0.5 * (low + high);
  if (best < 0)
    return;
  mode = Centre(best);
  int left = best, right = best;
  while (left > 0 && s[left - 1] <= s[left])
    --left;
  while (right + 1 < Bins && s[right + 1] <= s[right])
    ++right;
  for (int b = left; b <= right; ++b)
    share += h[b];
  share /= total;
}

// EM over the active classes; returns the iterations taken.
int Expectation(const std::vector<double>& h, double total,
  const std::array<bool, amTissueMixture::NumberOfClasses>& on, amTissueMixture::Result& r)
{
  const int K = amTissueMixture::NumberOfClasses;
  const double uniformDensity = BinWidth / (HistogramHigh - HistogramLow);
  // Each active class's share of a bin's density at x, in p; returns the bin's whole density.
  const auto joint = [&](double x, std::array<double, K>& p) {
    double sum = r.Uniform * uniformDensity;
    for (int k = 0; k < K; ++k)
      if (on[k])
      {
        const auto& c = r.Classes[k];
        const double z = (x - c.Mean) / c.Sigma;
        p[k] = c.Weight * BinWidth * std::exp(-0.5 * z * z) / (c.Sigma * std::sqrt(TwoPi));
        sum += p[k];
      }
    return sum;
  };
  // f(bin, its centre, the classes' shares, the bin's density) for every bin holding values.
  const auto eachBin = [&](auto&& f) {
    for (int b = 0; b < Bins; ++b)
    {
      if (h[b] == 0.0)
        continue;
      const double x = Centre(b);
      std::array<double, K> p{};
      const double sum = joint(x, p);
      if (sum > 0.0)
        f(b, x, p, sum);
    }
  };
  int iteration = 0;
  for (; iteration < 500; ++iteration)
  {
    std::array<double, K> W{}, S1{}, S2{};
    double WU = 0.0;
    eachBin([&](int b, double x, const std::array<double, K>& p, double sum) {
      for (int k = 0; k < K; ++k)
        if (on[k])
        {
          const double w = h[b] * p[k] / sum;
          W[k] += w;
          S1[k] += w * x;
        }
      WU += h[b] * r.Uniform * uniformDensity / sum;
    });
    double change = 0.0;
    for (int k = 0; k < K; ++k)
    {
      if (!on[k])
        continue;
      auto& c = r.Classes[k];
      const double mean = W[k] > 0.0 ? std::clamp(S1[k] / W[k], Priors[k].Low, Priors[k].High) : c.Mean;
      change = std::max(change, std::fabs(mean - c.Mean));
      c.Mean = mean;
    }
    // The spreads about the new centres, with the responsibilities evaluated at them.
    eachBin([&](int b, double x, const std::array<double, K>& p, double sum) {
      for (int k = 0; k < K; ++k)
        if (on[k])
          S2[k] += h[b] * p[k] / sum * (x - r.Classes[k].Mean) * (x - r.Classes[k].Mean);
    });
    for (int k = 0; k < K; ++k)
    {
      if (!on[k])
        continue;
      auto& c = r.Classes[k];
      const double variance = W[k] > 0.0 ? S2[k] / W[k] + BinWidth * BinWidth / 12.0 : c.Sigma * c.Sigma;
      const double sigma = std::clamp(std::sqrt(variance), Priors[k].MinSigma, Priors[k].MaxSigma);
      change = std::max(change, std::fabs(sigma - c.Sigma));
      c.Sigma = sigma;
      const double weight = W[k] / total;
      change = std::max(change, 1e3 * std::fabs(weight - c.Weight));
      c.Weight = weight;
    }
    // The partial-volume component may take no more than a fifth of the body.
    r.Uniform = std::min(0.2, WU / total);
    if (change < 0.01)
      break;
  }
  return iteration + 1;
}
}

void amTissueMixture::CentreRange(int c, double& low, double& high)
{
  low = Priors[c].Low;
  high = Priors[c].High;
}

const char* amTissueMixture::Name(int c)
{
  return c >= 0 && c < NumberOfClasses ? Names[c] : "Unknown";
}

namespace
{
template<typename T>
std::vector<double> Histogram(const T* values, const unsigned char* mask, std::size_t n, std::size_t& samples)
{
  std::vector<double> h(Bins, 0.0);
  samples = 0;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (mask && !mask[v])
      continue;
    const double x = values[v];
    const int b = static_cast<int>(std::floor((x - HistogramLow) / BinWidth));
    h[std::clamp(b, 0, Bins - 1)] += 1.0;
    ++samples;
  }
  return h;
}
}

amTissueMixture::Result amTissueMixture::Fit(
  const double* values, const unsigned char* mask, std::size_t n, double minimumWeight)
{
  std::size_t samples = 0;
  const std::vector<double> h = Histogram(values, mask, n, samples);
  return FitHistogram(h, samples, minimumWeight);
}

amTissueMixture::Result amTissueMixture::Fit(
  const float* values, const unsigned char* mask, std::size_t n, double minimumWeight)
{
  std::size_t samples = 0;
  const std::vector<double> h = Histogram(values, mask, n, samples);
  return FitHistogram(h, samples, minimumWeight);
}

amTissueMixture::Result amTissueMixture::FitHistogram(
  const std::vector<double>& h, std::size_t samples, double minimumWeight)
{
  Result r;
  r.Samples = samples;
  if (r.Samples == 0)
  {
    r.Problem = "there is no body in the image (every voxel is air)";
    return r;
  }
  const double total = static_cast<double>(r.Samples);
  std::array<bool, NumberOfClasses> on{};
  for (int k = 0; k < NumberOfClasses; ++k)
  {
    double mode, mass;
    Peak(h, total, Priors[k].Low, Priors[k].High, mode, mass);
    on[k] = mass >= minimumWeight;
    r.Classes[k].Mean = mode;
    r.Classes[k].Sigma = Priors[k].Sigma;
    r.Classes[k].Weight = std::max(mass, minimumWeight);
  }
  r.Uniform = 0.02;

  for (int round = 0; round < NumberOfClasses; ++round)
  {
    r.Iterations += Expectation(h, total, on, r);
    // A class whose centre ends at the edge of its range is a neighbour's tail; a class below the
    // least weight is not there. The weakest such class goes, and the rest is fitted again.
    int drop = -1;
    for (int k = 0; k < NumberOfClasses; ++k)
    {
      if (!on[k])
        continue;
      const auto& c = r.Classes[k];
      const bool pinned = c.Mean <= Priors[k].Low + 0.5 || c.Mean >= Priors[k].High - 0.5;
      if ((pinned || c.Weight < minimumWeight) && (drop < 0 || c.Weight < r.Classes[drop].Weight))
        drop = k;
    }
    if (drop < 0)
      break;
    on[drop] = false;
    r.Classes[drop].Weight = 0.0;
  }
  for (int k = 0; k < NumberOfClasses; ++k)
    r.Classes[k].Found = on[k];
  if (!on[Soft])
  {
    r.Problem = "no soft tissue: no intensity class with its centre between -20 and 120 HU (is the image a CT "
                "in HU, or windowed to 0..255 with its window given?)";
    return r;
  }

  // Boundaries between the classes found, in order; a class not found has an empty range.
  // Air is always there for the boundary: outside the body, at -1000 HU.
  Component air = r.Classes[Air];
  if (!air.Found)
    air.Mean = -1000.0;
  auto mean = [&](int k) { return k == Air ? air.Mean : r.Classes[k].Mean; };
  const auto& soft = r.Classes[Soft];
  const auto& blood = r.Classes[Blood];
  int previous = Air;
  for (int k = Lung; k < NumberOfClasses; ++k)
  {
    if (!on[k])
      continue;
    double t = 0.5 * (mean(previous) + mean(k));
    if (previous == Soft && k == Blood)
      t = std::min(std::max(t, blood.Mean - 2.5 * blood.Sigma), blood.Mean);
    if (k == Bone)
    {
      t = 0.5 * (soft.Mean + r.Classes[Bone].Mean);
      if (previous == Blood)
        t = std::min(std::max(t, blood.Mean + 3.0 * blood.Sigma), r.Classes[Bone].Mean);
    }
    for (int j = previous; j < k; ++j)
      r.Upper[j] = t;
    previous = k;
  }
  if (!on[Bone])
  {
    // No peak of bone (a crop without bone, or thin bone blurred by coarse voxels): what is
    // brighter than every class found and half-way to cortical bone is still bone.
    double t = 0.5 * (soft.Mean + CorticalBone);
    if (on[Blood])
      t = std::max(t, blood.Mean + 3.0 * blood.Sigma);
    else
      t = std::min(t, soft.Mean + 3.0 * soft.Sigma); // no contrast: all above soft tissue is bone
    for (int j = previous; j < Bone; ++j)
      r.Upper[j] = t;
    previous = Bone;
  }
  for (int j = previous; j < NumberOfClasses; ++j)
    r.Upper[j] = HistogramHigh * 1e6;
  return r;
}

int amTissueMixture::Classify(const Result& r, double value)
{
  for (int k = 0; k < NumberOfClasses - 1; ++k)
    if (value < r.Upper[k])
      return k;
  return NumberOfClasses - 1;
}
