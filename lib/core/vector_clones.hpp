// SIGCHAIN_VECTOR_CLONES: a hot numerical function compiled twice, for AVX2 and for
// the x86-64 baseline (SSE2), the loader picking one by the CPU (GCC's target_clones,
// through glibc's ifunc; Clang 14 accepts the attribute but may not clone). The clones give the same bits: AVX2 without
// FMA only widens element-wise loops (4 doubles a step instead of 2); no sum is
// reordered (no -ffast-math) and no multiply-add is fused (FMA is not enabled).
// Elsewhere the attribute is empty.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && defined(__linux__)
#define SIGCHAIN_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SIGCHAIN_VECTOR_CLONES
#endif
