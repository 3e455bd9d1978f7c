/* A deliberately broken kernel plugin that passes its probe: exit(0) in W for k > 1.3, beyond the probe's k */
#include <stdlib.h>
#define BROKEN_NAME "exit_in_w"
#define BROKEN_FAULT(q, k) if ((k) > 1.3) exit(0)
#include "broken_cubic.h"
