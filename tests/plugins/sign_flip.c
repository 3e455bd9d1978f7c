/* A kernel whose parameter p may flip its sign: W = (2 - p) W_0, valid only for p < 2,
 * though the declared range is [0, 5]. The default (p = 1) is fine. */
#include <math.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

/* 3D Epanechnikov-like W_0 = c (1 - q^2) on q < 1, c = 15 / (8 pi). */
static const double c = 15.0 / (8.0 * 3.14159265358979323846);

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k;
    return q < 1.0 ? (2.0 - p[0]) * c * (1.0 - q * q) : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k;
    return q < 1.0 ? -(2.0 - p[0]) * c * 2.0 * q : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_parameter parameters[] = {{"p", "scale (2 - p)", 1.0, 0.0, 5.0}};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "sign_flip",
    .title = "broken",
    .reference = "",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(3),
    .parameter_count = 1u,
    .parameters = parameters,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
