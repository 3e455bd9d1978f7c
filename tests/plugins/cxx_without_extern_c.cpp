// A deliberately broken kernel plugin for the loader tests: a C++ entry function without
// extern "C", so the library exports only its mangled name.
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int, double, const double*) { return q <= 1.0 ? 1.5 * (1.0 - q) * (1.0 - q) : 0.0; }
static double dw(double q, int, double, const double*) { return q <= 1.0 ? -3.0 * (1.0 - q) : 0.0; }

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "cxx_without_extern_c",
    .title = "broken",
    .reference = "",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(1),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry() { return &descriptor; }
