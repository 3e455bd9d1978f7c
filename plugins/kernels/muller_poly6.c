/* Poly6 kernel of Mueller et al. (paper eq. 12), R = 1. One formula: continues past R. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 35.0 / 32.0 : dim == 2 ? 4.0 / PI : 315.0 / (64.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    double s = 1.0 - q * q;
    return sigma(dim) * s * s * s;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    double s = 1.0 - q * q;
    return -6.0 * sigma(dim) * q * s * s;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "muller_poly6",
    .title = "Poly6 kernel (Mueller)",
    .reference = "Mueller, Charypar & Gross, SCA 2003, 154; Potapov & Reshetnikova (2021) eq. 12",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
