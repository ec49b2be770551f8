/* libFuzzer harness: the kiosk's configuration file, which exhibition staff edit.
 *
 * The input is a configuration file: kiosk_config_load(), then, when it loaded, kiosk_config_check(),
 * as the kiosk does at start. Beyond the sanitizers:
 *  - every refusal says why: a NUL-terminated, non-empty message and place;
 *  - what the check accepts, the kiosk can use: start_scene names a listed scene, the knobs' and
 *    buttons' inputs exist, every hid input gives a report layout (input_hid_layout(), as the
 *    kiosk's HID source builds it) that hid_layout_check() accepts,
 *    every gpio_encoder's counts_per_detent is one quadrature_init() takes and every gpio_button's
 *    debounce window one debounce_init() takes. A configuration that passes the check but that
 *    the input decoders refuse would stop the kiosk after start, where nobody reads the message.
 *
 * kiosk_config_load() reads a path: the input goes to one temporary file per process, made at start
 * in $BT_FUZZ_TMPDIR (else $TMPDIR, else /tmp), rewritten for every input and removed at exit.
 * Relative paths in the file (scenes, font, log, assets_root) resolve against that directory: make
 * fuzz runs this harness in a directory whose ../assets is the project's, as for kiosk/kiosk.conf. */
#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>
#include "fuzz_input_file.h"
#include "input/debounce.h"
#include "input/hid_report.h"
#include "input/input_hid_decode.h"
#include "kiosk_config/kiosk_config.h"
#include "input/quadrature.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* ---- the harness ------------------------------------------------------------------------------ */

static struct kiosk_config config;  /* about 45 KB: not on the stack */
static struct error err;

static void check_refusal(const struct error *e)
{
    if (memchr(e->where, '\0', sizeof e->where) == NULL ||
        memchr(e->message, '\0', sizeof e->message) == NULL || e->message[0] == '\0')
        __builtin_trap();
}

/* What a configuration that passed kiosk_config_check() promises the kiosk. */
static void check_accepted(const struct kiosk_config *c)
{
    if (c->kiosk.n_scenes < 1 || c->kiosk.n_scenes > KIOSK_MAX_SCENES || c->kiosk.start_scene < 0 ||
        c->kiosk.start_scene >= c->kiosk.n_scenes)
        __builtin_trap();
    if (c->n_inputs < 0 || c->n_inputs > KIOSK_MAX_INPUTS || c->n_buttons < 0 ||
        c->n_buttons > KIOSK_MAX_BUTTONS)
        __builtin_trap();
    if (kiosk_config_input(c, c->speed.input) == NULL || kiosk_config_input(c, c->mass.input) == NULL)
        __builtin_trap();
    for (int i = 0; i < c->n_buttons; i++)
        if (kiosk_config_input(c, c->buttons[i].input) == NULL ||
            kiosk_action_name(c->buttons[i].action) == NULL)
            __builtin_trap();
    for (int i = 0; i < c->n_inputs; i++) {
        const struct kiosk_input *in = &c->inputs[i];
        if (kiosk_input_type_name(in->type) == NULL)
            __builtin_trap();
        if (in->type == KIOSK_INPUT_HID) {
            struct hid_layout l;
            struct error why;
            if (in->buttons > HID_MAX_BUTTONS)
                __builtin_trap();
            /* the layout the kiosk's HID source reads the device with */
            if (input_hid_layout(in, &l, &why) != 0)
                __builtin_trap();
        } else if (in->type == KIOSK_INPUT_GPIO_ENCODER) {
            struct quadrature q;
            if (quadrature_init(&q, in->counts_per_detent, 0, 0) != 0)
                __builtin_trap();
        } else if (in->type == KIOSK_INPUT_GPIO_BUTTON) {
            struct debounce d;
            if (in->debounce_ms < 0 ||
                debounce_init(&d, (uint64_t)in->debounce_ms * 1000000u, !in->active_low, 1) != 0)
                __builtin_trap();
        }
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    tmp_create("kiosk");
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tmp_write(data, size);
    if (kiosk_config_load(&config, tmp_path, &err) != 0) {
        check_refusal(&err);
        return 0;
    }
    if (kiosk_config_check(&config, &err) != 0) {
        check_refusal(&err);
        return 0;
    }
    check_accepted(&config);
    return 0;
}
