/* Spiky kernel of Desbrun & Gascuel (paper eq. 11, with (2-q)^3: see share/docs/method.md, errata), R = 2. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 1 ? 1.0 / 8.0 : dim == 2 ? 5.0 / (16.0 * PI) : 15.0 / (64.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return q <= 2.0 ? sigma(dim) * (2.0 - q) * (2.0 - q) * (2.0 - q) : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    return q <= 2.0 ? -3.0 * sigma(dim) * (2.0 - q) * (2.0 - q) : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "desbrun_spiky",
    .title = "Spiky kernel (Desbrun)",
    .reference = "Desbrun & Gascuel, Computer Animation and Simulation '96, 61; Potapov & Reshetnikova (2021) eq. 11",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(1) | SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
