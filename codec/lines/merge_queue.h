// Step 4 of linemap's extractor: the merge's priority queue of candidate
// merges, cheapest first (see MergeGroups).
#ifndef LINEMAP_CODEC_LINES_MERGE_QUEUE_H_
#define LINEMAP_CODEC_LINES_MERGE_QUEUE_H_

#include <algorithm>
#include <cstdint>
#include <vector>

namespace linemap::lines_internal {

// A merge candidate: groups a and b under `added`, a lower bound of its
// charged cost or the exact one; live while b's version is `version_b` (a's
// candidates are dropped whenever a changes).
struct Candidate {
  double added;
  std::uint32_t a, b;
  std::uint32_t version_b;
};

// Candidates ordered by (added, a, b), a total order, so that the merges
// made do not depend on how the queue stores ties. Two levels: each group
// keeps the candidates it queued in a short list, and a binary heap of
// groups is keyed by each list's cheapest entry. A merge drops its groups'
// lists in O(1) instead of leaving them stale in one large heap; stale
// entries of the other lists are dropped when they reach their list's top.
class MergeQueue {
 public:
  // `version`: per group, bumped whenever the group changes or dies.
  explicit MergeQueue(const std::vector<std::uint32_t>* version)
      : version_(version),
        lists_(version->size()),
        best_(version->size(), 0),
        position_(version->size(), kAbsent) {
    arena_.reserve(16 * version->size());  // room for 16 candidates per group
  }

  // Queues c; until Build() only into c.a's list.
  void Push(const Candidate& c) {
    List& list = lists_[c.a];
    if (list.size == list.capacity) Grow(&list);
    Entry* entries = &arena_[list.begin];
    entries[list.size++] = {c.added, c.b, c.version_b};
    if (!built_) return;
    if (list.size == 1 || Less(entries[list.size - 1], entries[best_[c.a]])) {
      best_[c.a] = list.size - 1;
      if (position_[c.a] == kAbsent) {
        position_[c.a] = static_cast<std::int32_t>(heap_.size());
        heap_.push_back({c.added, c.a});
      }
      heap_[position_[c.a]].key = c.added;
      SiftUp(static_cast<std::size_t>(position_[c.a]));
    }
  }

  // Heapifies the groups queued so far.
  void Build() {
    for (std::uint32_t g = 0; g < lists_.size(); ++g) {
      if (!FindBest(g)) continue;
      position_[g] = static_cast<std::int32_t>(heap_.size());
      heap_.push_back({Best(g).added, g});
    }
    for (std::size_t i = heap_.size() / 2; i-- > 0;) SiftDown(i);
    built_ = true;
  }

  // The cheapest live candidate, dropping stale ones; false when none is
  // left.
  bool Top(Candidate* top) {
    while (!heap_.empty()) {
      const std::uint32_t g = heap_[0].group;
      const Entry& e = Best(g);
      if (Live(e)) {
        *top = {e.added, g, e.b, e.version_b};
        return true;
      }
      RemoveBest(g);
    }
    return false;
  }

  // Removes the candidate Top() returned.
  void Pop() { RemoveBest(heap_[0].group); }

  // Drops every candidate queued by g.
  void Clear(std::uint32_t g) {
    lists_[g].size = 0;  // keeps its room in the arena
    if (position_[g] != kAbsent) Erase(g);
  }

 private:
  struct Entry {
    double added;
    std::uint32_t b;
    std::uint32_t version_b;
  };
  // A group in the heap under its cheapest entry's `added` (kept here so
  // that sifting reads only the heap).
  struct HeapEntry {
    double key;
    std::uint32_t group;
  };
  // A group's candidates: arena_[begin, begin + size), with room for
  // `capacity` (one arena instead of a vector per group: fewer allocations).
  struct List {
    std::uint32_t begin = 0, size = 0, capacity = 0;
  };
  static constexpr std::int32_t kAbsent = -1;

  // Moves a full list to the arena's end with twice the room.
  void Grow(List* list) {
    const std::uint32_t capacity = std::max<std::uint32_t>(8, 2 * list->capacity);
    const std::uint32_t begin = static_cast<std::uint32_t>(arena_.size());
    arena_.resize(arena_.size() + capacity);
    std::copy_n(arena_.begin() + list->begin, list->size, arena_.begin() + begin);
    list->begin = begin;
    list->capacity = capacity;
  }
  const Entry& Best(std::uint32_t g) const { return arena_[lists_[g].begin + best_[g]]; }

  bool Live(const Entry& e) const { return (*version_)[e.b] == e.version_b; }
  static bool Less(const Entry& x, const Entry& y) {
    return x.added < y.added || (x.added == y.added && x.b < y.b);
  }
  // Heap order: by the best entry, then (a, b).
  static bool Before(const HeapEntry& x, const HeapEntry& y) {
    // Branch-free: sifting compares are data dependent.
    return (x.key < y.key) | ((x.key == y.key) & (x.group < y.group));
  }
  // Drops g's stale entries and finds its cheapest; false when none is left.
  bool FindBest(std::uint32_t g) {
    List& list = lists_[g];
    Entry* entries = &arena_[list.begin];
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < list.size; ++i) {
      const Entry e = entries[i];
      if (!Live(e)) continue;
      if (kept == 0 || Less(e, entries[best_[g]])) best_[g] = kept;
      entries[kept++] = e;
    }
    list.size = kept;
    return kept > 0;
  }
  // Swap-removes the best entry of g (the heap's top) and repositions g.
  void RemoveBest(std::uint32_t g) {
    List& list = lists_[g];
    arena_[list.begin + best_[g]] = arena_[list.begin + list.size - 1];
    --list.size;
    if (!FindBest(g)) {
      Erase(g);
      return;
    }
    const std::size_t i = static_cast<std::size_t>(position_[g]);
    heap_[i].key = Best(g).added;
    SiftDown(i);  // its key only grew
  }
  void Erase(std::uint32_t g) {
    const std::size_t i = static_cast<std::size_t>(position_[g]);
    position_[g] = kAbsent;
    const HeapEntry last = heap_.back();
    heap_.pop_back();
    if (i == heap_.size()) return;
    Place(i, last);
    SiftDown(i);
    SiftUp(static_cast<std::size_t>(position_[last.group]));
  }
  void Place(std::size_t i, const HeapEntry& entry) {
    heap_[i] = entry;
    position_[entry.group] = static_cast<std::int32_t>(i);
  }
  void SiftUp(std::size_t i) {
    const HeapEntry entry = heap_[i];
    while (i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if (!Before(entry, heap_[parent])) break;
      Place(i, heap_[parent]);
      i = parent;
    }
    Place(i, entry);
  }
  void SiftDown(std::size_t i) {
    const HeapEntry entry = heap_[i];
    for (;;) {
      std::size_t child = 2 * i + 1;
      if (child >= heap_.size()) break;
      if (child + 1 < heap_.size() && Before(heap_[child + 1], heap_[child])) ++child;
      if (!Before(heap_[child], entry)) break;
      Place(i, heap_[child]);
      i = child;
    }
    Place(i, entry);
  }

  const std::vector<std::uint32_t>* version_;
  std::vector<List> lists_;  // per group: the candidates it queued
  std::vector<Entry> arena_;
  std::vector<std::uint32_t> best_;     // per group: index of its cheapest entry
  std::vector<std::int32_t> position_;  // per group: index in heap_, or kAbsent
  std::vector<HeapEntry> heap_;         // groups with candidates
  bool built_ = false;
};

}  // namespace linemap::lines_internal

#endif  // LINEMAP_CODEC_LINES_MERGE_QUEUE_H_
