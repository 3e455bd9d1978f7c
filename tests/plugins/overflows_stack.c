/* A deliberately broken kernel plugin that passes its probe: W recurses without end for k > 1.3
   (beyond the probe's k) and overflows its stack. */
#define _GNU_SOURCE /* M_1_PI */
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static volatile int bottom = -1; /* never reached: the stack ends first */

static double deeper(double q, int depth)
{
    volatile char frame[1024];
    frame[depth % 1024] = (char)depth;
    if (depth == bottom) return q;
    return deeper(q + frame[0], depth + 1) + frame[depth % 1024]; /* not a tail call */
}

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    if (k > 1.3) return deeper(q, 0);
    return M_1_PI * (q < 2 ? 0.25 * (2 - q) * (2 - q) * (2 - q) - (q < 1 ? (1 - q) * (1 - q) * (1 - q) : 0.0) : 0.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return M_1_PI * (q < 2 ? -0.75 * (2 - q) * (2 - q) + (q < 1 ? 3 * (1 - q) * (1 - q) : 0.0) : 0.0);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const double breakpoints[] = {1.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "overflows_stack",
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
