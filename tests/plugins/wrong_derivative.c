/* A deliberately broken kernel for `check`: the 1D cubic B-spline with dW/dr 1.5 times too
 * large and a second derivative twice too large. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    double t = 2.0 - q;
    return q <= 1.0 ? 2.0 / 3.0 - q * q + 0.5 * q * q * q : q <= 2.0 ? t * t * t / 6.0 : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    double t = 2.0 - q;
    return 1.5 * (q <= 1.0 ? -2.0 * q + 1.5 * q * q : q <= 2.0 ? -0.5 * t * t : 0.0);
}

static double d2w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return 3.0 * (q <= 1.0 ? -2.0 + 3.0 * q : q <= 2.0 ? 2.0 - q : 0.0);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_BATCH_FROM_SCALAR(d2w_batch, d2w)

static const sphkern_second_derivative second = {.d2w = d2w, .d2w_batch = d2w_batch};

static const void* get_extension(const char* id)
{
    return strcmp(id, SPHKERN_EXTENSION_SECOND_DERIVATIVE) == 0 ? &second : NULL;
}

static const double breakpoints[] = {1.0};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "wrong_derivative", .title = "broken", .reference = "",
    .support = 2.0, .dimensions = SPHKERN_DIM(1),
    .breakpoint_count = 1u, .breakpoints = breakpoints,
    .w = w, .dw = dw, .w_batch = w_batch, .dw_batch = dw_batch,
    .get_extension = get_extension,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
