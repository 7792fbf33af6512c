/**
 * @file    amRemeshBinTable.h
 * @brief   The remesher's bins of one zone: bin key -> the triangles in it, in an open-addressing
 *          table (linear probing, a power-of-two number of slots).
 *
 * Every crossing check looks up a few bins and every change of a triangle a few more, millions of
 * times a pass: a lookup here reads one slot (its key and its list side by side), where a node
 * map reads a bucket, then a node. Clear keeps each slot's list storage, so binning every
 * triangle anew (after each pass) fills lists that already have their room. Bins are never
 * erased one by one (a bin that empties stays, with an empty list), so no slot is ever vacated
 * but by Clear.
 */
#ifndef amRemeshBinTable_h
#define amRemeshBinTable_h

#include <cstddef>
#include <cstdint>
#include <vector>

namespace amRemesh
{
class BinTable
{
public:
  /// The triangles of bin 'key' (null: no such bin).
  const std::vector<int>* Find(long long key) const
  {
    if (this->Count == 0)
      return nullptr;
    for (std::size_t s = this->Slot(key);; s = (s + 1) & this->Mask)
    {
      const Entry& e = this->Slots[s];
      if (!e.Used)
        return nullptr;
      if (e.Key == key)
        return &e.List;
    }
  }
  std::vector<int>* Find(long long key)
  {
    return const_cast<std::vector<int>*>(static_cast<const BinTable*>(this)->Find(key));
  }
  /// The triangles of bin 'key', an empty list made for it when there is none.
  std::vector<int>& operator[](long long key)
  {
    if (2 * (this->Count + 1) > this->Slots.size())
      this->Grow();
    std::size_t s = this->Slot(key);
    for (; this->Slots[s].Used; s = (s + 1) & this->Mask)
      if (this->Slots[s].Key == key)
        return this->Slots[s].List;
    this->Slots[s].Used = true;
    this->Slots[s].Key = key;
    this->Slots[s].List.clear();
    ++this->Count;
    return this->Slots[s].List;
  }
  /// The number of bins.
  std::size_t Size() const { return this->Count; }
  /// Calls f(key, list) for every bin, in no particular order.
  template<typename F>
  void ForEach(F f) const
  {
    for (const Entry& e : this->Slots)
      if (e.Used)
        f(e.Key, e.List);
  }
  /// No bins; the lists' storage is kept for the bins made next.
  void Clear()
  {
    for (Entry& e : this->Slots)
      e.Used = false;
    this->Count = 0;
  }

private:
  struct Entry
  {
    long long Key = 0;
    std::vector<int> List;
    bool Used = false;
  };
  std::size_t Slot(long long key) const
  {
    // Fibonacci hashing: the high bits of the product, which every bit of the key reaches.
    return static_cast<std::size_t>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ULL) >> this->Shift);
  }
  void Grow()
  {
    const std::size_t n = this->Slots.empty() ? 1024 : 2 * this->Slots.size();
    std::vector<Entry> slots(n);
    int shift = 64;
    for (std::size_t m = n; m > 1; m >>= 1)
      --shift;
    this->Shift = shift;
    this->Mask = n - 1;
    for (Entry& e : this->Slots)
      if (e.Used)
      {
        std::size_t t = this->Slot(e.Key);
        while (slots[t].Used)
          t = (t + 1) & this->Mask;
        slots[t].Used = true;
        slots[t].Key = e.Key;
        slots[t].List.swap(e.List);
      }
    this->Slots.swap(slots);
  }

  std::vector<Entry> Slots;
  std::size_t Count = 0;
  std::size_t Mask = 0;
  int Shift = 64;
};
}

#endif
