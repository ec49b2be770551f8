/* What a screen is opened with (screen.h): the [display] section of the kiosk configuration, as
 * src/kiosk_config/ reads it. Kept here, below the configuration file's module, so that the
 * screens take only their own settings (and the size of the frames they show). */
#ifndef BT_DISPLAY_SETTINGS_H
#define BT_DISPLAY_SETTINGS_H
#include "input/input_settings.h"

enum kiosk_backend { KIOSK_BACKEND_AUTO, KIOSK_BACKEND_KMS, KIOSK_BACKEND_X11, KIOSK_BACKEND_HEADLESS };

/* [display] */
struct kiosk_display {
    enum kiosk_backend backend;
    char drm_device[KIOSK_PATH_LEN]; /* "": the first card that drives a display */
    char connector[KIOSK_NAME_LEN];  /* "": the first connected one */
    int mode_width, mode_height;     /* px; 0: the connector's preferred mode */
    int vsync;
    char headless_out[KIOSK_PATH_LEN];   /* directory for PNG frames */
    int headless_frames;             /* frames to write before exiting; 0: until stopped */
    int backend_overridden;          /* backend set on the command line: the file's keys for its own
                                        screen are set aside, not refused (kiosk --display) */
};

#endif
