/* Quartic kernel of Liu (paper eq. 9), R = 2. One formula: continues past R. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 1.0 : dim == 2 ? 15.0 / (7.0 * PI) : 315.0 / (208.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (2.0 / 3.0 + q * q * (-9.0 / 8.0 + q * (19.0 / 24.0 - 5.0 / 32.0 * q)));
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * q * (-9.0 / 4.0 + q * (19.0 / 8.0 - 5.0 / 8.0 * q));
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "liu_quartic",
    .title = "Quartic kernel (Liu)",
    .reference = "Liu & Liu, Smoothed Particle Hydrodynamics, World Scientific (2003); Potapov & Reshetnikova (2021) eq. 9",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
