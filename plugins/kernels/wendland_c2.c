/* Wendland C2, support 2h as in PySPH and DualSPHysics; 2D and 3D only. Zero past R. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double sigma(int dim) { return dim == 2 ? 7.0 / (4.0 * PI) : 21.0 / (16.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    if (q >= 2.0) return 0.0;
    double t = 1.0 - 0.5 * q;
    double t3 = t * t * t;
    return sigma(dim) * t3 * t * (2.0 * q + 1.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    if (q >= 2.0) return 0.0;
    double t = 1.0 - 0.5 * q;
    double t3 = t * t * t;
    return sigma(dim) * -5.0 * q * t3;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "wendland_c2",
    .title = "Wendland C2",
    .reference = "Wendland, Adv. Comput. Math. 4 (1995) 389; Dehnen & Aly, MNRAS 425 (2012) 1068",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
