/* A deliberately broken kernel plugin that passes its probe: its batch W crashes (a segmentation
   fault) for batches of more than 100 values; the probe's batches have 61. */
#define _GNU_SOURCE /* M_1_PI */
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return M_1_PI * (q < 2 ? 0.25 * (2 - q) * (2 - q) * (2 - q) - (q < 1 ? (1 - q) * (1 - q) * (1 - q) : 0.0) : 0.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return M_1_PI * (q < 2 ? -0.75 * (2 - q) * (2 - q) + (q < 1 ? 3 * (1 - q) * (1 - q) : 0.0) : 0.0);
}

static void w_batch(const double* q, double* out, size_t n, int dim, double k, const double* p)
{
    volatile int* nowhere = (int*)0;
    if (n > 100) out[0] = *nowhere;
    for (size_t i = 0; i < n; ++i) out[i] = w(q[i], dim, k, p);
}
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const double breakpoints[] = {1.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "crash_big_batch",
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
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
