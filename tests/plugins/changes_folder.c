/* Wendland C2 whose constructor moves the process to the root folder when it is loaded: a
 * relative output path given on the command line must still mean the folder it was given in. */
#include <unistd.h>

__attribute__((constructor)) static void move_away(void)
{
    if (chdir("/") != 0) return;
}

#define WENDLAND_NAME "changes_folder"
#define WENDLAND_TITLE "moves the process to /"
#include "wendland_c2_plugin.h"
