/* Wendland C2 whose constructor forks a daemon, as a careless plugin might: a grandchild in a
 * session of its own, which writes its pid to the file named by SPHKERN_TEST_DAEMON_PIDS,
 * closes every descriptor and sleeps. sphkern must not leave it running when it exits. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

__attribute__((constructor)) static void fork_daemon(void)
{
    const char* record = getenv("SPHKERN_TEST_DAEMON_PIDS");
    int ready[2];
    if (!record || pipe(ready) != 0) return;
    pid_t first = fork();
    if (first != 0) {
        /* The loading process goes on once the daemon has written its pid (the intermediate
         * exits at once): a fast sphkern must not end before there is a daemon to find. */
        char byte;
        close(ready[1]);
        if (read(ready[0], &byte, 1) < 0) byte = 0;
        close(ready[0]);
        return;
    }
    if (setsid() < 0 || fork() != 0) _exit(0);
    int out = open(record, O_WRONLY | O_APPEND | O_CREAT, 0644);
    if (out >= 0) {
        char line[32];
        int n = snprintf(line, sizeof line, "%d\n", (int)getpid());
        if (write(out, line, (size_t)n) != n) _exit(1);
        close(out);
    }
    if (write(ready[1], "r", 1) != 1) _exit(1);
    for (int fd = 0; fd < 1024; ++fd) close(fd);
    sleep(120);
    _exit(0);
}

#define WENDLAND_NAME "forks_daemon"
#define WENDLAND_TITLE "forks a daemon when it is loaded"
#include "wendland_c2_plugin.h"
