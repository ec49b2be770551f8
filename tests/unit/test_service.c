/* The kiosk's messages to systemd, received the way systemd receives them: a unix datagram socket
 * named by NOTIFY_SOCKET (here in a temporary directory), one datagram per message. Checks what is
 * sent (READY=1 once, WATCHDOG=1 rate-limited to a twentieth of the interval, STATUS=text on one line,
 * STOPPING=1), that a watchdog meant for another process is left alone, that a failed send is
 * tried again, and that without NOTIFY_SOCKET every call does nothing and succeeds. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>
#include "kiosk/service.h"

#define MAX_MESSAGES 8
#define MESSAGE_LEN 512

static char dir[256];
static char socket_path[sizeof dir + 16];
static int listener = -1;

/* A datagram socket bound at path, or -1. */
static int bind_datagram(const char *path)
{
    struct sockaddr_un addr;
    memset(&addr, 0, sizeof addr);
    addr.sun_family = AF_UNIX;
    if (strlen(path) >= sizeof addr.sun_path)
        return -1;
    strcpy(addr.sun_path, path);
    int fd = socket(AF_UNIX, SOCK_DGRAM, 0);
    if (fd < 0)
        return -1;
    if (bind(fd, (const struct sockaddr *)&addr, sizeof addr) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

/* Every datagram waiting on fd, without blocking (a datagram sent to a unix socket is queued
 * before sendmsg returns); returns how many. */
static int receive_all(int fd, char messages[MAX_MESSAGES][MESSAGE_LEN])
{
    int n = 0;
    for (;;) {
        char buf[MESSAGE_LEN];
        ssize_t got = recv(fd, buf, sizeof buf - 1, MSG_DONTWAIT);
        if (got < 0) {
            assert_true(errno == EAGAIN || errno == EWOULDBLOCK);
            return n;
        }
        assert_true(n < MAX_MESSAGES);
        buf[got] = '\0';
        strcpy(messages[n++], buf);
    }
}

static void set_watchdog(const char *usec, long pid)
{
    char text[32];
    snprintf(text, sizeof text, "%ld", pid);
    assert_int_equal(setenv("WATCHDOG_USEC", usec, 1), 0);
    assert_int_equal(setenv("WATCHDOG_PID", text, 1), 0);
}

static int group_setup(void **state)
{
    (void)state;
    const char *tmp = getenv("TMPDIR");
    /* sun_path holds 108 bytes: a long TMPDIR falls back to /tmp */
    if (!tmp || !tmp[0] || strlen(tmp) > 64)
        tmp = "/tmp";
    snprintf(dir, sizeof dir, "%s/bt_notify_XXXXXX", tmp);
    if (!mkdtemp(dir)) {
        fprintf(stderr, "test_service: mkdtemp %s: %s\n", dir, strerror(errno));
        return -1;
    }
    snprintf(socket_path, sizeof socket_path, "%s/notify", dir);
    listener = bind_datagram(socket_path);
    if (listener < 0) {
        fprintf(stderr, "test_service: binding %s: %s\n", socket_path, strerror(errno));
        rmdir(dir);
        return -1;
    }
    return 0;
}

static int group_teardown(void **state)
{
    (void)state;
    if (listener >= 0)
        close(listener);
    unlink(socket_path);
    rmdir(dir);
    return 0;
}

/* Each case starts with NOTIFY_SOCKET at the listener, no watchdog, nothing queued and nothing
 * remembered as sent. */
static int case_setup(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    receive_all(listener, messages);
    unsetenv("WATCHDOG_USEC");
    unsetenv("WATCHDOG_PID");
    setenv("NOTIFY_SOCKET", socket_path, 1);
    service_reset();
    return 0;
}

static void test_ready_once(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    assert_int_equal(service_ready(), 1);
    assert_int_equal(service_ready(), 0);             /* the second frame: nothing more */
    assert_int_equal(receive_all(listener, messages), 1);
    assert_string_equal(messages[0], "READY=1");
}

/* The loop calls it every frame: two calls in quick succession send one datagram. The interval
 * is a minute, so that the second call lies within half of it however slow the machine. */
static void test_watchdog_rate_limited(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    set_watchdog("60000000", (long)getpid());
    assert_int_equal(service_watchdog(), 1);
    assert_int_equal(service_watchdog(), 0);
    assert_int_equal(receive_all(listener, messages), 1);
    assert_string_equal(messages[0], "WATCHDOG=1");
}

/* Once a twentieth of the interval has passed the next call sends again: an interval of 200 ms
 * and a pause of 15 ms (only a lower bound on the time passed matters, so a busy machine cannot
 * fail it). Half the interval, the rule before, sent nothing for 100 ms: a turn of the loop that
 * began just then had only half of WatchdogSec before the kiosk was taken as hung. */
static void test_watchdog_after_twentieth_of_interval(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    set_watchdog("200000", (long)getpid());
    assert_int_equal(service_watchdog(), 1);
    struct timespec pause = {.tv_sec = 0, .tv_nsec = 15 * 1000 * 1000};
    while (nanosleep(&pause, &pause) != 0 && errno == EINTR) {
    }
    assert_int_equal(service_watchdog(), 1);
    assert_int_equal(receive_all(listener, messages), 2);
    assert_string_equal(messages[0], "WATCHDOG=1");
    assert_string_equal(messages[1], "WATCHDOG=1");
}

/* WATCHDOG_PID names another process (the watchdog was set for a parent): not ours to feed.
 * Without WATCHDOG_USEC there is no watchdog at all. Other messages still go out. */
static void test_watchdog_not_ours(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    set_watchdog("60000000", (long)getppid());
    assert_int_equal(service_watchdog(), 0);
    unsetenv("WATCHDOG_USEC");
    unsetenv("WATCHDOG_PID");
    service_reset();
    assert_int_equal(service_watchdog(), 0);
    assert_int_equal(service_ready(), 1);
    assert_int_equal(receive_all(listener, messages), 1);
    assert_string_equal(messages[0], "READY=1");
}

static void test_status(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    assert_int_equal(service_status("scene %s, mass %.2f", "lorenz", 1.5), 1);
    /* a line break would make the rest a field of its own */
    assert_int_equal(service_status("%s", "two\nSTOPPING=1\r"), 1);
    char long_text[SERVICE_STATUS_LEN * 2 + 1];
    memset(long_text, 'x', sizeof long_text - 1);
    long_text[sizeof long_text - 1] = '\0';
    assert_int_equal(service_status("%s", long_text), 1);
    assert_int_equal(receive_all(listener, messages), 3);
    assert_string_equal(messages[0], "STATUS=scene lorenz, mass 1.50");
    assert_string_equal(messages[1], "STATUS=two STOPPING=1 ");
    assert_int_equal(strlen(messages[2]), strlen("STATUS=") + SERVICE_STATUS_LEN);
    assert_int_equal(strncmp(messages[2], "STATUS=xxx", 10), 0);
}

static void test_stopping(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    assert_int_equal(service_stopping(), 1);
    assert_int_equal(receive_all(listener, messages), 1);
    assert_string_equal(messages[0], "STOPPING=1");
}

/* No one listens at NOTIFY_SOCKET yet: READY=1 fails with an errno and is not counted as sent,
 * so the next frame's call sends it once the socket is there. */
static void test_failed_send_is_retried(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    char late_path[sizeof dir + 16];
    snprintf(late_path, sizeof late_path, "%s/late", dir);
    setenv("NOTIFY_SOCKET", late_path, 1);
    int r = service_ready();
    assert_true(r < 0);
    int late = bind_datagram(late_path);
    assert_true(late >= 0);
    assert_int_equal(service_ready(), 1);
    assert_int_equal(service_ready(), 0);
    int n = receive_all(late, messages);
    close(late);
    unlink(late_path);
    assert_int_equal(n, 1);
    assert_string_equal(messages[0], "READY=1");
}

/* Started from a terminal: NOTIFY_SOCKET unset (even with a watchdog in the environment), every
 * call returns 0 and nothing is sent anywhere. */
static void test_without_systemd(void **state)
{
    (void)state;
    char messages[MAX_MESSAGES][MESSAGE_LEN];
    unsetenv("NOTIFY_SOCKET");
    set_watchdog("20000", (long)getpid());
    service_reset();
    for (int frame = 0; frame < 3; frame++) {
        assert_int_equal(service_ready(), 0);
        assert_int_equal(service_watchdog(), 0);
    }
    assert_int_equal(service_status("scene %d", 1), 0);
    assert_int_equal(service_stopping(), 0);
    assert_int_equal(receive_all(listener, messages), 0);
    /* an empty NOTIFY_SOCKET is the same as none */
    setenv("NOTIFY_SOCKET", "", 1);
    service_reset();
    assert_int_equal(service_ready(), 0);
    assert_int_equal(service_status("empty"), 0);
    assert_int_equal(receive_all(listener, messages), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_ready_once, case_setup),
        cmocka_unit_test_setup(test_watchdog_rate_limited, case_setup),
        cmocka_unit_test_setup(test_watchdog_after_twentieth_of_interval, case_setup),
        cmocka_unit_test_setup(test_watchdog_not_ours, case_setup),
        cmocka_unit_test_setup(test_status, case_setup),
        cmocka_unit_test_setup(test_stopping, case_setup),
        cmocka_unit_test_setup(test_failed_send_is_retried, case_setup),
        cmocka_unit_test_setup(test_without_systemd, case_setup),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
