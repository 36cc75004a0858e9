#pragma once
// Four floats at once with the GCC/Clang vector extensions: SSE on x86-64, NEON on ARM, plain
// code elsewhere. For the per-pixel loops that dominate a frame (ICP sums, model splatting).

#include <cmath>
#include <cstring>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace vicc_tracking::simd {

using Float4 = float __attribute__((vector_size(16)));
using Mask4 = int __attribute__((vector_size(16)));  ///< comparison result: -1 true, 0 false

/// Unaligned load and store (memcpy compiles to one move).
inline Float4 load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof(v));
  return v;
}
inline void store4(float* p, Float4 v) { std::memcpy(p, &v, sizeof(v)); }
inline Mask4 load4(const int* p) {
  Mask4 v;
  std::memcpy(&v, p, sizeof(v));
  return v;
}

/// Bit i set where lane i of the comparison result is true.
inline unsigned bits4(Mask4 m) {
#if defined(__SSE__)
  return static_cast<unsigned>(_mm_movemask_ps((__m128)m));
#else
  return (m[0] & 1u) | (m[1] & 2u) | (m[2] & 4u) | (m[3] & 8u);
#endif
}

inline float sum4(Float4 v) { return (v[0] + v[1]) + (v[2] + v[3]); }

inline Float4 sqrt4(Float4 v) {
#if defined(__SSE__)
  return (Float4)_mm_sqrt_ps((__m128)v);
#else
  return Float4{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}

inline Float4 abs4(Float4 v) { return v < 0.f ? -v : v; }

}  // namespace vicc_tracking::simd
