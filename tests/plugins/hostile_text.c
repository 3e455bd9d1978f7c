/* A kernel plugin whose strings are hostile: a title that is not UTF-8 and a reference with
 * terminal escape sequences. The kernel itself is a valid 1D quadratic. */
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q <= 1.0 ? 1.5 * (1.0 - q) * (1.0 - q) : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q <= 1.0 ? -3.0 * (1.0 - q) : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "hostile_text", .title = "bad \xff\xfe title", .reference = "\x1b[2J\x1b]0;owned\x07 ref",
    .support = 1.0, .dimensions = SPHKERN_DIM(1),
    .w = w, .dw = dw, .w_batch = w_batch, .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
