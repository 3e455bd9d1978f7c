/* PySPH's SuperGaussian (pysph/base/kernels.py, class SuperGaussian, kernel and dwdq), R = 3:
 * W = pi^(-D/2) (1 + D/2 - q^2) exp(-q^2). In 1D and 3D the paper's super_gaussian; in 2D
 * (2 - q^2) / pi where the paper's eq. 6 has (3/2 - q^2) 2 / pi. One formula for all q: it
 * continues past R, where the host truncates it, as PySPH does at q = 3. */
#include <math.h>
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return pow(PI, -0.5 * dim); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (1.0 + 0.5 * dim - q * q) * exp(-q * q);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * q * (2.0 * q * q - dim - 4.0) * exp(-q * q);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "pysph_super_gaussian",
    .title = "PySPH's super-Gaussian (truncated at R = 3)",
    .reference = "Monaghan (1992) as PySPH defines it: pi^(-D/2) (1 + D/2 - q^2) exp(-q^2)",
    .support = 3.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
