/* A deliberately broken kernel plugin for the loader tests: R = 0 */
#define PARABOLA_NAME "zero_support"
#define PARABOLA_SUPPORT 0.0
#include "parabola_plugin.h"
