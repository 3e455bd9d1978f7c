/* A deliberately broken kernel for `check`: the 1D cubic B-spline (zero from q = 2)
 * declared with support R = 3. */
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    double t = 2.0 - q;
    return q <= 1.0 ? 2.0 / 3.0 - q * q + 0.5 * q * q * q : q <= 2.0 ? t * t * t / 6.0 : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    double t = 2.0 - q;
    return q <= 1.0 ? -2.0 * q + 1.5 * q * q : q <= 2.0 ? -0.5 * t * t : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const double breakpoints[] = {1.0, 2.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "over_declared_support", .title = "broken", .reference = "",
    .support = 3.0, .dimensions = SPHKERN_DIM(1),
    .breakpoint_count = 2u, .breakpoints = breakpoints,
    .w = w, .dw = dw, .w_batch = w_batch, .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
