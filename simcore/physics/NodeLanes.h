#pragma once
/// \file
/// Reading nodes into AVX2 lanes for the force kernels (SpringKernel.cpp,
/// InsufflationPressure.cpp): one node of x (3 x nodes, column-major) per lane,
/// its x, y and z read with one masked load (the fourth lane is never read,
/// so the last node's is safe) and four nodes transposed into a register per
/// component. No arithmetic: the lanes hold the very values a scalar read gets.
/// Only for functions compiled for AVX2 (target("avx2")), called where the
/// processor has it.

#if defined(__x86_64__)
#include <immintrin.h>

namespace colonosim::physics::lanes {

/// Whether this processor has AVX2, asked once (the build stays plain x86-64).
inline bool available()
{
    static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
    return avx2;
}

/// Rows 0-2 of the 4 x 4 matrix whose columns are a0..a3: each row one
/// component of the four columns, lane 0 from a0.
struct Rows {
    __m256d r0, r1, r2;
};

__attribute__((target("avx2"))) inline Rows transpose(__m256d a0, __m256d a1, __m256d a2, __m256d a3)
{
    const __m256d t0 = _mm256_unpacklo_pd(a0, a1);  // a0.0 a1.0 a0.2 a1.2
    const __m256d t1 = _mm256_unpackhi_pd(a0, a1);  // a0.1 a1.1 a0.3 a1.3
    const __m256d t2 = _mm256_unpacklo_pd(a2, a3);
    const __m256d t3 = _mm256_unpackhi_pd(a2, a3);
    return {_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
            _mm256_permute2f128_pd(t0, t2, 0x31)};
}

/// Row 3 of the same matrix.
__attribute__((target("avx2"))) inline __m256d fourthRow(__m256d a0, __m256d a1, __m256d a2, __m256d a3)
{
    return _mm256_permute2f128_pd(_mm256_unpackhi_pd(a0, a1), _mm256_unpackhi_pd(a2, a3), 0x31);
}

/// Node n's x, y and z in lanes 0-2 (lane 3 zero).
__attribute__((target("avx2"))) inline __m256d node(const double* q, int n)
{
    return _mm256_maskload_pd(q + 3 * n, _mm256_set_epi64x(0, -1, -1, -1));
}

/// The x, y and z of nodes n0..n3, lane 0 from n0.
__attribute__((target("avx2"))) inline Rows nodes(const double* q, int n0, int n1, int n2, int n3)
{
    return transpose(node(q, n0), node(q, n1), node(q, n2), node(q, n3));
}

}  // namespace colonosim::physics::lanes
#endif
