#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>

#include "spira/mesh/big_vector.h"

namespace spira {

// Items split into buckets. Bucket q holds entries[start[q] .. start[q + 1]), in the order their
// source items came.
template <class Entry>
struct Partitioned {
  BigArray<Entry> entries;  // every slot is written once
  std::vector<std::int64_t> start;
  size_t bucketCount() const { return start.size() - 1; }
  Entry* begin(size_t q) const { return entries.get() + start[q]; }
  Entry* end(size_t q) const { return entries.get() + start[q + 1]; }
};

// A power of two near n / perBucket (at least 1, at most 1 << 16): buckets of about perBucket
// entries, small enough for per-bucket work to stay in cache.
inline size_t bucketCountFor(size_t n, size_t perBucket)
{
  size_t p = 1;
  while (p < (1u << 16) && p * perBucket < n) p <<= 1;
  return p;
}

// Picks a bucket from the top bits of a well-mixed 64-bit hash; `count` must be a power of two.
struct HashBuckets {
  explicit HashBuckets(size_t buckets) : count(buckets)
  {
    while ((size_t{1} << bits) < count) ++bits;
  }
  size_t operator()(std::uint64_t hash) const
  {
    return bits == 0 ? 0 : static_cast<size_t>(hash >> (64 - bits));
  }
  size_t count;
  int bits = 0;
};

// Radix partition in parallel: `emit(i, sink)` calls `sink(bucket, entry)` for every entry source
// item i (0 <= i < n) yields, bucket < buckets. It runs twice per item (count, then fill), so it
// must yield the same entries both times.
template <class Entry, class Emit>
Partitioned<Entry> radixPartition(size_t n, size_t buckets, const Emit& emit)
{
  const size_t chunks = std::max<size_t>(1, std::min<size_t>(64, n / 16384));
  const size_t chunkSize = (n + chunks - 1) / chunks;

  // Chunk-major counters: each chunk's task writes only its own row (no false sharing).
  std::vector<std::int64_t> cursor(chunks * buckets, 0);
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    std::int64_t* row = cursor.data() + c * buckets;
    const size_t end = std::min(n, (c + 1) * chunkSize);
    for (size_t i = c * chunkSize; i < end; ++i) emit(i, [&](size_t bucket, const Entry&) { ++row[bucket]; });
  });
  Partitioned<Entry> out;
  out.start.resize(buckets + 1);
  std::int64_t sum = 0;
  for (size_t q = 0; q < buckets; ++q) {
    out.start[q] = sum;
    for (size_t c = 0; c < chunks; ++c) {
      const std::int64_t k = cursor[c * buckets + q];
      cursor[c * buckets + q] = sum;
      sum += k;
    }
  }
  out.start[buckets] = sum;
  out.entries = BigArray<Entry>(static_cast<size_t>(sum));
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    std::int64_t* row = cursor.data() + c * buckets;
    Entry* dst = out.entries.get();
    const size_t end = std::min(n, (c + 1) * chunkSize);
    for (size_t i = c * chunkSize; i < end; ++i)
      emit(i, [&](size_t bucket, const Entry& e) { dst[row[bucket]++] = e; });
  });
  return out;
}

}  // namespace spira
