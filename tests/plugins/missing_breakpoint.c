/* A deliberately broken kernel for `check`: the quadratic B-spline (R = 1.5), whose
 * derivative has a kink at q = 0.5 that is not declared. */
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    double t = 1.5 - q;
    return q < 0.5 ? 0.75 - q * q : q <= 1.5 ? 0.5 * t * t : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q < 0.5 ? -2.0 * q : q <= 1.5 ? -(1.5 - q) : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "missing_breakpoint", .title = "broken", .reference = "",
    .support = 1.5, .dimensions = SPHKERN_DIM(1),
    .w = w, .dw = dw, .w_batch = w_batch, .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
