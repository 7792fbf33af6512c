/**
 * @class   amECGFeatures
 * @brief   What a cardiologist reads off a 12-lead ECG: the QRS complex's onset and duration, the
 *          QT interval, and per lead the R and S amplitudes and the T wave's amplitude and polarity.
 *
 * On simulated leads that are exactly zero before the first activation and after the last
 * repolarisation:
 * - QRS onset: the first time the spatial magnitude sqrt(sum of the leads squared) exceeds 1 % of
 *   its maximum;
 * - QRS end (the J point): the first time after the spatial velocity's peak (sum over leads of
 *   |dV/dt|) from which it stays below 5 % of that peak for 20 ms;
 * - T end: the last time the spatial magnitude exceeds 1 % of its maximum after the QRS end; QT
 *   is T end less QRS onset;
 * - per lead, within the QRS: R the largest positive value, S the most negative; after it, T the
 *   value of largest magnitude, "upright" when positive, "inverted" when negative, "flat" when
 *   under 0.05 mV.
 */
#ifndef amECGFeatures_h
#define amECGFeatures_h

#include <string>
#include <vector>

class amECGFeatures
{
public:
  struct Lead
  {
    std::string Name;
    double R = 0, S = 0, T = 0; // mV
    std::string TPolarity;
  };

  /// times (ms, increasing) and each lead's values at them. False with Error when the leads are
  /// all zero or too short to read.
  bool Measure(const std::vector<double>& times, const std::vector<std::string>& names,
    const std::vector<std::vector<double>>& leads);

  double QRSOnset = 0, QRSEnd = 0, QRSDuration = 0, TEnd = 0, QTInterval = 0; // ms
  std::vector<Lead> Leads;
  std::string Error;
};

#endif
