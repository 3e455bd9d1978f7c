/* A deliberately broken kernel plugin that passes its probe: abort() in W for k > 1.3, beyond the probe's k */
#include <stdlib.h>
#define BROKEN_NAME "abort_above_k"
#define BROKEN_FAULT(q, k) if ((k) > 1.3) abort()
#include "broken_cubic.h"
