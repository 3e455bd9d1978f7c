/*
 * sphkern kernel plugin interface: the only header a kernel plugin includes.
 *
 * A plugin is a shared library exporting one C function,
 *
 *     SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void);
 *
 * returning a pointer to a static descriptor that starts with the ABI version.
 * Everything that crosses the boundary is plain C: numbers, C strings, arrays and
 * function pointers. No allocation, exception or C++ type may cross it.
 *
 * Conventions (q = r / h, h = k d, D = dimension):
 *   w(q, D, k, params)  returns h^D W       (the normalised kernel, sigma_D included)
 *   dw(q, D, k, params) returns h^(D+1) dW/dr
 * Each returns the formula as written for every q >= 0: a one-formula kernel keeps
 * its formula past the support R, a piecewise kernel returns its own zero branch.
 * The host truncates at R. The derivative is its own function: the host never
 * assumes it is the derivative of w (it may depend on k).
 *
 * Contract with the host:
 *   - Threads: w, dw, w_batch and dw_batch are called concurrently from several
 *     threads, with different or equal arguments. They must be reentrant: no writable
 *     global or static state, no locale or errno games.
 *   - Memory: `q` and `out` of a batch call never alias; `params` is read-only. The
 *     descriptor and every string and array it points to must stay valid and unchanged
 *     as long as the library is loaded (static storage).
 *   - Output: stdout belongs to the host; a plugin must not write to it (sphkern points
 *     descriptor 1 at stderr, so stray output only clutters the log).
 *   - Signals: a plugin must not install signal handlers; the host takes SIGINT,
 *     SIGTERM and SIGHUP back after loading a library.
 *   - The entry function is first called in a child process (a probe with a time
 *     bound), then in the host; it must have no side effect but returning the pointer.
 */
#ifndef SPHKERN_KERNEL_PLUGIN_H
#define SPHKERN_KERNEL_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped whenever the descriptor layout or a function signature changes. */
#define SPHKERN_KERNEL_ABI_VERSION 1u

/* Bit set in `dimensions` for each supported dimension D (1, 2, 3). */
#define SPHKERN_DIM(D) (1u << (D))

/* `flags`: the derivative is a separate formula, not d/dr of W. */
#define SPHKERN_KERNEL_SEPARATE_DERIVATIVE 1u

#define SPHKERN_ENTRY_NAME "sphkern_kernel_entry"

#if defined(_WIN32)
#define SPHKERN_PLUGIN_EXPORT __declspec(dllexport)
#else
#define SPHKERN_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

typedef struct sphkern_kernel_parameter {
    const char* name;
    const char* description;
    double default_value;
    double min_value; /* allowed range, inclusive */
    double max_value;
} sphkern_kernel_parameter;

/* Scalar form. `params` holds one value per declared parameter (may be NULL if none). */
typedef double (*sphkern_kernel_fn)(double q, int dim, double k, const double* params);
/* Batch form: out[i] = f(q[i]) for i < n. */
typedef void (*sphkern_kernel_batch_fn)(const double* q, double* out, size_t n, int dim,
                                        double k, const double* params);

typedef struct sphkern_kernel_descriptor {
    uint32_t abi_version; /* must be SPHKERN_KERNEL_ABI_VERSION; always first */
    const char* name;      /* identifier: [a-z0-9_]+ */
    const char* title;
    const char* reference; /* literature reference */
    double support;        /* R: W = 0 for q > R */
    uint32_t dimensions;   /* SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3) subset */
    uint32_t flags;
    uint32_t parameter_count;
    const sphkern_kernel_parameter* parameters;
    uint32_t breakpoint_count; /* interior q where the piecewise definition changes */
    const double* breakpoints;
    sphkern_kernel_fn w;
    sphkern_kernel_fn dw;
    sphkern_kernel_batch_fn w_batch;
    sphkern_kernel_batch_fn dw_batch;
} sphkern_kernel_descriptor;

typedef const sphkern_kernel_descriptor* (*sphkern_kernel_entry_fn)(void);

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

#ifdef __cplusplus
}
#endif

#endif /* SPHKERN_KERNEL_PLUGIN_H */
