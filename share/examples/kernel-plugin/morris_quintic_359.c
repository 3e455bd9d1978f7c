/* Example kernel plugin: Morris's quintic spline with the 3D constant 3/(359 pi) that
 * many codes copied. `sphkern check` shows why it is wrong: its 3D integral is 1.00279.
 * A plugin includes only <sphkern/kernel_plugin.h> and exports sphkern_kernel_entry. */
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim)
{
    return dim == 1 ? 1.0 / 120.0 : dim == 2 ? 7.0 / (478.0 * PI) : 3.0 / (359.0 * PI);
}
static double p5(double x) { return x > 0.0 ? x * x * x * x * x : 0.0; }
static double p4(double x) { return x > 0.0 ? x * x * x * x : 0.0; }

/* h^D W(q): the formula as written; this piecewise kernel has its own zero branch. */
static double w(double q, int dim, double k, const double* params)
{
    (void)k; (void)params;
    return sigma(dim) * (p5(3.0 - q) - 6.0 * p5(2.0 - q) + 15.0 * p5(1.0 - q));
}

/* h^(D+1) dW/dr(q) */
static double dw(double q, int dim, double k, const double* params)
{
    (void)k; (void)params;
    return -5.0 * sigma(dim) * (p4(3.0 - q) - 6.0 * p4(2.0 - q) + 15.0 * p4(1.0 - q));
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const double breakpoints[] = {1.0, 2.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "morris_quintic_359",
    .title = "Quintic spline with the 3D constant 3/(359 pi)",
    .reference = "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214",
    .support = 3.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .breakpoint_count = 2u,
    .breakpoints = breakpoints,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
