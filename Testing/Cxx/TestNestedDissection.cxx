// amNestedDissection: METIS's nested dissection with its two halves ordered at once.
#include "amLatticeMatrix.h"
#include "amNestedDissection.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{
/// The lattice matrix's graph: every coupling both ways, no diagonal.
void Graph(const amSparseMatrix& A, std::vector<int>& start, std::vector<int>& adjacent)
{
  start.assign(1, 0);
  adjacent.clear();
  for (vtkIdType r = 0; r < A.Size(); ++r)
  {
    for (vtkIdType k = A.RowStart[r]; k < A.RowStart[r + 1]; ++k)
      if (A.Columns[k] != r)
        adjacent.push_back(static_cast<int>(A.Columns[k]));
    start.push_back(static_cast<int>(adjacent.size()));
  }
}
}

TEST(NestedDissection, OrdersEveryNodeOnceTheSameInAChildOrHere)
{
  const amTest::LatticeMatrix lattice(24);
  std::vector<int> start, adjacent;
  Graph(lattice.A, start, adjacent);
  const size_t n = start.size() - 1;
  std::vector<long long> forked, here, again;
  std::string why;
  ASSERT_TRUE(amNestedDissection::Order(start, adjacent, forked, why)) << why;
  ASSERT_TRUE(amNestedDissection::Order(start, adjacent, here, why, false)) << why;
  ASSERT_TRUE(amNestedDissection::Order(start, adjacent, again, why)) << why;
  ASSERT_EQ(forked.size(), n);
  EXPECT_EQ(forked, here);
  EXPECT_EQ(forked, again);
  std::vector<int> position(n, -1);
  for (size_t k = 0; k < n; ++k)
  {
    ASSERT_GE(forked[k], 0);
    ASSERT_LT(forked[k], static_cast<long long>(n));
    EXPECT_EQ(position[forked[k]], -1) << "node " << forked[k] << " ordered twice";
    position[forked[k]] = static_cast<int>(k);
  }
  // A dissection: some first s nodes of the order (all but a few, the separator ordered last)
  // fall apart into two big halves, the first node's and the s-th's. The nodes go into a
  // union-find in their order.
  std::vector<size_t> parent(n), size(n, 1);
  std::vector<char> in(n, 0);
  auto find = [&parent](size_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  bool dissected = false;
  for (size_t s = 1; s <= n && !dissected; ++s)
  {
    const size_t v = static_cast<size_t>(forked[s - 1]);
    parent[v] = v;
    in[v] = 1;
    for (int k = start[v]; k < start[v + 1]; ++k)
      if (in[adjacent[k]])
      {
        const size_t a = find(v), b = find(static_cast<size_t>(adjacent[k]));
        if (a != b)
        {
          parent[b] = a;
          size[a] += size[b];
        }
      }
    const size_t first = find(static_cast<size_t>(forked[0])), last = find(v);
    dissected = first != last && size[first] > n / 3 && size[last] > n / 3 && n - s < n / 10;
  }
  EXPECT_TRUE(dissected) << "no two big halves apart before a small separator";
}

TEST(NestedDissection, EmptyGraph)
{
  std::vector<long long> order;
  std::string why;
  EXPECT_TRUE(amNestedDissection::Order({ 0 }, {}, order, why));
  EXPECT_TRUE(order.empty());
}
