#include "amNestedDissection.h"

#include "amDescriptorIO.h"

#include <metis.h>

#include <cerrno>
#include <cstdio>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <sys/wait.h>
#include <unistd.h>

namespace
{
/// One side of the separator: its nodes and their graph, numbered from 0.
struct Half
{
  std::vector<idx_t> Nodes, Start, Adjacent, Order;
};

void Extract(const std::vector<int>& start, const std::vector<int>& adjacent, const std::vector<idx_t>& part,
  idx_t side, std::vector<idx_t>& local, Half& half)
{
  const idx_t n = static_cast<idx_t>(part.size());
  for (idx_t v = 0; v < n; ++v)
    if (part[v] == side)
    {
      local[v] = static_cast<idx_t>(half.Nodes.size());
      half.Nodes.push_back(v);
    }
  half.Start.assign(1, 0);
  for (idx_t v : half.Nodes)
  {
    for (int k = start[v]; k < start[v + 1]; ++k)
      if (part[adjacent[k]] == side)
        half.Adjacent.push_back(local[adjacent[k]]);
    half.Start.push_back(static_cast<idx_t>(half.Adjacent.size()));
  }
}

/// METIS's nested dissection of a whole graph (the order only: its inverse is dropped).
bool Dissect(std::vector<idx_t>& start, std::vector<idx_t>& adjacent, std::vector<idx_t>& order)
{
  idx_t n = static_cast<idx_t>(start.size()) - 1;
  order.resize(static_cast<size_t>(n));
  if (n == 0)
    return true;
  std::vector<idx_t> inverse(static_cast<size_t>(n));
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  return METIS_NodeND(&n, start.data(), adjacent.data(), nullptr, options, order.data(), inverse.data()) == METIS_OK;
}

/// Orders 'half' in a forked child; -1 when no child could be started.
pid_t StartChild(Half& half, int& readEnd)
{
  int fds[2];
  if (::pipe(fds) != 0)
    return -1;
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return -1;
  }
  if (pid == 0)
  {
    ::close(fds[0]);
#ifdef __GLIBC__
    // METIS's blocks would otherwise land in the parent's free pages and copy them on write
    // (see amTetGenRun.cxx).
    ::malloc_trim(0);
#endif
    const bool ok = Dissect(half.Start, half.Adjacent, half.Order) &&
      amDescriptorIO::WriteAll(fds[1], half.Order.data(), sizeof(idx_t) * half.Order.size());
    ::close(fds[1]);
    ::_exit(ok ? 0 : 1);
  }
  ::close(fds[1]);
  readEnd = fds[0];
  return pid;
}

/// The child's order of 'half', or false when it failed.
bool FinishChild(pid_t pid, int readEnd, Half& half)
{
  half.Order.resize(half.Nodes.size());
  const bool read = amDescriptorIO::ReadAll(readEnd, half.Order.data(), sizeof(idx_t) * half.Order.size());
  ::close(readEnd);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  return read && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}
}

namespace amNestedDissection
{
bool Order(const std::vector<int>& start, const std::vector<int>& adjacent, std::vector<long long>& order,
  std::string& why, bool inChild)
{
  idx_t n = static_cast<idx_t>(start.size()) - 1;
  order.clear();
  if (n <= 0)
    return true;
  std::vector<idx_t> xadj(start.begin(), start.end()), adjncy(adjacent.begin(), adjacent.end());
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  // Halves within 3 % of each other (METIS's default allows 20 %), so that the two processes
  // finish together.
  options[METIS_OPTION_UFACTOR] = 30;
  idx_t separatorSize = 0;
  std::vector<idx_t> part(static_cast<size_t>(n));
  if (METIS_ComputeVertexSeparator(&n, xadj.data(), adjncy.data(), nullptr, options, &separatorSize, part.data()) !=
    METIS_OK)
  {
    why = "METIS found no vertex separator of the matrix's graph";
    return false;
  }
  std::vector<idx_t> local(static_cast<size_t>(n), -1);
  Half halves[2];
  for (idx_t side = 0; side < 2; ++side)
    Extract(start, adjacent, part, side, local, halves[side]);
  xadj.clear();
  xadj.shrink_to_fit();
  adjncy.clear();
  adjncy.shrink_to_fit();

  int readEnd = -1;
  const pid_t child = inChild ? StartChild(halves[1], readEnd) : -1;
  bool ok = Dissect(halves[0].Start, halves[0].Adjacent, halves[0].Order);
  if (child < 0 || !FinishChild(child, readEnd, halves[1]))
    ok = ok && Dissect(halves[1].Start, halves[1].Adjacent, halves[1].Order);
  if (!ok)
  {
    why = "METIS could not order the matrix's graph";
    return false;
  }
  order.reserve(static_cast<size_t>(n));
  for (const Half& half : halves)
    for (idx_t k : half.Order)
      order.push_back(half.Nodes[k]);
  for (idx_t v = 0; v < n; ++v)
    if (part[v] == 2)
      order.push_back(v);
  // Every node once: the child's bytes are trusted only as a permutation.
  std::vector<char> seen(static_cast<size_t>(n), 0);
  bool permutation = order.size() == static_cast<size_t>(n);
  for (size_t k = 0; k < order.size() && permutation; ++k)
    permutation = order[k] >= 0 && order[k] < n && !seen[order[k]]++;
  if (!permutation)
  {
    why = "the nested dissection did not order every node of the matrix's graph once";
    order.clear();
  }
  return permutation;
}
}
