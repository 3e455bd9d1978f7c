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

/* No aliasing between the arrays of a batch (the contract of kernel_plugin.h): the loop
 * with two outputs vectorises only when the compiler knows it. C and C++ alike. */
#if defined(__GNUC__) || defined(__clang__)
#define SPHKERN_RESTRICT __restrict
#else
#define SPHKERN_RESTRICT
#endif

/* Defines `name` as the fused function of SPHKERN_EXTENSION_FUSED_EVALUATION from the
 * scalar functions `w` and `dw`: one call writes both, a loop for each (GCC turns one loop
 * over two piecewise functions into branches, not vector code). The loops vectorise when the
 * functions are branch-free and the plugin is built without trapping math, as
 * sphkern_add_kernel_plugin builds it. Pair it with SPHKERN_FUSED_EXTENSION or return
 * &name's struct yourself. */
#define SPHKERN_FUSED_FROM_SCALAR(name, w, dw)                                                  \
    SPHKERN_VECTOR_CLONES static void name(const double* SPHKERN_RESTRICT q, double* SPHKERN_RESTRICT w_out, \
                                           double* SPHKERN_RESTRICT dw_out, size_t n, int dim, double k,      \
                                           const double* params)                                              \
    {                                                                                         \
        for (size_t i = 0; i < n; ++i) w_out[i] = w(q[i], dim, k, params);                     \
        for (size_t i = 0; i < n; ++i) dw_out[i] = dw(q[i], dim, k, params);                   \
    }

/* Defines `name` as a get_extension function that gives the fused evaluation `fused`
 * (made by SPHKERN_FUSED_FROM_SCALAR) and no other extension. Needs <string.h>. */
#define SPHKERN_FUSED_EXTENSION(name, fused)                                                    \
    static const void* name(const char* id)                                                   \
    {                                                                                         \
        static const sphkern_fused_evaluation extension = {fused};                            \
        return strcmp(id, SPHKERN_EXTENSION_FUSED_EVALUATION) == 0 ? &extension : NULL;       \
    }

#endif /* SPHKERN_KERNEL_PLUGIN_HELPERS_H */
