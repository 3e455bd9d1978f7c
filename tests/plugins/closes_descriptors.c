/* Wendland C2 whose constructor closes descriptors 3 to 63 and moves the process to the root
 * folder when it is loaded: the host must still find its working folder, without a descriptor
 * the plugin could have closed under it. */
#include <unistd.h>

__attribute__((constructor)) static void close_and_move(void)
{
    for (int fd = 3; fd < 64; ++fd) close(fd);
    if (chdir("/") != 0) return;
}

#define WENDLAND_NAME "closes_descriptors"
#define WENDLAND_TITLE "closes descriptors 3 to 63 and moves the process to /"
#include "wendland_c2_plugin.h"
