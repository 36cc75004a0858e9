#pragma once
// Memory for the renderer's per-pixel buffers (an implementation detail of the renderer). A
// one-shot render first-touches tens of MB, and a 4 KiB page fault costs ~15 us on the development
// VM, more than the whole diffusion of a reused renderer. Large buffers are therefore 2 MiB-aligned
// and advised as transparent huge pages (one fault per 2 MiB; where THP is off, the advice is
// ignored), and PixelVector does not zero-fill what the renderer overwrites anyway.

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace vicc_glyphs::render_detail {

inline constexpr std::size_t kHugePage = std::size_t{2} << 20;

/// Advises the whole 2 MiB pages inside [data, data + bytes) as huge pages; call it before the
/// memory is first touched (e.g. right after reserving a vector).
inline void adviseHugePages(void* data, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (first < last) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

/// Allocator for per-pixel buffers: blocks of 1 MiB or more come 2 MiB-aligned, rounded up to
/// whole huge pages and advised as such; resize() default-initialises (no zero-fill for
/// trivial types), so callers must write every element they read.
template <class T>
struct PixelAllocator {
  using value_type = T;

  PixelAllocator() = default;
  template <class U>
  PixelAllocator(const PixelAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage / 2) return static_cast<T*>(::operator new(bytes));
    const std::size_t rounded = (bytes + kHugePage - 1) & ~(kHugePage - 1);
    void* data = std::aligned_alloc(kHugePage, rounded);
    if (!data) throw std::bad_alloc();
    madvise(data, rounded, MADV_HUGEPAGE);
    return static_cast<T*>(data);
  }

  void deallocate(T* data, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePage / 2) {
      ::operator delete(data);
    } else {
      std::free(data);
    }
  }

  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialisation: no zero-fill
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  /// Nothing to do: pixel buffers hold trivially destructible values. Without it the vector's
  /// element-wise destruction compiled (GCC 12, -O3) to a memset of the whole buffer, 4 MB per
  /// field of a 512 px solve when a renderer is destroyed.
  template <class U>
  void destroy(U*) noexcept {
    static_assert(std::is_trivially_destructible_v<U>, "PixelAllocator: trivial types only");
  }

  template <class U>
  bool operator==(const PixelAllocator<U>&) const noexcept {
    return true;
  }
  template <class U>
  bool operator!=(const PixelAllocator<U>&) const noexcept {
    return false;
  }
};

template <class T>
using PixelVector = std::vector<T, PixelAllocator<T>>;

/// Gives an ordinary std::vector (a public type) room for `n` elements with huge-page advice
/// before its first fill; keeps its storage when it already has the room.
template <class T>
void reserveWithHugePages(std::vector<T>& vector, std::size_t n) {
  if (vector.capacity() >= n) return;
  vector.clear();  // nothing to copy over: the caller refills it
  const std::size_t bytes = n * sizeof(T);
  if (bytes < kHugePage / 2) {
    vector.reserve(n);
    return;
  }
  // std::allocator's block is not 2 MiB-aligned: 2 MiB of spare (never touched) capacity
  // lets whole huge pages cover everything from the first 2 MiB boundary to the end.
  const std::size_t spare = kHugePage / sizeof(T);
  vector.reserve(n + spare);
  adviseHugePages(vector.data(), bytes + kHugePage);
}

}  // namespace vicc_glyphs::render_detail
