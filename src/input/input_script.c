/* The script input: a file of timestamped events replayed from the moment the kiosk starts. The
 * file was checked when the kiosk started (kiosk_inputs_check), so a failure here is rare: it is
 * logged and the source stays silent. */
#include "input/script_player.h"
#include <stdlib.h>

struct script_source {
    struct script script;
    struct script_player player;
};

static int script_fds(struct input_source *src, struct pollfd *out, int max)
{
    (void)src;
    (void)out;
    (void)max;
    return 0;
}

static int script_drain(struct input_source *src, double now, struct input_event *out, int max)
{
    struct script_source *s = src->priv;
    if (!src->present)
        return 0;
    int n = script_player_due(&s->player, now, src->index, out, max);
    src->finished = script_player_done(&s->player);
    return n;
}

static void script_close(struct input_source *src)
{
    free(src->priv);
}

struct input_source *input_open_script(const struct kiosk_input *in, int index, FILE *log, double now)
{
    struct input_source *src =
        input_source_new(in, index, log, sizeof(struct script_source), script_fds, script_drain, script_close);
    if (!src)
        return NULL;
    struct script_source *s = src->priv;
    struct error e;
    if (script_load(&s->script, src->cfg->path, &e) != 0) {
        char err[600];
        error_format(&e, err, sizeof err);
        fprintf(log, "input %s: %s; the script is not replayed\n", src->cfg->name, err);
        src->finished = 1;
        return src;
    }
    script_player_start(&s->player, &s->script, now, 0);
    src->present = 1;
    return src;
}
