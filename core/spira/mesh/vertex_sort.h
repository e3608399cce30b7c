#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "spira/mesh/big_vector.h"

namespace spira {

// Items grouped by vertex: the items of vertex v are items[offset[v] .. offset[v + 1]), sorted by
// Item's operator<.
template <class Item>
struct VertexSorted {
  std::vector<int> offset;
  BigVector<Item> items;
};

// Groups the items `emit(i, sink)` yields (sink(vertex, item), any number per source item
// i < n) by vertex and sorts each group. `emit` runs twice per item (count, then fill), so it must
// yield the same items both times.
//
// A counting sort split into one chunk of source items per thread, each with its own row of
// counters, so both passes run in parallel and stay stable; then the small per-vertex groups are
// sorted in parallel (insertion sort: groups hold a handful of items on real meshes).
template <class Item, class Emit>
VertexSorted<Item> sortByVertex(size_t n, size_t vertexCount, const Emit& emit)
{
  const size_t threads =
      std::clamp<size_t>(static_cast<size_t>(tbb::this_task_arena::max_concurrency()), 1, 8);
  const size_t chunks = std::clamp<size_t>(n / 65536, 1, threads);
  const size_t chunkSize = (n + chunks - 1) / chunks;
  std::vector<std::vector<int>> rows(chunks);
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    std::vector<int>& row = rows[c];
    row.assign(vertexCount, 0);
    for (size_t i = c * chunkSize; i < std::min(n, (c + 1) * chunkSize); ++i)
      emit(i, [&](int vertex, const Item&) { ++row[vertex]; });
  });
  VertexSorted<Item> out;
  out.offset.resize(vertexCount + 1);
  int sum = 0;
  for (size_t v = 0; v < vertexCount; ++v) {
    out.offset[v] = sum;
    for (size_t c = 0; c < chunks; ++c) {
      const int k = rows[c][v];
      rows[c][v] = sum;
      sum += k;
    }
  }
  out.offset[vertexCount] = sum;
  out.items.resize(static_cast<size_t>(sum));
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    std::vector<int>& cursor = rows[c];
    for (size_t i = c * chunkSize; i < std::min(n, (c + 1) * chunkSize); ++i)
      emit(i, [&](int vertex, const Item& item) { out.items[cursor[vertex]++] = item; });
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertexCount, 4096),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t v = r.begin(); v != r.end(); ++v) {
                        Item* b = out.items.data() + out.offset[v];
                        Item* e = out.items.data() + out.offset[v + 1];
                        if (e - b < 2) continue;  // also when there are no items at all (data() null)
                        if (e - b > 24) {
                          std::sort(b, e);
                          continue;
                        }
                        for (Item* i = b + 1; i < e; ++i) {
                          const Item x = *i;
                          Item* j = i;
                          for (; j > b && x < *(j - 1); --j) *j = *(j - 1);
                          *j = x;
                        }
                      }
                    });
  return out;
}

}  // namespace spira
