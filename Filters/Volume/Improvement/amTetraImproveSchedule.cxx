#include "amTetraImproveSchedule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amTetraImprove
{
SliverSchedule::SliverSchedule(double bound)
  : Bound(bound)
  , Current(bound)
  , Past(std::numeric_limits<double>::infinity())
{
}

void SliverSchedule::Record(int attempt, double deviation)
{
  const double budget = this->Current;
  if (deviation <= this->Bound)
    this->Within = std::max(this->Within, budget);
  else
    this->Past = std::min(this->Past, budget);
  if ((attempt + 1) % BudgetsPerOrder == 0)
  {
    // The search again, with the next order.
    this->Current = this->Bound;
    this->Within = 0;
    this->Past = std::numeric_limits<double>::infinity();
    return;
  }
  if (this->Within == 0)
    this->Current = budget * (ShrinkPast * this->Bound / deviation);
  else if (std::isfinite(this->Past))
    this->Current = 0.5 * (this->Within + this->Past);
  else
    this->Current =
      std::min(2 * this->Within, budget * GrowWithin * this->Bound / std::max(deviation, 1e-9 * this->Bound));
}
}
