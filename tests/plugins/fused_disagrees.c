/* A deliberately broken kernel plugin for the loader tests: its fused W and W'
 * (sphkern.fused_evaluation.1) give W' with the wrong sign past q = 0.5. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q < 1.0 ? 1.0 - q * q : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q < 1.0 ? -2.0 * q : 0.0;
}

static double wrong_dw(double q, int dim, double k, const double* p) { return q > 0.5 ? -dw(q, dim, k, p) : dw(q, dim, k, p); }

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, wrong_dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "fused_disagrees",
    .title = "broken",
    .reference = "",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(2),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
