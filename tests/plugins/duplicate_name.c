/* A deliberately broken kernel plugin for the loader tests: the name of a shipped kernel */
#define PARABOLA_NAME "cubic_bspline"
#define PARABOLA_SUPPORT 2.0
#include "parabola_plugin.h"
