/* Morris quintic spline (paper eq. 7), R = 3, with the exact sigma_3 = 1/(120 pi). */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim)
{
    return dim == 1 ? 1.0 / 120.0 : dim == 2 ? 7.0 / (478.0 * PI) : 1.0 / (120.0 * PI);
}
static double p5(double x) { return x > 0.0 ? x * x * x * x * x : 0.0; }
static double p4(double x) { return x > 0.0 ? x * x * x * x : 0.0; }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (p5(3.0 - q) - 6.0 * p5(2.0 - q) + 15.0 * p5(1.0 - q));
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return -5.0 * sigma(dim) * (p4(3.0 - q) - 6.0 * p4(2.0 - q) + 15.0 * p4(1.0 - q));
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const double breakpoints[] = {1.0, 2.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "morris_quintic",
    .title = "Quintic spline (Morris)",
    .reference = "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214; Potapov & Reshetnikova (2021) eq. 7",
    .support = 3.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .breakpoint_count = 2u,
    .breakpoints = breakpoints,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
