// A deliberately broken kernel plugin for the loader tests: a C++ exception thrown
// across the C boundary.
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#include <stdexcept>

static double w(double q, int, double, const double*)
{
    if (q > 0.5) throw std::runtime_error("kernel blew up");
    return 1.0 - q * q;
}
static double dw(double q, int, double, const double*) { return -2.0 * q; }
SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "throws_exception",
    .title = "broken",
    .reference = "",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(2),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

extern "C" SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
