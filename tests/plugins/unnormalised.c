/* A deliberately broken kernel plugin for the loader tests: valid but not normalised (check must fail it) */
#define PARABOLA_NAME "unnormalised"
#define PARABOLA_W_BODY(q) return q <= 1.0 ? 1.0 - q * q : 0.0;
#include "parabola_plugin.h"
