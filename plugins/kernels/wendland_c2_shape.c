/* A one-parameter family around Wendland C2 (support 2h, 2D and 3D):
 *     f(q) = (1 - q/2)^4 (1 + 2q + beta q^2),
 * beta = 0 is Wendland C2. beta changes the kernel's shape, not only its width, so
 * eps_rho and eps_gradP move differently and can vanish together (sphkern design).
 * sigma_D(beta) = 1 / (S_D (I_{D-1} + 2 I_D + beta I_{D+1})), with
 * I_n = integral_0^2 q^n (1 - q/2)^4 dq = 2^(n+1) n! 4! / (n+5)!. */
#include <string.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

static double moment(int n) /* I_n */
{
    double value = 2.0 * 24.0; /* 2^(n+1) n! 4! / (n+5)! built up step by step */
    for (int i = 1; i <= n; ++i) value *= 2.0 * i;
    for (int i = 1; i <= n + 5; ++i) value /= i;
    return value;
}

static double sigma(int dim, double beta)
{
    double area = dim == 2 ? 2.0 * PI : 4.0 * PI;
    return 1.0 / (area * (moment(dim - 1) + 2.0 * moment(dim) + beta * moment(dim + 1)));
}

static inline double w(double q, int dim, double k, const double* p)
{
    (void)k;
    double t = q < 2.0 ? 1.0 - 0.5 * q : 0.0;
    double t2 = t * t;
    return sigma(dim, p[0]) * t2 * t2 * (1.0 + 2.0 * q + p[0] * q * q);
}

static inline double dw(double q, int dim, double k, const double* p)
{
    (void)k;
    double t = q < 2.0 ? 1.0 - 0.5 * q : 0.0;
    double shape = 1.0 + 2.0 * q + p[0] * q * q, slope = 2.0 + 2.0 * p[0] * q;
    return sigma(dim, p[0]) * t * t * t * (-2.0 * shape + t * slope);
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)
SPHKERN_FUSED_FROM_SCALAR(w_dw, w, dw)
SPHKERN_FUSED_EXTENSION(extensions, w_dw)

static const sphkern_kernel_parameter parameters[] = {
    {"beta", "weight of q^2 in the polynomial factor; 0 is Wendland C2", 0.0, -1.0, 10.0}};

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "wendland_c2_shape",
    .title = "Wendland C2 family (1 - q/2)^4 (1 + 2q + beta q^2)",
    .reference = "Wendland, Adv. Comput. Math. 4 (1995) 389 (beta = 0); the family is sphkern's",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .parameter_count = 1u,
    .parameters = parameters,
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
    .get_extension = extensions,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
