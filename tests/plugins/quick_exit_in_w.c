/* A deliberately broken kernel plugin that passes its probe: _exit(0) in W for k > 1.3, beyond
 * the probe's k. No atexit handler runs for _exit: only the redirected call can report it. */
#include <unistd.h>
#define BROKEN_NAME "quick_exit_in_w"
#define BROKEN_FAULT(q, k) if ((k) > 1.3) _exit(0)
#include "broken_cubic.h"
