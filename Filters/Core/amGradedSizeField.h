/**
 * @class   amGradedSizeField
 * @brief   A mesh-size field h(x) grown from sizes given at surface points with a bounded
 *          gradation: h(x) = min(MaximumSize, min_i (h_i + (beta - 1) |x - p_i|)).
 *
 * The field lives on a Cartesian grid over the given bounds (spacing chosen so the grid has at
 * most a given number of nodes): nodes near each point p_i start from h_i + (beta - 1) |x - p_i|,
 * then two raster sweeps with the 26-neighbour chamfer propagate h_j <= h_k + (beta - 1) |x_j - x_k|
 * through the grid. Evaluate() interpolates trilinearly (a size never below the smallest h_i it
 * came from, never above MaximumSize). Sizes between neighbouring points therefore change by at
 * most a factor of about beta per unit of size, which is the "gradation" of the meshing
 * literature (1.3 is the usual default). Thread-safe queries; deterministic.
 */
#ifndef amGradedSizeField_h
#define amGradedSizeField_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <array>
#include <string>
#include <vector>

class ANATOMESHFILTERSCORE_EXPORT amGradedSizeField
{
public:
  /// Build from sizes at points (sizes must be finite and > 0; returns false with 'why').
  /// gradation >= 1; maximumSize <= 0 means unbounded. bounds: xmin xmax ymin ymax zmin zmax.
  bool Build(const std::vector<std::array<double, 3>>& points, const std::vector<double>& sizes, double gradation,
    double maximumSize, const double bounds[6], std::string& why, long long maximumNodes = 8000000);

  /// The size at x (outside the grid: the value at the nearest grid point).
  double Evaluate(const double x[3]) const;

  double GetSpacing() const { return this->H; }
  double GetMinimum() const { return this->Minimum; }

private:
  double Origin[3] = { 0, 0, 0 };
  double H = 1.0;
  int N[3] = { 0, 0, 0 };
  double Maximum = 0.0, Minimum = 0.0;
  std::vector<float> Values;
};

#endif
