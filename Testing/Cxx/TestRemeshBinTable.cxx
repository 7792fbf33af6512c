// The remesher's bin table against a node map, on keys as the bins make them (including the far
// corners of their range, and negative ones), through growth and Clear.
#include "amRemeshBinTable.h"
#include "amRemeshBins.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

TEST(RemeshBinTable, AgreesWithAMapThroughGrowthAndClear)
{
  amRemesh::BinTable table;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> index(-(1 << 20), (1 << 20) - 1);
  for (int round = 0; round < 3; ++round)
  {
    std::map<long long, std::vector<int>> reference;
    std::vector<long long> keys = { amRemesh::Bins::Key(-(1 << 20), -(1 << 20), -(1 << 20)),
      amRemesh::Bins::Key((1 << 20) - 1, (1 << 20) - 1, (1 << 20) - 1), -1, 0 };
    for (int i = 0; i < 5000 * (round + 1); ++i)
      keys.push_back(amRemesh::Bins::Key(index(rng) % 64, index(rng) % 64, index(rng)));
    for (size_t i = 0; i < 4 * keys.size(); ++i)
    {
      const long long key = keys[rng() % keys.size()];
      table[key].push_back(static_cast<int>(i));
      reference[key].push_back(static_cast<int>(i));
    }
    for (const auto& kv : reference)
    {
      const std::vector<int>* list = table.Find(kv.first);
      ASSERT_NE(list, nullptr) << "key " << kv.first;
      EXPECT_EQ(*list, kv.second);
    }
    EXPECT_EQ(table.Find(amRemesh::Bins::Key(70, 70, 70)), nullptr);
    EXPECT_EQ(table.Size(), reference.size());
    size_t visited = 0;
    table.ForEach([&](long long key, const std::vector<int>& list) {
      ++visited;
      EXPECT_EQ(list, reference[key]);
    });
    EXPECT_EQ(visited, reference.size());
    table.Clear();
    for (const auto& kv : reference)
      EXPECT_EQ(table.Find(kv.first), nullptr);
    EXPECT_EQ(table.Size(), 0u);
    // A bin made after Clear starts empty, whatever storage its slot kept.
    EXPECT_TRUE(table[keys[0]].empty());
    table.Clear();
  }
}
