/* systemd's notify protocol for the kiosk loop, over libsystemd's sd_notify. The environment is
 * read once (the loop calls service_watchdog every frame); what was sent is remembered so that
 * READY=1 goes out once and WATCHDOG=1 no more often than the interval needs. The state is the
 * process's: the functions are called from the loop's thread only. */
#include "kiosk/service.h"
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <systemd/sd-daemon.h>

#define USEC_PER_SEC 1000000u

static struct {
    int env_read;
    int notify;                      /* NOTIFY_SOCKET names a socket: run by systemd */
    uint64_t watchdog_usec;          /* µs, WatchdogSec= of this process; 0: no watchdog */
    int ready_sent;
    int watchdog_sent;
    uint64_t last_watchdog_usec;     /* µs on CLOCK_MONOTONIC, the clock systemd's watchdog runs on */
} svc;

static uint64_t monotonic_usec(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * USEC_PER_SEC + (uint64_t)ts.tv_nsec / 1000u;
}

static void read_environment(void)
{
    if (svc.env_read)
        return;
    const char *notify_socket = getenv("NOTIFY_SOCKET");
    svc.notify = notify_socket && notify_socket[0];
    uint64_t usec = 0;
    /* > 0 only when WATCHDOG_USEC is set and WATCHDOG_PID, if set, is this process: a watchdog
     * inherited from a parent that forked us is not ours to feed */
    svc.watchdog_usec = svc.notify && sd_watchdog_enabled(0, &usec) > 0 ? usec : 0;
    svc.env_read = 1;
}

/* 1 sent, 0 not under systemd, negative errno */
static int send_message(const char *message)
{
    read_environment();
    if (!svc.notify)
        return 0;
    int r = sd_notify(0, message);
    return r > 0 ? 1 : r;
}

int service_ready(void)
{
    read_environment();
    if (!svc.notify || svc.ready_sent)
        return 0;
    int r = send_message("READY=1");
    if (r > 0)
        svc.ready_sent = 1;
    return r;
}

int service_watchdog(void)
{
    read_environment();
    if (!svc.notify || svc.watchdog_usec == 0)
        return 0;
    uint64_t now = monotonic_usec();
    /* every twentieth of the interval (half a second of WatchdogSec=10): a slow turn of the loop
     * then has nearly the whole interval before the service manager takes the kiosk as hung.
     * Half the interval, which sd_watchdog_enabled(3) gives as the least, left a turn that began
     * just before a due datagram only half of it (a scene's shaders compiling on a slow machine). */
    if (svc.watchdog_sent && now - svc.last_watchdog_usec < svc.watchdog_usec / SERVICE_WATCHDOG_FRACTION)
        return 0;
    int r = send_message("WATCHDOG=1");
    if (r > 0) {
        svc.watchdog_sent = 1;
        svc.last_watchdog_usec = now;
    }
    return r;
}

int service_status(const char *fmt, ...)
{
    read_environment();
    if (!svc.notify)
        return 0;
    char message[sizeof "STATUS=" + SERVICE_STATUS_LEN];
    size_t head = strlen("STATUS=");
    memcpy(message, "STATUS=", head);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message + head, sizeof message - head, fmt, ap);
    va_end(ap);
    /* the protocol is one FIELD=value per line: a line break in a scene's name must not become
     * a field of its own (READY=1, STOPPING=1) */
    for (char *c = message + head; *c; c++)
        if (*c == '\n' || *c == '\r')
            *c = ' ';
    return send_message(message);
}

int service_extend_timeout(double seconds)
{
    char message[64];
    snprintf(message, sizeof message, "EXTEND_TIMEOUT_USEC=%llu",
             (unsigned long long)(seconds > 0.0 ? seconds * USEC_PER_SEC : 0.0));
    return send_message(message);
}

int service_stopping(void)
{
    return send_message("STOPPING=1");
}

void service_reset(void)
{
    memset(&svc, 0, sizeof svc);
}
