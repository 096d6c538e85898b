#include "core/common/vector_state.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define PROBECYCLE_X86_64_GNU 1
#endif

namespace probecycle {

#ifdef PROBECYCLE_X86_64_GNU

namespace {

// vzeroupper is an AVX instruction: only this function is built for AVX, and
// it runs only where the CPU has it.
__attribute__((target("avx"))) void zero_upper() {
    _mm256_zeroupper();
}

}  // namespace

void clear_vector_upper_state() {
    static const bool has_avx = __builtin_cpu_supports("avx") != 0;
    if (has_avx) zero_upper();
}

#else

void clear_vector_upper_state() {}

#endif

}  // namespace probecycle
