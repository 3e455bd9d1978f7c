/* A deliberately broken kernel plugin for the loader tests: a future ABI version */
#define PARABOLA_NAME "wrong_abi"
#define PARABOLA_VERSION .abi_major = 999u, .abi_minor = 0u, .struct_size = (uint32_t)sizeof(sphkern_kernel_descriptor)
#include "parabola_plugin.h"
