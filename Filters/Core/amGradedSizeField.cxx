#include "amGradedSizeField.h"

#include <algorithm>
#include <cmath>
#include <limits>

bool amGradedSizeField::Build(const std::vector<std::array<double, 3>>& points, const std::vector<double>& sizes,
  double gradation, double maximumSize, const double bounds[6], std::string& why, long long maximumNodes)
{
  if (points.empty() || points.size() != sizes.size())
  {
    why = "no sizes to grow a size field from";
    return false;
  }
  for (size_t i = 0; i < sizes.size(); ++i)
    if (!std::isfinite(sizes[i]) || sizes[i] <= 0)
    {
      why = "the size at point " + std::to_string(i) + " is " + std::to_string(sizes[i]) +
        " (sizes must be finite and positive)";
      return false;
    }
  if (!(gradation >= 1.0))
  {
    why = "the gradation must be at least 1";
    return false;
  }
  const double slope = gradation - 1.0;
  this->Maximum = maximumSize > 0 ? maximumSize : std::numeric_limits<double>::infinity();
  this->Minimum = *std::min_element(sizes.begin(), sizes.end());
  double extent[3], volume = 1.0;
  for (int d = 0; d < 3; ++d)
  {
    extent[d] = std::max(bounds[2 * d + 1] - bounds[2 * d], 1e-9);
    volume *= extent[d];
  }
  // Spacing: no finer than a third of the smallest size, no more nodes than allowed.
  this->H = std::max(this->Minimum / 3.0, std::cbrt(volume / static_cast<double>(maximumNodes)));
  for (int d = 0; d < 3; ++d)
  {
    this->N[d] = static_cast<int>(std::ceil(extent[d] / this->H)) + 3;
    this->Origin[d] = bounds[2 * d] - this->H;
  }
  const long long nx = this->N[0], ny = this->N[1], nz = this->N[2];
  const float big = std::numeric_limits<float>::max();
  this->Values.assign(static_cast<size_t>(nx * ny * nz), big);
  auto index = [&](long long i, long long j, long long k) { return (k * ny + j) * nx + i; };

  // Seed the nodes of the cell around each point (and one cell beyond).
  for (size_t p = 0; p < points.size(); ++p)
  {
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d)
    {
      const double g = (points[p][d] - this->Origin[d]) / this->H;
      lo[d] = std::max(0, static_cast<int>(std::floor(g)) - 1);
      hi[d] = std::min(this->N[d] - 1, static_cast<int>(std::floor(g)) + 2);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
        {
          const double dx = this->Origin[0] + i * this->H - points[p][0];
          const double dy = this->Origin[1] + j * this->H - points[p][1];
          const double dz = this->Origin[2] + k * this->H - points[p][2];
          const double v = sizes[p] + slope * std::sqrt(dx * dx + dy * dy + dz * dz);
          float& node = this->Values[static_cast<size_t>(index(i, j, k))];
          node = std::min(node, static_cast<float>(v));
        }
  }

  // Two chamfer sweeps over the 26-neighbourhood (13 "earlier" neighbours forward, 13 later back).
  struct Offset
  {
    int di, dj, dk;
    float w;
  };
  std::vector<Offset> earlier;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
      {
        const int linear = (dk * 3 + dj) * 3 + di;
        if (linear < 0)
          earlier.push_back(
            { di, dj, dk, static_cast<float>(slope * this->H * std::sqrt(double(di * di + dj * dj + dk * dk))) });
      }
  // A node with all 26 neighbours in the grid takes them at fixed index offsets (the same minima
  // in the same order as the checked path).
  std::vector<long long> linear;
  for (const Offset& o : earlier)
    linear.push_back((static_cast<long long>(o.dk) * ny + o.dj) * nx + o.di);
  for (int pass = 0; pass < 2; ++pass)
  {
    const int s = pass == 0 ? 1 : -1;
    for (long long kk = 0; kk < nz; ++kk)
    {
      const long long k = pass == 0 ? kk : nz - 1 - kk;
      for (long long jj = 0; jj < ny; ++jj)
      {
        const long long j = pass == 0 ? jj : ny - 1 - jj;
        const bool innerRow = j > 0 && k > 0 && j < ny - 1 && k < nz - 1;
        for (long long ii = 0; ii < nx; ++ii)
        {
          const long long i = pass == 0 ? ii : nx - 1 - ii;
          const long long at = index(i, j, k);
          float& v = this->Values[static_cast<size_t>(at)];
          if (innerRow && i > 0 && i < nx - 1)
          {
            for (size_t n = 0; n < earlier.size(); ++n)
            {
              const float u = this->Values[static_cast<size_t>(at + s * linear[n])];
              if (u != big)
                v = std::min(v, u + earlier[n].w);
            }
            continue;
          }
          for (const Offset& o : earlier)
          {
            const long long a = i + s * o.di, b = j + s * o.dj, c = k + s * o.dk;
            if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz)
              continue;
            const float u = this->Values[static_cast<size_t>(index(a, b, c))];
            if (u != big)
              v = std::min(v, u + o.w);
          }
        }
      }
    }
  }
  return true;
}

double amGradedSizeField::Evaluate(const double x[3]) const
{
  if (this->Values.empty())
    return this->Maximum;
  int base[3];
  double f[3];
  for (int d = 0; d < 3; ++d)
  {
    double g = (x[d] - this->Origin[d]) / this->H;
    g = std::min(std::max(g, 0.0), static_cast<double>(this->N[d] - 1) - 1e-9);
    base[d] = std::min(static_cast<int>(g), this->N[d] - 2);
    f[d] = g - base[d];
  }
  const long long nx = this->N[0], ny = this->N[1];
  double v = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    const int i = base[0] + (c & 1), j = base[1] + ((c >> 1) & 1), k = base[2] + ((c >> 2) & 1);
    const double w =
      ((c & 1) ? f[0] : 1 - f[0]) * (((c >> 1) & 1) ? f[1] : 1 - f[1]) * (((c >> 2) & 1) ? f[2] : 1 - f[2]);
    v += w * this->Values[static_cast<size_t>((k * ny + j) * nx + i)];
  }
  return std::min(std::max(v, this->Minimum), this->Maximum);
}
