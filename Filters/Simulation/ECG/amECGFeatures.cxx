#include "amECGFeatures.h"

#include <algorithm>
#include <cmath>

bool amECGFeatures::Measure(const std::vector<double>& times, const std::vector<std::string>& names,
  const std::vector<std::vector<double>>& leads)
{
  const std::size_t nt = times.size();
  this->Leads.clear();
  if (nt < 3 || leads.empty())
  {
    this->Error = "fewer than three samples or no lead";
    return false;
  }
  std::vector<double> magnitude(nt, 0.0), velocity(nt, 0.0);
  for (const auto& lead : leads)
    for (std::size_t k = 0; k < nt; ++k)
    {
      magnitude[k] += lead[k] * lead[k];
      if (k > 0)
        velocity[k] += std::fabs(lead[k] - lead[k - 1]) / std::max(1e-12, times[k] - times[k - 1]);
    }
  for (double& m : magnitude)
    m = std::sqrt(m);
  const double largest = *std::max_element(magnitude.begin(), magnitude.end());
  if (!(largest > 0))
  {
    this->Error = "every lead is zero";
    return false;
  }
  std::size_t onset = 0;
  while (onset < nt && magnitude[onset] <= 0.01 * largest)
    ++onset;
  // The spatial velocity's peak within the first 200 ms after the onset: the QRS's steepest part.
  std::size_t peak = onset;
  for (std::size_t k = onset; k < nt && times[k] <= times[onset] + 200.0; ++k)
    if (velocity[k] > velocity[peak])
      peak = k;
  // 5 %: the last, small regions to activate (the base) still move the leads; the read QRS then
  // spans the activation, as a QRS duration does.
  const double quiet = 0.05 * velocity[peak];
  // The J point: the first quiet sample after the peak that stays quiet for 20 ms.
  std::size_t end = nt - 1;
  for (std::size_t k = peak; k < nt; ++k)
  {
    if (velocity[k] > quiet)
      continue;
    std::size_t j = k;
    while (j < nt && velocity[j] <= quiet && times[j] < times[k] + 20.0)
      ++j;
    if (j == nt || times[j] >= times[k] + 20.0)
    {
      end = k;
      break;
    }
    k = j;
  }
  end = std::min(end, nt - 1);
  std::size_t tEnd = end;
  for (std::size_t k = end; k < nt; ++k)
    if (magnitude[k] > 0.01 * largest)
      tEnd = k;
  this->QRSOnset = times[onset];
  this->QRSEnd = times[end];
  this->QRSDuration = this->QRSEnd - this->QRSOnset;
  this->TEnd = times[tEnd];
  this->QTInterval = this->TEnd - this->QRSOnset;
  for (std::size_t l = 0; l < leads.size(); ++l)
  {
    Lead out;
    out.Name = l < names.size() ? names[l] : std::to_string(l);
    for (std::size_t k = onset; k <= end; ++k)
    {
      out.R = std::max(out.R, leads[l][k]);
      out.S = std::min(out.S, leads[l][k]);
    }
    for (std::size_t k = end + 1; k <= tEnd; ++k)
      if (std::fabs(leads[l][k]) > std::fabs(out.T))
        out.T = leads[l][k];
    out.TPolarity = std::fabs(out.T) < 0.05 ? "flat" : (out.T > 0 ? "upright" : "inverted");
    this->Leads.push_back(out);
  }
  return true;
}
