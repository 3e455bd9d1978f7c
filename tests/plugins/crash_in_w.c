/* A deliberately broken kernel plugin for the loader tests: a segmentation fault inside W */
#define PARABOLA_NAME "crash_in_w"
#define PARABOLA_W_BODY(q) volatile int* nowhere = (int*)0; return q > 0.5 ? *nowhere : 1.0 - q * q;
#include "parabola_plugin.h"
