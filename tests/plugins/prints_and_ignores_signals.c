/* A valid kernel whose library misbehaves around it: it prints on stdout when loaded and
 * when asked for its descriptor, and ignores SIGINT, SIGTERM and SIGHUP from then on. */
#include <signal.h>
#include <stdio.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

__attribute__((constructor)) static void on_load(void)
{
    printf("hello from a plugin's constructor\n");
    fflush(stdout);
    signal(SIGINT, SIG_IGN);
    signal(SIGTERM, SIG_IGN);
    signal(SIGHUP, SIG_IGN);
}

static double w(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q < 1.0 ? 15.0 / (8.0 * 3.14159265358979323846) * (1.0 - q * q) : 0.0;
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)dim; (void)k; (void)p;
    return q < 1.0 ? -15.0 / (4.0 * 3.14159265358979323846) * q : 0.0;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "noisy",
    .title = "prints and ignores signals",
    .reference = "",
    .support = 1.0,
    .dimensions = SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void)
{
    printf("hello from sphkern_kernel_entry\n");
    fflush(stdout);
    return &descriptor;
}
