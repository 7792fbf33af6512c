/**
 * @file    amTwelveLeads.h
 * @brief   The standard 12 leads from the potentials of the nine electrodes RA, LA, LL, V1..V6:
 *          Einthoven's I, II, III, Goldberger's augmented aVR, aVL, aVF, and the precordial
 *          V1..V6 against Wilson's central terminal (the mean of RA, LA and LL).
 */
#ifndef amTwelveLeads_h
#define amTwelveLeads_h

#include <array>
#include <string>
#include <vector>

namespace amTwelveLeads
{
/// The electrodes' names in the order the leads take them.
const std::vector<std::string>& ElectrodeNames();
/// The leads' names: I, II, III, aVR, aVL, aVF, V1..V6.
const std::vector<std::string>& LeadNames();
/// The 12 leads of the nine electrodes' potentials (RA, LA, LL, V1..V6).
std::array<double, 12> Leads(const double electrodes[9]);
}

#endif
