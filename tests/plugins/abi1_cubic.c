/* A plugin built against the frozen ABI 1 header (tests/plugins/abi1): the cubic B-spline,
 * filled positionally as ABI 1 plugins were. It must load and agree with cubic_bspline. */
#include "sphkern/kernel_plugin.h"

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 1.0 : dim == 2 ? 15.0 / (7.0 * PI) : 3.0 / (2.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    double t = 2.0 - q;
    return sigma(dim) * (q <= 1.0 ? 2.0 / 3.0 - q * q + 0.5 * q * q * q : q <= 2.0 ? t * t * t * (1.0 / 6.0) : 0.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    double t = 2.0 - q;
    return sigma(dim) * (q <= 1.0 ? -2.0 * q + 1.5 * q * q : q <= 2.0 ? -0.5 * t * t : 0.0);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const double breakpoints[] = {1.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_KERNEL_ABI_VERSION, "abi1_cubic", "Cubic B-spline built against ABI 1", "",
    2.0, SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3), 0u, 0u, NULL, 1u, breakpoints,
    w, dw, w_batch, dw_batch};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
