/* The kiosk's messages to the service manager (systemd's notify protocol, kiosk/bentray-kiosk.service
 * is Type=notify with a watchdog): that the first frame is on screen, that the loop still runs,
 * what it shows, that it is stopping. Outside systemd (NOTIFY_SOCKET unset: a terminal, the tests)
 * each call does nothing and returns 0, so the loop calls them unconditionally.
 *
 * Each returns 1 when a message went out, 0 when none was due, or a negative errno when sending
 * failed (the caller logs it and goes on; a watchdog message that failed is tried again on the
 * next call). */
#ifndef BT_KIOSK_SERVICE_H
#define BT_KIOSK_SERVICE_H

/* The largest status text sent; longer text is cut. */
#define SERVICE_STATUS_LEN 200

/* READY=1, once: call it after each frame shown; only the first call sends (until
 * service_reset). Until it is sent, systemd counts the kiosk as starting. */
int service_ready(void);

/* WATCHDOG=1 when 1/SERVICE_WATCHDOG_FRACTION of the watchdog interval (WatchdogSec=, from
 * sd_watchdog_enabled) has passed since the last one sent, so that calling it every frame costs a
 * clock read and a slow turn of the loop has nearly the whole interval. Nothing when the unit has
 * no watchdog or it is meant for another process (WATCHDOG_PID). */
#define SERVICE_WATCHDOG_FRACTION 20
int service_watchdog(void);

/* STATUS=text, printf-style: what `systemctl status` shows beside the unit. Line breaks in the
 * text become blanks (a line break would start another message field). Send it when the state
 * changes, not every frame: each message wakes the service manager. */
int service_status(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* STOPPING=1: the kiosk has begun to shut down (SIGTERM, q); sent before the display is put
 * back. */
int service_stopping(void);
/* EXTEND_TIMEOUT_USEC: the start-up (before READY) may take this many seconds more, for a kiosk
 * waiting for its monitor; 1 sent, 0 not under systemd, negative errno. */
int service_extend_timeout(double seconds);

/* Forgets what was sent and reads the environment (NOTIFY_SOCKET, WATCHDOG_USEC, WATCHDOG_PID)
 * again on the next call. For tests, which change the environment between cases. */
void service_reset(void);

#endif
