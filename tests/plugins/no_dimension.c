/* A deliberately broken kernel plugin for the loader tests: no supported dimension */
#define PARABOLA_NAME "no_dimension"
#define PARABOLA_DIMENSIONS 0u
#include "parabola_plugin.h"
