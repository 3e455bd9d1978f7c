/* A working Wendland C2 (support 2, 2D and 3D) for the test plugins whose fault is outside W:
   what they do when loaded. A plugin defines WENDLAND_NAME and WENDLAND_TITLE, then includes
   this. */
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define WENDLAND_PI 3.14159265358979323846

static double sigma(int dim) { return dim == 2 ? 7.0 / (4.0 * WENDLAND_PI) : 21.0 / (16.0 * WENDLAND_PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    if (q >= 2.0) return 0.0;
    double t = 1.0 - 0.5 * q;
    return sigma(dim) * t * t * t * t * (2.0 * q + 1.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    if (q >= 2.0) return 0.0;
    double t = 1.0 - 0.5 * q;
    return sigma(dim) * -5.0 * q * t * t * t;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = WENDLAND_NAME,
    .title = WENDLAND_TITLE,
    .reference = "",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
