/* The keyboard input: keys typed on the terminal the kiosk was started from (service and
 * development; an X11 window's keys come through the screen instead). The terminal is put into
 * non-canonical mode without echo, so that a key acts at once, and restored at close. Standard
 * input that is not a terminal (a pipe, /dev/null under the service manager) is read as keys
 * until it ends. */
#include "input/input.h"
#include "input/keymap.h"
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

struct keyboard {
    int fd;
    int is_tty;
    struct termios saved;
    int saved_flags;
    int ended;                       /* end of input: nothing more to poll */
    /* the start of an escape sequence (ESC, or ESC '[') that the last read ended in: a terminal may
     * split "ESC [ A" across reads, and a lone ESC is the Escape key, which stops the kiosk */
    unsigned char pending[2];
    int n_pending;
};

static int keyboard_fds(struct input_source *src, struct pollfd *out, int max)
{
    struct keyboard *k = src->priv;
    if (k->ended || max < 1)
        return 0;
    out[0].fd = k->fd;
    out[0].events = POLLIN;
    out[0].revents = 0;
    return 1;
}

/* One key from the bytes read: arrows arrive as ESC [ A..D; a lone ESC is the Escape key. Returns
 * -1 when the bytes end inside an escape sequence (more may follow), 0 for bytes that are no key,
 * 1 for a key. */
static int next_key(const unsigned char *buf, int len, int *used, enum key_code *code, int *ch)
{
    *ch = buf[0];
    *code = KEY_CODE_CHAR;
    *used = 1;
    if (buf[0] != 0x1b)
        return 1;
    if (len == 1 || (len == 2 && buf[1] == '['))
        return -1;
    if (buf[1] == '[') {
        static const char arrows[] = "ABCD";
        static const enum key_code codes[] = {KEY_CODE_UP, KEY_CODE_DOWN, KEY_CODE_RIGHT, KEY_CODE_LEFT};
        const char *at = memchr(arrows, buf[2], 4);
        *used = 3;
        if (!at)
            return 0;
        *code = codes[at - arrows];
        return 1;
    }
    *code = KEY_CODE_ESCAPE;
    return 1;
}

static int emit(struct input_source *src, double now, enum key_code code, int ch, struct input_event *ev)
{
    if (!keymap_event(code, ch, ev))
        return 0;
    ev->t = now;
    ev->source = src->index;
    return 1;
}

static int keyboard_drain(struct input_source *src, double now, struct input_event *out, int max)
{
    struct keyboard *k = src->priv;
    int n = 0, read_any = 0;
    /* at least one whole escape sequence of room, so that nothing read is dropped */
    while (!k->ended && max - n >= 3) {
        unsigned char buf[64];
        memcpy(buf, k->pending, (size_t)k->n_pending);
        size_t room = (size_t)(max - n) < sizeof buf - 2 ? (size_t)(max - n) : sizeof buf - 2;
        ssize_t got = read(k->fd, buf + k->n_pending, room);
        if (got < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
            /* held back since the last drain and nothing followed: a lone ESC is the Escape key (an
             * unfinished ESC '[' is nothing) */
            if (!read_any) {
                if (k->n_pending == 1)
                    n += emit(src, now, KEY_CODE_ESCAPE, 0x1b, &out[n]);
                k->n_pending = 0;
            }
            break;
        }
        struct pollfd hup = {.fd = k->fd, .events = POLLIN, .revents = 0};
        if (got == 0 && k->is_tty && !(poll(&hup, 1, 0) > 0 && (hup.revents & (POLLHUP | POLLERR | POLLNVAL)))) {
            /* a terminal answers 0 when nothing is waiting (where its VMIN was reset to 0) as well as
             * when it hung up; only a hang-up, which poll reports, ends the keyboard */
            if (!read_any && k->n_pending == 1)
                n += emit(src, now, KEY_CODE_ESCAPE, 0x1b, &out[n]);
            if (!read_any)
                k->n_pending = 0;
            break;
        }
        if (got <= 0) {
            k->ended = 1;
            src->finished = 1;
            if (got < 0)
                fprintf(src->log, "input %s: reading the keyboard failed: %s; keys are no longer read\n",
                        src->cfg->name, strerror(errno));
            else
                fprintf(src->log, "input %s: the keyboard's input ended; keys are no longer read\n",
                        src->cfg->name);
            break;
        }
        read_any = 1;
        int len = (int)got + k->n_pending;
        k->n_pending = 0;
        for (int i = 0; i < len && n < max;) {
            enum key_code code;
            int ch, used;
            int key = next_key(buf + i, len - i, &used, &code, &ch);
            if (key < 0) {
                k->n_pending = len - i;
                memcpy(k->pending, buf + i, (size_t)k->n_pending);
                break;
            }
            if (key > 0)
                n += emit(src, now, code, ch, &out[n]);
            i += used;
        }
    }
    return n;
}

static void keyboard_close(struct input_source *src)
{
    struct keyboard *k = src->priv;
    if (k->is_tty)
        tcsetattr(k->fd, TCSANOW, &k->saved);
    if (k->saved_flags >= 0)
        fcntl(k->fd, F_SETFL, k->saved_flags);
    free(k);
}

struct input_source *input_open_keyboard(const struct kiosk_input *in, int index, FILE *log, double now)
{
    (void)now;
    struct input_source *src =
        input_source_new(in, index, log, sizeof(struct keyboard), keyboard_fds, keyboard_drain, keyboard_close);
    if (!src)
        return NULL;
    struct keyboard *k = src->priv;
    k->fd = STDIN_FILENO;
    k->saved_flags = fcntl(k->fd, F_GETFL);
    if (k->saved_flags < 0) {
        fprintf(log, "input %s: there is no standard input to read keys from\n", src->cfg->name);
        k->ended = 1;
        src->finished = 1;
        return src;
    }
    fcntl(k->fd, F_SETFL, k->saved_flags | O_NONBLOCK);
    if (isatty(k->fd) && tcgetattr(k->fd, &k->saved) == 0) {
        struct termios raw = k->saved;
        raw.c_lflag &= ~(tcflag_t)(ICANON | ECHO);
        /* VMIN 1 with O_NONBLOCK: a terminal with no key waiting answers EAGAIN, as a pipe does;
         * with VMIN 0 it would answer 0, which reads as the end of input */
        raw.c_cc[VMIN] = 1;
        raw.c_cc[VTIME] = 0;
        k->is_tty = tcsetattr(k->fd, TCSANOW, &raw) == 0;
    }
    src->present = 1;
    return src;
}
