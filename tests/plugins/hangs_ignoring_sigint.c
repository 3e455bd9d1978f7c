/* A plugin whose entry point ignores SIGINT and never returns: only its host can stop it. */
#include <signal.h>
#include <sphkern/kernel_plugin.h>

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void)
{
    signal(SIGINT, SIG_IGN);
    signal(SIGTERM, SIG_IGN);
    for (volatile unsigned long i = 0;; ++i) {
    }
    return 0;
}
