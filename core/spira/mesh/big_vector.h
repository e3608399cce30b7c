#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace spira {

// Allocator for the large arrays of mesh algorithms (millions of entries, allocated and dropped
// on every call). Blocks of 4 MiB and more are 2 MiB-aligned and marked for transparent huge
// pages on Linux: filling a fresh 50 MB array otherwise costs some 12,000 page faults, which on
// virtual machines took as long as the algorithm itself. Smaller blocks use the default allocator.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr size_t kHugeFrom = size_t{4} << 20;
  static constexpr size_t kAlign = size_t{2} << 20;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept
  {
  }

  T* allocate(size_t n)
  {
    const size_t bytes = n * sizeof(T);
    if (bytes < kHugeFrom) return std::allocator<T>().allocate(n);
    const size_t rounded = (bytes + kAlign - 1) / kAlign * kAlign;
    void* p = std::aligned_alloc(kAlign, rounded);
    if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: without THP support it changes nothing
#endif
    return static_cast<T*>(p);
  }

  void deallocate(T* p, size_t n) noexcept
  {
    if (n * sizeof(T) < kHugeFrom)
      std::allocator<T>().deallocate(p, n);
    else
      std::free(p);
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept
  {
    return true;
  }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept
  {
    return false;
  }
};

template <class T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

// A big array whose elements are written before they are read: no value-initialisation pass.
// T must be trivially default-constructible.
template <class T>
class BigArray {
  static_assert(std::is_trivially_default_constructible_v<T>, "BigArray leaves its elements uninitialised");

 public:
  BigArray() = default;
  explicit BigArray(size_t n) : data_(n ? HugePageAllocator<T>().allocate(n) : nullptr, Deleter{n}), size_(n)
  {
  }
  T* get() const { return data_.get(); }
  T& operator[](size_t i) const { return data_[i]; }
  size_t size() const { return size_; }

 private:
  struct Deleter {
    size_t n = 0;
    void operator()(T* p) const noexcept { HugePageAllocator<T>().deallocate(p, n); }
  };
  std::unique_ptr<T[], Deleter> data_;
  size_t size_ = 0;
};

}  // namespace spira
