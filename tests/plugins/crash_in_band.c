/* A deliberately broken kernel plugin that passes its probe: a segmentation fault in W for q in (0.51, 0.54), between the probe's points */
#define BROKEN_NAME "crash_in_band"
#define BROKEN_FAULT(q, k) if ((q) > 0.51 && (q) < 0.54) { volatile int* nowhere = (int*)0; return *nowhere; }
#include "broken_cubic.h"
