#pragma once
// The operations the contact law's shared texts (dem/rolling_models.hpp) use beyond
// + - * / dot and cross, for the scalar law: a double is one lane, a comparison its mask.
// The AVX2 batch defines the same names for four lanes (dem/pair_batch_avx2.hpp).
#include <cmath>
#if defined(__AVX2__) && !defined(CENTREC_NO_SIMD)
#include <immintrin.h>
#endif

#include "dem/vec3.hpp"

namespace centrec::dem {

inline double sqrt_of(double a) { return std::sqrt(a); }
inline double abs_of(double a) { return std::fabs(a); }
inline bool greater(double a, double b) { return a > b; }  // false for NaN
inline double select(bool mask, double a, double b) { return mask ? a : b; }
inline Vec3 select(bool mask, Vec3 a, Vec3 b) { return mask ? a : b; }
inline double zero_like(double) { return 0.0; }
inline Vec3 zero_like(Vec3) { return Vec3{}; }

#if defined(__AVX2__) && !defined(CENTREC_NO_SIMD)
// Four lanes (__m256d; GCC and Clang apply + - * / lane-wise). Their 3-vector and its
// operations are pair_batch::V4 (dem/pair_batch_avx2.hpp).
inline __m256d sqrt_of(__m256d a) { return _mm256_sqrt_pd(a); }  // correctly rounded, as std::sqrt
inline __m256d abs_of(__m256d a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a); }
// a > b per lane: all ones where true, false for NaN as the scalar comparison.
inline __m256d greater(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
inline __m256d select(__m256d mask, __m256d a, __m256d b) { return _mm256_blendv_pd(b, a, mask); }
inline __m256d zero_like(__m256d) { return _mm256_setzero_pd(); }
#endif

}  // namespace centrec::dem
