// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#include "core/solver/plain_sweep.h"

#include <cstddef>
#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define MESHFAIR_HAVE_AVX2_SWEEP 1
#endif

namespace meshfair {

namespace detail {

void plain_sweep_scalar(const PlainSweep& s, Index begin, Index end)
{
    // x and y as one pair, z alone: two instructions fewer per neighbour than three
    // scalars (GCC's vector extension; SSE2 on every x86-64).
    using Pair = Scalar __attribute__((vector_size(2 * sizeof(Scalar))));
    // Locals: the stores to y could change s's members for the compiler.
    const Index* free = s.free;
    const Index* offsets = s.offsets;
    const Index* neighbors = s.neighbors;
    const Scalar* diagonal = s.diagonal;
    const Scalar* x = s.x;
    Scalar* y = s.y;
    const Scalar step = s.lambda;
    for (Index k = begin; k < end; ++k)
    {
        const Index i = free[k];
        // 64 bits before the multiplication: the address is then one addressing mode.
        const std::ptrdiff_t at = 3 * static_cast<std::ptrdiff_t>(i);
        Pair x01;
        std::memcpy(&x01, x + at, sizeof x01);
        const Scalar x2 = x[at + 2];
        Pair s01 = {0, 0};
        Scalar s2 = 0;
        for (Index n = offsets[i]; n < offsets[i + 1]; ++n)
        {
            const Scalar* q = x + 3 * static_cast<std::ptrdiff_t>(neighbors[n]);
            Pair q01;
            std::memcpy(&q01, q, sizeof q01);
            s01 += q01 - x01;
            s2 += q[2] - x2;
        }
        const Scalar inv = Scalar(1) / diagonal[i];
        y[at] = x01[0] + step * (s01[0] * inv);
        y[at + 1] = x01[1] + step * (s01[1] * inv);
        y[at + 2] = x2 + step * (s2 * inv);
    }
}

#ifdef MESHFAIR_HAVE_AVX2_SWEEP

namespace {

// No "fma" in the target: a fused multiply-add would round once where the scalar sweep
// rounds twice, and the two sweeps must agree bit for bit.
__attribute__((target("avx2"))) void plain_sweep_avx2_body(const PlainSweep& s, Index begin,
                                                           Index end)
{
    // Lanes 0-2 hold x, y, z; lane 3 is masked off, so the load never reads past a
    // vertex's three coordinates (the last vertex's are the array's last values).
    const __m256i xyz = _mm256_set_epi64x(0, -1, -1, -1);
    const Index* free = s.free;
    const Index* offsets = s.offsets;
    const Index* neighbors = s.neighbors;
    const Scalar* diagonal = s.diagonal;
    const Scalar* x = s.x;
    Scalar* y = s.y;
    const __m256d step = _mm256_set1_pd(s.lambda);
    for (Index k = begin; k < end; ++k)
    {
        const Index i = free[k];
        const std::ptrdiff_t at = 3 * static_cast<std::ptrdiff_t>(i);
        const __m256d xi = _mm256_maskload_pd(x + at, xyz);
        __m256d sum = _mm256_setzero_pd();
        for (Index n = offsets[i]; n < offsets[i + 1]; ++n)
        {
            const __m256d q =
                _mm256_maskload_pd(x + 3 * static_cast<std::ptrdiff_t>(neighbors[n]), xyz);
            sum = _mm256_add_pd(sum, _mm256_sub_pd(q, xi));
        }
        const __m256d inv = _mm256_set1_pd(Scalar(1) / diagonal[i]);
        const __m256d next = _mm256_add_pd(xi, _mm256_mul_pd(step, _mm256_mul_pd(sum, inv)));
        _mm_storeu_pd(y + at, _mm256_castpd256_pd128(next));
        _mm_store_sd(y + at + 2, _mm256_extractf128_pd(next, 1));
    }
}

bool have_avx2()
{
    static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
    return avx2;
}

} // namespace

bool plain_sweep_avx2(const PlainSweep& s, Index begin, Index end)
{
    if (!have_avx2())
        return false;
    plain_sweep_avx2_body(s, begin, end);
    return true;
}

#else

bool plain_sweep_avx2(const PlainSweep&, Index, Index)
{
    return false;
}

#endif

} // namespace detail

void plain_sweep(const PlainSweep& s, Index begin, Index end)
{
    if (!detail::plain_sweep_avx2(s, begin, end))
        detail::plain_sweep_scalar(s, begin, end);
}

} // namespace meshfair
