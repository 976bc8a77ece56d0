#pragma once
// Allocator for the engine's large arrays (private to particles/): blocks of
// 2 MiB or more are aligned to 2 MiB and offered to the kernel for transparent
// huge pages (madvise), so that the random accesses of the event loop at
// N ~ 10^6 do not also miss the TLB.
// Smaller blocks, or systems without madvise, get ordinary memory.
#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shockgas::particles {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t huge = std::size_t{2} << 20;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge) {
      void* p = ::operator new (bytes, std::align_val_t{alignof(T) > 64 ? alignof(T) : 64});
      return static_cast<T*>(p);
    }
    const std::size_t rounded = (bytes + huge - 1) / huge * huge;
    void* p = std::aligned_alloc(huge, rounded);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) < huge) {
      ::operator delete (p, std::align_val_t{alignof(T) > 64 ? alignof(T) : 64});
    } else {
      std::free(p);
    }
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }
};

}  // namespace shockgas::particles
