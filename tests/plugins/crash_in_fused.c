/* A deliberately broken kernel plugin that passes its probe: its fused W and W'
   (sphkern.fused_evaluation.1) crash (a segmentation fault) on a batch whose length is a
   multiple of 8, as the particle engine's are; the probe's batches have 61 values. */
#include <string.h>
#define BROKEN_NAME "crash_in_fused"
#define BROKEN_FAULT(q, k)
#define BROKEN_EXTENSION extensions
#include "broken_cubic.h"

static void w_dw(const double* q, double* w_out, double* dw_out, size_t n, int dim, double k, const double* p)
{
    if (n % 8 == 0) {
        volatile int* nowhere = (int*)0;
        w_out[0] = *nowhere;
    }
    for (size_t i = 0; i < n; ++i) w_out[i] = w(q[i], dim, k, p), dw_out[i] = dw(q[i], dim, k, p);
}
SPHKERN_FUSED_EXTENSION(extensions, w_dw)
