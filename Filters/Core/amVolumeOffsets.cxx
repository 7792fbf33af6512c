#include "amVolumeOffsets.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

std::vector<double> amVolumeOffsets::Solve(
  const std::vector<Sheet>& sheets, const std::map<int, double>& error, double limit)
{
  std::map<int, int> row;
  for (const auto& kv : error)
    row.emplace(kv.first, static_cast<int>(row.size()));
  const int n = static_cast<int>(row.size());
  if (n == 0)
    return {};
  Eigen::VectorXd e(n);
  for (const auto& kv : error)
    e[row[kv.first]] = kv.second;
  auto rowOf = [&row](int label) {
    const auto it = row.find(label);
    return it == row.end() ? -1 : it->second;
  };
  std::vector<Eigen::Triplet<double>> entries;
  for (const Sheet& s : sheets)
  {
    if (!s.Valid())
      continue;
    const double w = s.Sensitivity * s.Sensitivity / s.Area;
    const int r0 = rowOf(s.Lo), r1 = rowOf(s.Hi);
    if (r0 >= 0)
      entries.emplace_back(r0, r0, w);
    if (r1 >= 0)
      entries.emplace_back(r1, r1, w);
    if (r0 >= 0 && r1 >= 0)
    {
      entries.emplace_back(r0, r1, -w);
      entries.emplace_back(r1, r0, -w);
    }
  }
  double largest = 0;
  for (const auto& entry : entries)
    largest = std::max(largest, std::fabs(entry.value()));
  if (!(largest > 0))
    return {};
  for (int r = 0; r < n; ++r)
    entries.emplace_back(r, r, 1e-9 * largest);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success)
    return {};
  const Eigen::VectorXd y = solver.solve(e);
  std::vector<double> offset(sheets.size(), 0.0);
  for (size_t k = 0; k < sheets.size(); ++k)
  {
    const Sheet& s = sheets[k];
    if (!s.Valid())
      continue;
    const int r0 = rowOf(s.Lo), r1 = rowOf(s.Hi);
    const double y0 = r0 >= 0 ? y[r0] : 0.0, y1 = r1 >= 0 ? y[r1] : 0.0;
    offset[k] = std::max(-limit, std::min(limit, s.Sensitivity / s.Area * (y0 - y1)));
  }
  return offset;
}
