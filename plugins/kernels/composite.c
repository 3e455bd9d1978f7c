/* Composite kernel (paper eq. 13a, 13b), R = 1, 2D only. Its derivative (13b) is a
 * separate formula that depends on k and is singular at k = 63/74. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    if (q > 1.0) return 0.0;
    double s = 1.0 - q * q;
    return 15.0 / 13.0 * s * s * (1.0 - (4.0 - 52.0 / (5.0 * PI)) * q * q);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)p;
    if (q > 1.0) return 0.0;
    return -1369.0 * k * k / (28.0 * PI * (74.0 * k - 63.0)) * (84.0 / 37.0 * k - 2.0 * q);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "composite",
    .title = "Composite kernel (Potapov & Reshetnikova)",
    .reference = "Potapov & Reshetnikova, Computer Research and Modeling 13(5) (2021), eq. 13a, 13b",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(2),
    .flags = SPHKERN_KERNEL_SEPARATE_DERIVATIVE,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
