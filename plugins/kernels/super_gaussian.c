/* Super-Gaussian kernel (paper eq. 6; Monaghan's D-dimensional form in 3D), R = 3.
 * One formula for all q: it continues past R, where the host truncates it. */
#include <math.h>
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

/* The paper's (3/2 - q^2) in 1D and 2D; (5/2 - q^2) in 3D (the 2D form integrates to 0 there). */
static double shape_constant(int dim) { return dim == 3 ? 2.5 : 1.5; }
static double sigma(int dim)
{
    return dim == 1 ? 1.0 / sqrt(PI) : dim == 2 ? 2.0 / PI : pow(PI, -1.5);
}

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (shape_constant(dim) - q * q) * exp(-q * q);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * -2.0 * q * (1.0 + shape_constant(dim) - q * q) * exp(-q * q);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "super_gaussian",
    .title = "Super-Gaussian (truncated at R = 3)",
    .reference = "Monaghan, Rep. Prog. Phys. 68 (2005) 1703; Potapov & Reshetnikova (2021) eq. 6",
    .support = 3.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
