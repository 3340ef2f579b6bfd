// SPDX-License-Identifier: MIT
// The integer formats' depth test four pixels at a time on x86-64 processors with AVX2 (the build takes this file
// on x86 only; depth_test_row_portable.cpp elsewhere).
#include "zbuffer/depth_test_row.h"

#include <immintrin.h>

namespace hsr::algo {
namespace {

// The integer formats' test, four pixels a step with AVX2. The depths z are made one after another by the same
// additions as the pixel-by-pixel loop (so each is the same double); their codes round(levels · clamp(z, 0, 1))
// are made as round_nonnegative makes them (x < ½ → 0, else trunc(x + ½), exact), compared as unsigned 32-bit
// integers (offset by 2^31 to use the signed compare), and written where nearer.
__attribute__((target("avx2"))) std::uint64_t integer_row_avx2(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z,
                                                              double per_x, std::int32_t index, double levels) {
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), half = _mm256_set1_pd(0.5), scale = _mm256_set1_pd(levels);
    const __m256d offset = _mm256_set1_pd(2147483648.0);  // 2^31
    const __m128i sign = _mm_set1_epi32(std::int32_t(0x80000000u)), mine = _mm_set1_epi32(index);
    const __m128i lanes = _mm_setr_epi32(0, 1, 2, 3);
    std::uint64_t won = 0;
    // Every step takes four pixels; the last one masks the lanes past the span's end (they are neither read nor
    // written: the next tile may be another thread's), so that a row ends with no loop of its own for the rest.
    for (int x = begin; x < end; x += 4) {
        const double z0 = z, z1 = z0 + per_x, z2 = z1 + per_x, z3 = z2 + per_x;
        z = z3 + per_x;
        const __m256d level = _mm256_mul_pd(scale, _mm256_min_pd(_mm256_max_pd(_mm256_set_pd(z3, z2, z1, z0), zero), one));
        const __m256d rounded = _mm256_and_pd(_mm256_cmp_pd(level, half, _CMP_GE_OQ),
                                              _mm256_round_pd(_mm256_add_pd(level, half), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC));
        const __m128i incoming = _mm256_cvttpd_epi32(_mm256_sub_pd(rounded, offset));  // code − 2^31, as a signed integer
        const __m128i inside = _mm_cmpgt_epi32(_mm_set1_epi32(end - x), lanes);
        auto* const d = reinterpret_cast<int*>(depth + x);
        const __m128i stored = _mm_maskload_epi32(d, inside);
        const __m128i nearer = _mm_and_si128(inside, _mm_cmpgt_epi32(_mm_xor_si128(stored, sign), incoming));
        _mm_maskstore_epi32(d, nearer, _mm_xor_si128(incoming, sign));
        _mm_maskstore_epi32(owner + x, nearer, mine);
        won += std::uint64_t(__builtin_popcount(unsigned(_mm_movemask_ps(_mm_castsi128_ps(nearer)))));
    }
    return won;
}

// (a static initialiser runs among the constructors, where the processor's features must be read first)
const bool has_avx2 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
}();

}  // namespace

std::optional<std::uint64_t> integer_row_wide(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x,
                                              std::int32_t index, double levels) {
    if (!has_avx2) return std::nullopt;
    return integer_row_avx2(depth, owner, begin, end, z, per_x, index, levels);
}

}  // namespace hsr::algo
