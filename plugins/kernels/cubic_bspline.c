/* Cubic B-spline (Monaghan & Lattanzio; paper eq. 8), R = 2. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 1.0 : dim == 2 ? 15.0 / (7.0 * PI) : 3.0 / (2.0 * PI); }

/* Branch-free (?: on both pieces) so that the batch loop vectorises. */
static inline double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    double t = 2.0 - q;
    double inner = 2.0 / 3.0 - q * q + 0.5 * q * q * q, outer = t * t * t * (1.0 / 6.0); /* no division in the hot loop */
    return sigma(dim) * (q <= 1.0 ? inner : q <= 2.0 ? outer : 0.0);
}

static inline double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    double t = 2.0 - q;
    double inner = -2.0 * q + 1.5 * q * q, outer = -0.5 * t * t;
    return sigma(dim) * (q <= 1.0 ? inner : q <= 2.0 ? outer : 0.0);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const double breakpoints[] = {1.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "cubic_bspline",
    .title = "Cubic B-spline",
    .reference = "Monaghan & Lattanzio, Astron. Astrophys. 149 (1985) 135; Potapov & Reshetnikova (2021) eq. 8",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .breakpoint_count = 1u,
    .breakpoints = breakpoints,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
