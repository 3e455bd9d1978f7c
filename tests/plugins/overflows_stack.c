/* A deliberately broken kernel plugin that passes its probe: W recurses without end for k > 1.3
   (beyond the probe's k) and overflows its stack. */
static volatile int bottom = -1; /* never reached: the stack ends first */

static double deeper(double q, int depth)
{
    volatile char frame[1024];
    frame[depth % 1024] = (char)depth;
    if (depth == bottom) return q;
    return deeper(q + frame[0], depth + 1) + frame[depth % 1024]; /* not a tail call */
}

#define BROKEN_NAME "overflows_stack"
#define BROKEN_FAULT(q, k) if ((k) > 1.3) return deeper((q), 0)
#include "broken_cubic.h"
