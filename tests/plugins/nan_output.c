/* A deliberately broken kernel plugin for the loader tests: NaN for q > 0.7 */
#define PARABOLA_NAME "nan_output"
#define PARABOLA_W_BODY(q) return q > 0.7 ? NAN : 1.0 - q * q;
#include "parabola_plugin.h"
