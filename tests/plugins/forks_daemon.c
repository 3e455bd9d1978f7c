/* Wendland C2 whose constructor forks a daemon, as a careless plugin might: a grandchild in a
 * session of its own, every descriptor closed, which writes its pid to the file named by
 * SPHKERN_TEST_DAEMON_PIDS and sleeps. sphkern must not leave it running when it exits. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <sphkern/kernel_plugin.h>
#include <sphkern/kernel_plugin_helpers.h>

#define PI 3.14159265358979323846

__attribute__((constructor)) static void fork_daemon(void)
{
    const char* record = getenv("SPHKERN_TEST_DAEMON_PIDS");
    if (!record) return;
    pid_t first = fork();
    if (first != 0) return; /* the loading process goes on (the intermediate exits at once) */
    if (setsid() < 0 || fork() != 0) _exit(0);
    for (int fd = 0; fd < 1024; ++fd) close(fd);
    int out = open(record, O_WRONLY | O_APPEND | O_CREAT, 0644);
    if (out >= 0) {
        char line[32];
        int n = snprintf(line, sizeof line, "%d\n", (int)getpid());
        if (write(out, line, (size_t)n) != n) _exit(1);
        close(out);
    }
    sleep(120);
    _exit(0);
}

static double sigma(int dim) { return dim == 2 ? 7.0 / (4.0 * PI) : 21.0 / (16.0 * PI); }

static double w(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    if (q >= 2.0) return 0.0;
    double t = 1.0 - 0.5 * q;
    return sigma(dim) * t * t * t * t * (2.0 * q + 1.0);
}

static double dw(double q, int dim, double k, const double* p)
{
    (void)k; (void)p;
    if (q >= 2.0) return 0.0;
    double t = 1.0 - 0.5 * q;
    return sigma(dim) * -5.0 * q * t * t * t;
}

SPHKERN_BATCH_FROM_SCALAR(w_batch, w)
SPHKERN_BATCH_FROM_SCALAR(dw_batch, dw)

static const sphkern_kernel_descriptor descriptor = {
    SPHKERN_DESCRIPTOR_VERSION,
    .name = "forks_daemon",
    .title = "forks a daemon when it is loaded",
    .reference = "",
    .support = 2.0,
    .dimensions = SPHKERN_DIM(2) | SPHKERN_DIM(3),
    .w = w,
    .dw = dw,
    .w_batch = w_batch,
    .dw_batch = dw_batch,
};

SPHKERN_PLUGIN_EXPORT const sphkern_kernel_descriptor* sphkern_kernel_entry(void) { return &descriptor; }
