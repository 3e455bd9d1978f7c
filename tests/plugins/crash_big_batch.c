/* A deliberately broken kernel plugin that passes its probe: its batch W crashes (a segmentation
   fault) for batches of more than 100 values; the probe's batches have 61. */
#define BROKEN_NAME "crash_big_batch"
#define BROKEN_FAULT(q, k)
#define BROKEN_BATCH_FAULT(n, out) if ((n) > 100) { volatile int* nowhere = (int*)0; (out)[0] = *nowhere; }
#include "broken_cubic.h"
