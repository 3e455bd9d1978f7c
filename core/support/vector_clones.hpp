// The engine's batch loops compiled once per instruction set (AVX-512, AVX2, the baseline)
// and picked at load time (GCC on x86-64 Linux), as the plugin SDK's SPHKERN_VECTOR_CLONES
// does for plugins; elsewhere one plain version.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SPHKERN_ENGINE_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SPHKERN_ENGINE_CLONES
#endif
