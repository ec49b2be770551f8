/* What an input source is opened with (input.h): one [input NAME] section of the kiosk
 * configuration, as src/kiosk_config/ reads it, and the actions a button, a key or a script may
 * ask for. Kept here, below the configuration file's module, so that the inputs take only their
 * own settings. */
#ifndef BT_INPUT_SETTINGS_H
#define BT_INPUT_SETTINGS_H
#include <stdint.h>

#define KIOSK_NAME_LEN 64            /* section names, GPIO chips and line names, connectors */
#define KIOSK_PATH_LEN 512           /* every stored path, after joining the config's directory */

/* Griffin PowerMate's USB ids, the defaults of a powermate input. */
#define KIOSK_POWERMATE_VID 0x077d
#define KIOSK_POWERMATE_PID 0x0410

/* The actions, each with the name a button's `action`, a script's `press` and the log use:
 * X(ID, "name") for each, in the enum's order (the one list of their names). */
#define KIOSK_ACTIONS(X)                                                                           \
    X(NEXT_SCENE, "next_scene")                                                                    \
    X(PREVIOUS_SCENE, "previous_scene")                                                            \
    X(CYCLE_EFFECTS, "cycle_effects")                                                              \
    X(RESET, "reset")                                                                              \
    X(PIPELINE_VIEW, "pipeline_view")                                                              \
    X(STAFF_MODE, "staff_mode")

#define KIOSK_ACTION_ENUM(id, name) KIOSK_ACTION_##id,
enum kiosk_action { KIOSK_ACTIONS(KIOSK_ACTION_ENUM) KIOSK_ACTION_COUNT };
#undef KIOSK_ACTION_ENUM

enum kiosk_input_type {
    KIOSK_INPUT_POWERMATE,           /* Griffin PowerMate: a USB knob with one push button */
    KIOSK_INPUT_HID,                 /* any HID device, its report layout given in the file */
    KIOSK_INPUT_GPIO_ENCODER,        /* quadrature encoder on two GPIO lines */
    KIOSK_INPUT_GPIO_BUTTON,         /* push button on one GPIO line */
    KIOSK_INPUT_KEYBOARD,            /* the program's fixed key mapping, for service and tests */
    KIOSK_INPUT_SCRIPT,              /* a file of timestamped events, replayed */
    KIOSK_INPUT_TYPE_COUNT
};

enum kiosk_axis_mode { KIOSK_AXIS_RELATIVE, KIOSK_AXIS_ABSOLUTE };

/* [input NAME]: fields apply by type, as the comments say; the others keep their defaults. */
struct kiosk_input {
    char name[KIOSK_NAME_LEN];
    enum kiosk_input_type type;
    int vid, pid;                    /* powermate, hid: USB vendor and product */
    int report_id;                   /* hid: 0 for devices without numbered reports */
    int report_length;               /* hid: bytes, the report id byte included */
    int axis_offset, axis_size;      /* hid: byte offset and width (1, 2, 4) of the knob's value */
    int axis_signed;
    enum kiosk_axis_mode axis_mode;  /* relative: counts per report; absolute: a position */
    int64_t axis_min, axis_max;      /* hid, absolute: raw values at the two ends of the knob */
    int button_offset, buttons;      /* hid: byte holding the button bits, how many bits */
    char chip[KIOSK_NAME_LEN];       /* gpio_*: "gpiochip0" */
    int line_a, line_b;              /* gpio_encoder: line offsets, -1 when given by name */
    char line_a_name[KIOSK_NAME_LEN], line_b_name[KIOSK_NAME_LEN];
    int counts_per_detent;           /* gpio_encoder: 1, 2 or 4 */
    int line;                        /* gpio_button: line offset, -1 when given by name */
    char line_name[KIOSK_NAME_LEN];
    int active_low;                  /* gpio_button */
    int debounce_ms;                 /* gpio_button, ms */
    char path[KIOSK_PATH_LEN];       /* script */
};

#endif
