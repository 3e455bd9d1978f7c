/*
 * Optional helpers for kernel plugins: batch functions from scalar ones, compiled for
 * several instruction sets. Not part of the ABI; a plugin may write its own batches.
 */
#ifndef SPHKERN_KERNEL_PLUGIN_HELPERS_H
#define SPHKERN_KERNEL_PLUGIN_HELPERS_H

#include <stddef.h>

/* Compiles a batch loop once per instruction set and picks one at load time (GCC on
 * x86-64), so that a branch-free scalar formula runs in wide vector registers. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SPHKERN_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SPHKERN_VECTOR_CLONES
#endif

/* Defines `name` as a batch function looping over the scalar function `scalar`; the
 * loop vectorises when `scalar` is branch-free (use ?: rather than if/return). */
#define SPHKERN_BATCH_FROM_SCALAR(name, scalar)                                              \
    SPHKERN_VECTOR_CLONES static void name(const double* q, double* out, size_t n, int dim, \
                                           double k, const double* params)                 \
    {                                                                                      \
        for (size_t i = 0; i < n; ++i) out[i] = scalar(q[i], dim, k, params);              \
    }

#endif /* SPHKERN_KERNEL_PLUGIN_HELPERS_H */
