/*
 * sphkern kernel plugin interface, ABI 2: the header a kernel plugin includes.
 *
 * A plugin is a shared library exporting one C function,
 *
 *     SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void);
 *
 * (in C++, inside extern "C", or the host cannot find the name), returning a pointer to a
 * static descriptor that starts with {abi_major, abi_minor, struct_size}. Everything
 * that crosses the boundary is plain C: numbers, C strings, arrays and function
 * pointers. No allocation, exception or C++ type may cross it.
 *
 * Versions: the host loads every minor version of its major version and reads only the
 * fields that lie inside `struct_size`, so a newer minor adds fields at the end (taken
 * from `reserved`) and an older host ignores them. A new major version is a new layout.
 * Plugins built against ABI 1 (a first field `abi_version` = 1) keep loading.
 * Optional features are extensions: `get_extension(id)` returns a pointer to the
 * extension's static struct, or NULL when the plugin does not provide it.
 *
 * Conventions (q = r / h, h = k d, D = dimension):
 *   w(q, D, k, params)   returns h^D W          (the normalised kernel, sigma_D included)
 *   dw(q, D, k, params)  returns h^(D+1) dW/dr
 *   d2w(q, D, k, params) returns h^(D+2) d2W/dr2 (extension SPHKERN_EXTENSION_SECOND_DERIVATIVE)
 *   w_dw(q, w, dw, n, D, k, params) writes w[i] = h^D W(q[i]) and dw[i] = h^(D+1) dW/dr(q[i])
 *     for i < n in one call (extension SPHKERN_EXTENSION_FUSED_EVALUATION, ABI 2.1)
 *   transform(kh, D, k, params) returns the Fourier transform of W at wave number kappa
 *     with kh = kappa h: integral of W(|x|) exp(-i kappa.x) d^D x, dimensionless, 1 at
 *     kh = 0 (extension SPHKERN_EXTENSION_FOURIER_TRANSFORM).
 * Each returns the formula as written for every q >= 0: a one-formula kernel keeps
 * its formula past the support R, a piecewise kernel returns its own zero branch.
 * The host truncates at R. The derivatives are their own functions: the host never
 * assumes they are derivatives of w (they may depend on k); `sphkern check` compares.
 *
 * Contract with the host:
 *   - Threads: every kernel function (scalar, batch, extensions) is called concurrently
 *     from several threads, with different or equal arguments. They must be reentrant:
 *     no writable global or static state, no locale or errno games.
 *   - Memory: `q` and `out` of a batch call never alias; `params` is read-only and holds
 *     one value per declared parameter (NULL if none). The descriptor, the extension
 *     structs and every string and array they point to must stay valid and unchanged as
 *     long as the library is loaded (static storage).
 *   - Flags: only the bits defined here; a descriptor with an unknown bit is refused.
 *   - Output: stdout belongs to the host; a plugin must not write to it (sphkern points
 *     descriptor 1 at stderr, so stray output only clutters the log).
 *   - Signals: a plugin must not install signal handlers; the host takes SIGINT,
 *     SIGTERM and SIGHUP back after loading a library.
 *   - The entry function is first called in a child process (a probe with a time
 *     bound), then in the host; it must have no side effect but returning the pointer.
 *
 * Fill the descriptor with designated initialisers and SPHKERN_DESCRIPTOR_VERSION:
 *
 *     static const sphkern_kernel_descriptor descriptor = {
 *         SPHKERN_DESCRIPTOR_VERSION,
 *         .name = "my_kernel", .title = "...", .reference = "...",
 *         .support = 2.0, .dimensions = SPHKERN_DIM(2) | SPHKERN_DIM(3),
 *         .w = w, .dw = dw, .w_batch = w_batch, .dw_batch = dw_batch,
 *     };
 */
#ifndef SPHKERN_KERNEL_PLUGIN_H
#define SPHKERN_KERNEL_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SPHKERN_KERNEL_ABI_MAJOR 2u
#define SPHKERN_KERNEL_ABI_MINOR 1u

/* Bit set in `dimensions` for each supported dimension D (1, 2, 3). */
#define SPHKERN_DIM(D) (1u << (D))

