/* The 3D cubic B-spline of the deliberately broken plugins that pass their probe and fail
   later. A plugin defines BROKEN_NAME and BROKEN_FAULT(q, k), a statement run first in W, and
   may define BROKEN_BATCH_FAULT(n, out), run first in the batch W, and BROKEN_EXTENSION, its
   get_extension function (defined after this file's w and dw); then includes this. */
#define _GNU_SOURCE /* M_1_PI */
#include <math.h>
#include <stddef.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#ifndef M_1_PI /* a plugin's own includes came first, without _GNU_SOURCE */
#define M_1_PI 0.318309886183790671538
#endif
#ifndef BROKEN_BATCH_FAULT
#define BROKEN_BATCH_FAULT(n, out)
#endif

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    BROKEN_FAULT(q, k);
    return M_1_PI * (q < 2 ? 0.25 * (2 - q) * (2 - q) * (2 - q) - (q < 1 ? (1 - q) * (1 - q) * (1 - q) : 0.0) : 0.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return M_1_PI * (q < 2 ? -0.75 * (2 - q) * (2 - q) + (q < 1 ? 3 * (1 - q) * (1 - q) : 0.0) : 0.0);
}

static void w_batch(const double* q, double* out, size_t n, int dim, double k, const double* p)
{
    BROKEN_BATCH_FAULT(n, out);
    for (size_t i = 0; i < n; ++i) out[i] = w(q[i], dim, k, p);
}
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

#ifdef BROKEN_EXTENSION
static const void* BROKEN_EXTENSION(const char* id);
#endif

static const double breakpoints[] = {1.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = BROKEN_NAME,
    .title = "broken: the 3D cubic B-spline",
    .reference = "",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(3),
    .breakpoint_count = 1,
    .breakpoints = breakpoints,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
#ifdef BROKEN_EXTENSION
    .get_extension = BROKEN_EXTENSION,
#endif
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
