/**
 * @class   amPolarContour
 * @brief   A star-shaped snake in one slice, found as the global minimum of its energy by dynamic
 *          programming (private helper of amSnakeSegmentation, plain C++).
 *
 * The contour is r(theta) around a centre: NumberOfRays rays (5 degrees apart), radii sampled every
 * 0.5 mm up to MaximumRadius. Its energy is a sum over rays of
 *   4/mm x length inside the contour darker than OutsideThreshold (fat, lung: not the structure)
 *   + 2/mm x length within 3 mm outside the contour not darker than it (the structure goes on)
 *   - EdgeWeight x min(3, outward intensity drop over 3 mm / EdgeContrast) (a boundary edge)
 *   + AreaCost/mm x radius (no growth without evidence: keeps the snake out of touching tissue
 *     of the structure's intensity)
 *   + PriorWeight/mm x |r - r_previous| (the previous slice's contour, when propagating),
 * plus 2/mm x |r(theta) - r(theta')| between neighbouring rays (smoothness; at most 1 mm or the arc
 * between the rays apart, whichever is more).
 * Radii are at least MinimumRadius and, when propagating, at most r_previous + MaximumGrowth.
 * The closed contour is the middle turn of the optimal path over three turns (the usual way to
 * close a circular dynamic program); the result is deterministic.
 *
 * Why: an intensity interval cannot tell a vessel's weakly enhanced part (the false lumen of a
 * dissection, thrombus, the wall) from the soft tissue it touches; a star-shaped contour bounded
 * by fat where fat is, by edges elsewhere, and continuous from slice to slice can (Amini et al.,
 * "Using dynamic programming for solving variational problems in vision", 1990, for the method).
 */
#ifndef amPolarContour_h
#define amPolarContour_h

#include <vector>

class amPolarContour
{
public:
  struct Parameters
  {
    double OutsideThreshold = -30.0; // intensity below which a pixel is not the structure
    double EdgeContrast = 40.0;      // an outward drop of this much is one unit of edge evidence
    double EdgeWeight = 3.0;
    double AreaCost = 0.4;    // per mm of radius
    double PriorWeight = 0.6; // per mm of change against the previous slice
    double MinimumRadius = 2.0;
    double MaximumRadius = 30.0;
    double MaximumGrowth = 2.0; // mm per slice
  };

  /// The slice: nu x nv pixels (u fastest), spacing su, sv mm.
  amPolarContour(const float* image, int nu, int nv, double su, double sv);

  static constexpr int NumberOfRays = 72;
  static constexpr double RadialStep = 0.5; // mm

  /// Contour around (cu, cv) (pixel coordinates); 'previous' (NumberOfRays radii, mm, or empty)
  /// is the last slice's contour seen from this centre. Returns the radii, mm.
  std::vector<double> Find(double cu, double cv, const std::vector<double>& previous, const Parameters& p) const;

  /// Radii, seen from (cu, cv), of a mask's boundary: the farthest mask pixel along each ray.
  std::vector<double> RadiiOf(const unsigned char* mask, double cu, double cv, double maximumRadius) const;

  /// Rasterise: pixels whose centre lies inside the contour are set to 1 (others untouched).
  void Fill(double cu, double cv, const std::vector<double>& radii, unsigned char* mask) const;

private:
  double Sample(double u, double v) const;
  const float* Image;
  int Nu, Nv;
  double Su, Sv;
};

#endif
