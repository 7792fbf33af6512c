#include "amTwelveLeads.h"

const std::vector<std::string>& amTwelveLeads::ElectrodeNames()
{
  static const std::vector<std::string> names{ "RA", "LA", "LL", "V1", "V2", "V3", "V4", "V5", "V6" };
  return names;
}

const std::vector<std::string>& amTwelveLeads::LeadNames()
{
  static const std::vector<std::string> names{ "I", "II", "III", "aVR", "aVL", "aVF", "V1", "V2", "V3", "V4", "V5",
    "V6" };
  return names;
}

std::array<double, 12> amTwelveLeads::Leads(const double e[9])
{
  const double ra = e[0], la = e[1], ll = e[2], wct = (ra + la + ll) / 3.0;
  return { la - ra, ll - ra, ll - la, ra - 0.5 * (la + ll), la - 0.5 * (ra + ll), ll - 0.5 * (ra + la), e[3] - wct,
    e[4] - wct, e[5] - wct, e[6] - wct, e[7] - wct, e[8] - wct };
}
