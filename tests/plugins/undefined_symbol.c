/* Wendland C2 that also calls a function no library defines, as a plugin whose author forgot
 * to link a library: the dynamic loader refuses it, and the error must say which symbol. */
#define WENDLAND_NAME "undefined_symbol"
#define WENDLAND_TITLE "needs a symbol nobody defines"
#include "wendland_c2_plugin.h"

double sphkern_test_function_nobody_defines(double q);

SPHKERN_PLUGIN_EXPORT double undefined_symbol_helper(double q) { return sphkern_test_function_nobody_defines(q); }
