/**
 * @file    amNestedDissection.h
 * @brief   A fill-reducing ordering of a large sparse symmetric matrix: METIS's nested dissection,
 *          its two halves ordered at once.
 *
 * METIS orders on one core, and on the torso's matrix its ordering is most of the Cholesky
 * factor's set-up. A nested dissection's first step, a vertex separator, splits the graph into two
 * halves that the rest of the dissection orders independently: the separator is found first, then
 * one half is ordered in a forked child process while this process orders the other. METIS draws
 * from the C library's single random sequence, which two threads would share in an order that
 * changes from run to run; a child process has its own, so each half's ordering is METIS's own for
 * that half on any machine. The halves come first, the separator last. When the child cannot be
 * started or fails, this process orders that half too: the same ordering, later.
 */
#ifndef amNestedDissection_h
#define amNestedDissection_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <string>
#include <vector>

namespace amNestedDissection
{
/// The graph of n nodes (node i's neighbours: adjacent[start[i]] .. adjacent[start[i + 1] - 1],
/// both directions of every edge, no self-loop) into 'order' (order[k]: the node eliminated
/// k-th). False, with 'why', when METIS fails. inChild false orders both halves in this process
/// (the same order).
ANATOMESHFILTERSCORE_EXPORT bool Order(const std::vector<int>& start, const std::vector<int>& adjacent,
  std::vector<long long>& order, std::string& why, bool inChild = true);
}

#endif
