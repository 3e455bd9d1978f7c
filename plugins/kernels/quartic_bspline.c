/* Quartic B-spline M5 (Schoenberg 1946; Monaghan & Lattanzio 1985), R = 2.5 in the usual
   convention W = sigma_D f(q) / h^D, f(q) = (5/2 - q)^4_+ - 5 (3/2 - q)^4_+ + 10 (1/2 - q)^4_+,
   with the exact sigma_D = 1/24, 96/(1199 pi), 1/(20 pi) (a test integrates them). */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 1.0 / 24.0 : dim == 2 ? 96.0 / (1199.0 * PI) : 1.0 / (20.0 * PI); }
static double p4(double x) { return x > 0.0 ? x * x * x * x : 0.0; }
static double p3(double x) { return x > 0.0 ? x * x * x : 0.0; }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return sigma(dim) * (p4(2.5 - q) - 5.0 * p4(1.5 - q) + 10.0 * p4(0.5 - q));
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return -4.0 * sigma(dim) * (p3(2.5 - q) - 5.0 * p3(1.5 - q) + 10.0 * p3(0.5 - q));
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const double breakpoints[] = {0.5, 1.5};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "quartic_bspline",
    .title = "Quartic B-spline M5",
    .reference = "Schoenberg, Q. Appl. Math. 4 (1946) 45; Monaghan & Lattanzio, Astron. Astrophys. 149 (1985) 135",
    .support = 2.5,
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
