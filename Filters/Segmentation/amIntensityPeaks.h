/**
 * @file    amIntensityPeaks.h
 * @brief   The intensity populations of a region (the peaks of its smoothed histogram), and the
 *          nearest one below and above a seed's intensity: the snake's interval stops half-way to
 *          them, so an organ is never grown into a neighbour whose intensity is within its default
 *          window (an enhanced wall beside a late-phase blood pool).
 */
#ifndef amIntensityPeaks_h
#define amIntensityPeaks_h

#include <vector>

struct amIntensityPeaks
{
  /// The peaks' centres (input units) in increasing order: local maxima of the histogram (512 bins
  /// over the values' range, smoothed over two bins) holding at least minimumShare of the values
  /// between their neighbouring minima.
  std::vector<double> Centres;
  /// Each peak's basin: the values between the histogram's minima on either side of it.
  std::vector<double> BasinLow, BasinHigh;

  static amIntensityPeaks Find(const std::vector<float>& values, double minimumShare = 0.02);

  /// The nearest peak below mean - ownReach whose basin does not hold mean (that peak is the seed's
  /// own population), false when there is none; likewise above.
  bool Below(double mean, double ownReach, double& peak) const;
  bool Above(double mean, double ownReach, double& peak) const;
};

#endif
