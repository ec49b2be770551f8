/* The exhibition kiosk's configuration: which scenes it shows, how it draws them, and which knobs
 * and buttons drive it. Read from an INI file (kiosk/kiosk.conf documents every key) by
 * kiosk_config_load(), then checked as a whole by kiosk_config_check(): the kiosk runs unattended,
 * so anything doubtful is refused at start with FILE:LINE rather than guessed at. */
#ifndef BT_KIOSK_CONFIG_H
#define BT_KIOSK_CONFIG_H
#include <stdint.h>
#include "conf/conf_reader.h"
#include "display/display_settings.h"
#include "input/input_settings.h"

#define KIOSK_MAX_SCENES 32
#define KIOSK_MAX_BUTTONS 16
#define KIOSK_MAX_INPUTS 16
/* [kiosk] refine_samples at most: each a whole frame more of the GPU's idle time */
#define KIOSK_MAX_REFINE_SAMPLES 16
/* [kiosk] image_memory's default, MB: every scene's textures and sky faces are decoded at start
 * and kept (io/image_cache.h); a kiosk's computer may have 1 GB in all */
#define KIOSK_IMAGE_MEMORY_MB 256
/* Capacity of the record of where each key was set; kiosk_config_keys.c checks its table fits. */
#define KIOSK_KEY_TABLE_MAX 96
/* One record per section instance: the five single sections, then buttons, then inputs. */
#define KIOSK_SINGLE_SECTIONS 5
#define KIOSK_SLOTS (KIOSK_SINGLE_SECTIONS + KIOSK_MAX_BUTTONS + KIOSK_MAX_INPUTS)

/* The HUD's font where Debian's fonts-dejavu-core puts it. */
#define KIOSK_DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

/* Knob limits. Speeds are fractions of c: 0.99 c is gamma 7, and c itself is out of reach for an
 * observer. Masses are in the scene's unit (the horizon radius is 2 x mass). */
#define KIOSK_SPEED_MAX 0.99
#define KIOSK_MASS_MAX 10.0

/* Frame sizes (preview, refined, display mode), pixels per side. */
#define KIOSK_MIN_SIZE 16
#define KIOSK_MAX_SIZE 8192

/* How a knob's counts move its value. linear: step is in the value's own unit. rapidity (speed):
 * step is in rapidity, atanh(v/c), so equal turns give equal boosts and gamma grows without the
 * knob slowing to a crawl near c. log (mass): step is in ln(mass), each count multiplies. */
enum kiosk_curve { KIOSK_CURVE_LINEAR, KIOSK_CURVE_RAPIDITY, KIOSK_CURVE_LOG };

enum kiosk_ahead { KIOSK_AHEAD_AUTO, KIOSK_AHEAD_ON, KIOSK_AHEAD_OFF };

/* [kiosk] */
struct kiosk_main {
    char scenes[KIOSK_MAX_SCENES][KIOSK_PATH_LEN];   /* joined with the config's directory */
    int n_scenes;
    int start_scene;                 /* index into scenes */
    char start_scene_name[KIOSK_NAME_LEN];   /* as written: an index or a scene's name, or "" */
    int idle_seconds;                /* s without input before attract mode */
    int preview_width, preview_height;   /* px, drawn while a knob moves */
    int width, height;               /* px, the refined frame */
    int refine_frames;               /* frames from preview to full quality */
    int refine_samples;              /* rays a pixel the refined frame ends with (1: one, no anti-aliasing) */
    int preview_rate;                /* previews a second the preview size is tuned to hold; 0: kept */
    int image_memory;                /* MB the scenes' decoded images may take in all */
    int hud;                         /* 1: draw the values on screen */
    /* compile every scene's shader programs before the first frame (kiosk_warm.h): KIOSK_AHEAD_AUTO
     * (on a display, not on the headless screen), _ON or _OFF */
    int compile_ahead;
    char font[KIOSK_PATH_LEN];
    char log[KIOSK_PATH_LEN];        /* a file, or "stderr" */
    char assets_root[KIOSK_PATH_LEN];    /* "": scenes may be anywhere */
};

/* [speed] and [mass]. speed: fractions of c; mass: the scene's mass unit (M = 1: horizon at 2). */
struct kiosk_knob {
    char input[KIOSK_NAME_LEN];      /* name of the [input NAME] that turns it */
    double min, max;
    double step;                     /* per detent or count, in the curve's unit */
    enum kiosk_curve curve;
    double start;                    /* value at start and after reset; min when not given */
};

/* [button NAME] */
struct kiosk_button {
    char name[KIOSK_NAME_LEN];
    enum kiosk_action action;
    char input[KIOSK_NAME_LEN];
    int bit;                         /* hid: button bit 0..7; -1 for other input types */
};

/* [attract] */
struct kiosk_attract {
    int enabled;
    char script[KIOSK_PATH_LEN];
};

/* Where each key was set, for the messages of kiosk_config_check(); 0 where it was not. Filled by
 * kiosk_config_load(); a configuration built in code has none, and its messages name no line. */
struct kiosk_config_source {
    int header[KIOSK_SLOTS];
    int key[KIOSK_SLOTS][KIOSK_KEY_TABLE_MAX];
};

struct kiosk_config {
    char path[KIOSK_PATH_LEN];       /* the file read, "" for defaults */
    char dir[KIOSK_PATH_LEN];        /* its directory: relative paths in it start here */
    struct kiosk_main kiosk;
    struct kiosk_display display;
    struct kiosk_knob speed, mass;
    struct kiosk_attract attract;
    struct kiosk_button buttons[KIOSK_MAX_BUTTONS];
    int n_buttons;
    struct kiosk_input inputs[KIOSK_MAX_INPUTS];
    int n_inputs;
    struct kiosk_config_source source;
};

/* where: "FILE:LINE", or FILE alone for a problem with the whole file. */

void kiosk_config_defaults(struct kiosk_config *c);
/* Defaults, then the file at PATH. 0, or -1 with the first error in ERR. Values are checked one
 * by one here; call kiosk_config_check() for what involves several keys. */
int kiosk_config_load(struct kiosk_config *c, const char *path, struct error *err);
/* The shipped configuration as seen from this program: kiosk/kiosk.conf of the source tree the
 * binary was built in (its directory or up to three above), else the installed
 * /etc/bentray/kiosk.conf. 0 with its path, or -1 with e (ERROR_INPUT) naming where it looked. */
int kiosk_config_default_path(char *out, size_t len, struct error *e);
/* Checks across keys and sections: references between sections, one knob's range and start,
 * frame sizes, an input's settings against its type and its use. 0, or -1 with ERR. */
int kiosk_config_check(const struct kiosk_config *c, struct error *err);

/* The input called NAME, NULL if there is none. */
const struct kiosk_input *kiosk_config_input(const struct kiosk_config *c, const char *name);
const char *kiosk_action_name(enum kiosk_action action);
const char *kiosk_input_type_name(enum kiosk_input_type type);

#endif
