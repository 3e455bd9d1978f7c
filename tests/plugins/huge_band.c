/* A kernel that is 1e308 on the narrow band 0.701 < q < 0.709 only, finite everywhere: a
 * lattice sum at k = 1/0.705 on fcc overflows (12 neighbours on the band) while each value is
 * a number. The error must name the kernel and the band, not blame k. */
#include <math.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    if (q > 0.701 && q < 0.709) return 1e308;
    return q < 1.0 ? 0.75 * (1.0 - q * q) : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q < 1.0 ? -1.5 * q : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "huge_band",
    .title = "broken",
    .reference = "",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
