/* The HID source's back-end: the few hidapi calls it makes, as a table, so that the source can be
 * driven by a device of the tests' own making (plugged, reporting, unplugged) where no knob is
 * attached. input_open_hid() uses input_hid_libusb. */
#ifndef BT_KIOSK_INPUT_HID_H
#define BT_KIOSK_INPUT_HID_H
#include <hidapi.h>
#include "input/input.h"

struct input_hid_api {
    int *users;                      /* sources open on this back-end: init at the first, exit after the last */
    int (*init)(void);
    int (*exit)(void);
    struct hid_device_info *(*enumerate)(unsigned short vid, unsigned short pid);
    void (*free_enumeration)(struct hid_device_info *devs);
    hid_device *(*open_path)(const char *path);
    int (*set_nonblocking)(hid_device *dev, int nonblock);
    int (*read_timeout)(hid_device *dev, unsigned char *data, size_t length, int milliseconds);
    void (*close)(hid_device *dev);
};

/* hidapi's libusb back-end (hidapi-libusb). */
extern const struct input_hid_api input_hid_libusb;

/* input_open_hid() on the back-end `api`, which must outlive the source. */
struct input_source *input_open_hid_api(const struct kiosk_input *in, int index, FILE *log, double now,
                                        const struct input_hid_api *api);

#endif
