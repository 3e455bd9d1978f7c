/* A deliberately broken kernel plugin for the loader tests: an endless loop inside W */
#define PARABOLA_NAME "endless_loop"
#define PARABOLA_W_BODY(q) volatile int forever = 1; while (forever && q > 0.5) {} return 1.0 - q * q;
#include "parabola_plugin.h"