/* `flags`: the derivative is a separate formula, not d/dr of W. */
#define SPHKERN_KERNEL_SEPARATE_DERIVATIVE 1u
/* Every flag this version defines. */
#define SPHKERN_KERNEL_KNOWN_FLAGS SPHKERN_KERNEL_SEPARATE_DERIVATIVE

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

/* Scalar form. */
typedef double (*sphkern_kernel_fn)(double q, int dim, double k, const double* params);
/* Batch form: out[i] = f(q[i]) for i < n. */
typedef void (*sphkern_kernel_batch_fn)(const double* q, double* out, size_t n, int dim,
                                        double k, const double* params);

typedef struct sphkern_kernel_descriptor {
    uint32_t abi_major;   /* SPHKERN_KERNEL_ABI_MAJOR; always first */
    uint32_t abi_minor;   /* SPHKERN_KERNEL_ABI_MINOR */
    uint32_t struct_size; /* sizeof(sphkern_kernel_descriptor) in the plugin's build */
    uint32_t flags;       /* SPHKERN_KERNEL_* bits */
    const char* name;      /* identifier: [a-z0-9_]+ */
    const char* title;
    const char* reference; /* literature reference */
    double support;        /* R: W = 0 for q > R */
    uint32_t dimensions;   /* SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3) subset */
    uint32_t parameter_count;
    const sphkern_kernel_parameter* parameters;
    uint32_t breakpoint_count; /* interior q where the piecewise definition changes */
    const double* breakpoints;
    sphkern_kernel_fn w;
    sphkern_kernel_fn dw;
    sphkern_kernel_batch_fn w_batch;
    sphkern_kernel_batch_fn dw_batch;
    /* Optional features by identifier (SPHKERN_EXTENSION_*); NULL or returning NULL: none. */
    const void* (*get_extension)(const char* id);
    void* reserved[8]; /* zero; later minor versions take fields from here */
} sphkern_kernel_descriptor;

/* The first three fields, for designated initialisation. */
#define SPHKERN_DESCRIPTOR_VERSION                                                           \
    .abi_major = SPHKERN_KERNEL_ABI_MAJOR, .abi_minor = SPHKERN_KERNEL_ABI_MINOR,           \
    .struct_size = (uint32_t)sizeof(sphkern_kernel_descriptor)

typedef const sphkern_kernel_descriptor* (*sphkern_kernel_entry_fn)(void);

/* Extension: the second derivative h^(D+2) d2W/dr2, scalar and batch. */
#define SPHKERN_EXTENSION_SECOND_DERIVATIVE "sphkern.second_derivative.1"
typedef struct sphkern_second_derivative {
    sphkern_kernel_fn d2w;
    sphkern_kernel_batch_fn d2w_batch;
} sphkern_second_derivative;

/* Extension: the radial Fourier transform of the normalised kernel, as a function of
 * kh = kappa h (dimensionless; 1 at kh = 0). */
#define SPHKERN_EXTENSION_FOURIER_TRANSFORM "sphkern.fourier_transform.1"
typedef double (*sphkern_fourier_fn)(double kh, int dim, double k, const double* params);
typedef struct sphkern_fourier_transform {
    sphkern_fourier_fn transform;
} sphkern_fourier_transform;

/* Extension (ABI 2.1): W and dW/dr together over an array of q = r / h, in one call. The
 * host's pair loops (`sphkern particles`) evaluate both at every neighbour; one call
 * instead of two batch calls halves the calls and lets the plugin share q's powers between
 * W and W'. The values must equal the scalar w and dw (the host's probe compares them).
 * q, w and dw never alias. The host takes q rather than r^2 or q^2: it needs r and 1/r
 * for the pair's direction anyway, so a square root in the plugin would be a second one.
 * Write it with SPHKERN_FUSED_FROM_SCALAR (kernel_plugin_helpers.h). A plugin without it
 * keeps working: the host calls w_batch and dw_batch instead. */
#define SPHKERN_EXTENSION_FUSED_EVALUATION "sphkern.fused_evaluation.1"
typedef void (*sphkern_kernel_fused_fn)(const double* q, double* w, double* dw, size_t n, int dim, double k,
                                        const double* params);
typedef struct sphkern_fused_evaluation {
    sphkern_kernel_fused_fn w_dw;
} sphkern_fused_evaluation;

#ifdef __cplusplus
}
#endif

#endif /* SPHKERN_KERNEL_PLUGIN_H */
