/* The 2D parabola W = 1 - q^2 of the deliberately broken plugins that differ only in W or in
   their descriptor. A plugin defines PARABOLA_NAME and may define PARABOLA_W_BODY(q) (the
   statements of W, returning its value), PARABOLA_SUPPORT, PARABOLA_DIMENSIONS and
   PARABOLA_VERSION (the descriptor's version fields); then
   includes this. */
#include <math.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#ifndef PARABOLA_W_BODY
#define PARABOLA_W_BODY(q) return 1.0 - (q) * (q);
#endif
#ifndef PARABOLA_SUPPORT
#define PARABOLA_SUPPORT 1.0
#endif
#ifndef PARABOLA_VERSION
#define PARABOLA_VERSION SPHKERN_DESCRIPTOR_VERSION
#endif
#ifndef PARABOLA_DIMENSIONS
#define PARABOLA_DIMENSIONS SPHKERN_DIM(2)
#endif

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    PARABOLA_W_BODY(q)
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return -2.0 * q;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    PARABOLA_VERSION,
    .name = PARABOLA_NAME,
    .title = "broken",
    .reference = "",
    .support = PARABOLA_SUPPORT,
    .dimensions = PARABOLA_DIMENSIONS,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
