/* A deliberately broken kernel plugin that passes its probe: an endless loop in W for k > 1.3 that ignores SIGINT and SIGTERM */
#include <signal.h>
#define BROKEN_NAME "loops_above_k"
#define BROKEN_FAULT(q, k)                                                                                              \
    if ((k) > 1.3) {                                                                                                    \
        signal(SIGINT, SIG_IGN);                                                                                        \
        signal(SIGTERM, SIG_IGN);                                                                                       \
        for (volatile int forever = 1; forever;) {                                                                      \
        }                                                                                                               \
    }
#include "broken_cubic.h"
