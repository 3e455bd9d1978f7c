/* Quadratic kernel of Johnson et al. (paper eq. 10), R = 2. One formula: continues past R. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 1.0 : dim == 2 ? 2.0 / PI : 5.0 / (4.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (0.75 - 0.75 * q + 3.0 / 16.0 * q * q);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (-0.75 + 0.375 * q);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "johnson_quadratic",
    .title = "Quadratic kernel (Johnson)",
    .reference = "Johnson, Stryk & Beissel, Comput. Methods Appl. Mech. Eng. 139 (1996) 347; Potapov & Reshetnikova (2021) eq. 10",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
