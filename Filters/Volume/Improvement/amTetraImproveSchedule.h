/**
 * @file    amTetraImproveSchedule.h
 * @brief   The sliver phase's schedule (not wrapped): in which order each attempt's operations go,
 *          which budget each attempt gets, and the margins the operations work to.
 *
 * Where the flips and moves leave slivers and the surface may move by MaximumSurfaceDeviation
 * (Options, amTetraImproveOptions.h), FreeSlivers (amTetraImproveSlivers.cxx) makes attempts from
 * the same mesh. Each attempt runs rounds with a budget (mm): the slivers' surface vertices slide
 * by at most SlideShare of it, towards an objective GoalMargin above the bar; slivers still bad
 * change region and have a surface edge split; then the flips and moves run again. The operations
 * bound their own displacement, but several acting on one place may together exceed the budget, so
 * the deviation is measured after each attempt and the next budget follows from it:
 * - the first attempt of an order gets the whole bound;
 * - while no attempt has stayed within the bound, the next budget is the last scaled by
 *   ShrinkPast * bound / deviation (a little under what would have just fitted);
 * - once one has stayed within and one has gone past, the next is half-way between the largest
 *   within and the smallest past (bisection);
 * - while every attempt has stayed within, the next grows towards the bound (GrowWithin * bound /
 *   deviation times the last), at most doubling the largest within.
 * BudgetsPerOrder attempts are made per order (First), the orders in turn: surface slides first,
 * then region changes first (a fin's element removed while its whole budget is left), then a short
 * surface edge of each sliver collapsed first (a junction curve that zigzags). The first attempt
 * that frees every sliver within the bound ends the phase; otherwise the one within the bound with
 * the fewest slivers (the first of equals) is kept, and none within it leaves the mesh as it was.
 * Which slivers an attempt frees depends on its budget in no simple way: hence several budgets.
 */
#ifndef amTetraImproveSchedule_h
#define amTetraImproveSchedule_h

namespace amTetraImprove
{
/// What an attempt does first in each round.
enum class First
{
  Slide,    // surface vertex slides
  Relabel,  // region changes
  Collapse, // surface edge collapses
};

class SliverSchedule
{
public:
  static constexpr int BudgetsPerOrder = 4;
  static constexpr int Orders = 3; // First::Slide, First::Relabel, First::Collapse
  static constexpr double SlideShare = 0.75;
  static constexpr double GoalMargin = 1.05; // the bar is on Q and angles, the goal on the objective
  static constexpr double ShrinkPast = 0.9;
  static constexpr double GrowWithin = 0.98;

  /// bound: the surface's largest allowed deviation (mm).
  explicit SliverSchedule(double bound);

  int Attempts() const { return Orders * BudgetsPerOrder; }
  /// The order and budget (mm) of attempt 'attempt' (0, 1, ...), once the previous ones have been
  /// recorded.
  First Order(int attempt) const { return static_cast<First>(attempt / BudgetsPerOrder); }
  double Budget() const { return this->Current; }
  /// Records the deviation the current attempt ended with (mm) and sets the next budget.
  void Record(int attempt, double deviation);

private:
  double Bound, Current, Within = 0, Past;
};
}

#endif
