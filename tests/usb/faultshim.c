/*
 * faultshim.so - LD_PRELOAD fault injector for the USB tests.
 *
 * umockdev's ioctl replay answers every bulk IN request at once, so it
 * cannot express a silent device, a busy interface or a device node the
 * user may not open.  This shim sits in front of umockdev's preload
 * library (LD_PRELOAD=faultshim.so:libumockdev-preload.so, see
 * tests/usb/mockrun.sh) and fakes those kernel answers at the usbdevfs
 * ioctl level, so libusb, pyusb and rast8-usbcat run their real code
 * paths.  Selected by RAST8_USB_FAULT:
 *   access       open() of /dev/bus/usb/... fails with EACCES
 *   busy         USBDEVFS_CLAIMINTERFACE fails with EBUSY
 *   silent=K     the first K bulk IN requests go to umockdev as usual;
 *                later ones never complete (the device sends nothing),
 *                until libusb cancels them on its timeout
 * Test code only (gnu99).
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <linux/usbdevice_fs.h>

static int mode = -1;               /* 0 none, 1 access, 2 busy, 3 silent */
static long silent_after;
static long in_submits;
static struct usbdevfs_urb *pending;
static int pending_discarded;

static void init_mode(void)
{
    const char *f;
    if (mode >= 0) return;
    f = getenv("RAST8_USB_FAULT");
    mode = 0;
    if (!f) return;
    if (!strcmp(f, "access")) mode = 1;
    else if (!strcmp(f, "busy")) mode = 2;
    else if (!strncmp(f, "silent=", 7)) { mode = 3; silent_after = strtol(f + 7, NULL, 10); }
}

static int is_usb_node(const char *path)
{
    return path && !strncmp(path, "/dev/bus/usb/", 13);
}

typedef int (*open_fn)(const char *, int, ...);

static int do_open(const char *name, const char *path, int flags, va_list ap)
{
    open_fn real = (open_fn)dlsym(RTLD_NEXT, name);
    mode_t m = 0;
    init_mode();
    if (flags & (O_CREAT | O_TMPFILE)) m = (mode_t)va_arg(ap, int);
    if (mode == 1 && is_usb_node(path)) {
        errno = EACCES;
        return -1;
    }
    return real(path, flags, m);
}

int open(const char *path, int flags, ...)
{
    va_list ap;
    int r;
    va_start(ap, flags);
    r = do_open("open", path, flags, ap);
    va_end(ap);
    return r;
}

int open64(const char *path, int flags, ...)
{
    va_list ap;
    int r;
    va_start(ap, flags);
    r = do_open("open64", path, flags, ap);
    va_end(ap);
    return r;
}

int __open_2(const char *path, int flags)
{
    open_fn real = (open_fn)dlsym(RTLD_NEXT, "__open_2");
    init_mode();
    if (mode == 1 && is_usb_node(path)) {
        errno = EACCES;
        return -1;
    }
    return real(path, flags);
}

typedef int (*ioctl_fn)(int, unsigned long, ...);

int ioctl(int fd, unsigned long req, ...)
{
    static ioctl_fn real;
    va_list ap;
    void *arg;
    va_start(ap, req);
    arg = va_arg(ap, void *);
    va_end(ap);
    if (!real) real = (ioctl_fn)dlsym(RTLD_NEXT, "ioctl");
    init_mode();
    if (mode == 2 && req == USBDEVFS_CLAIMINTERFACE) {
        errno = EBUSY;
        return -1;
    }
    if (mode == 3) {
        if (req == USBDEVFS_SUBMITURB) {
            struct usbdevfs_urb *u = arg;
            if (u->type == USBDEVFS_URB_TYPE_BULK && (u->endpoint & 0x80) &&
                ++in_submits > silent_after) {
                pending = u;              /* never answered by the device */
                pending_discarded = 0;
                return 0;
            }
        } else if (req == USBDEVFS_DISCARDURB && pending && arg == pending) {
            pending_discarded = 1;
            return 0;
        } else if ((req == USBDEVFS_REAPURBNDELAY || req == USBDEVFS_REAPURB) && pending) {
            if (!pending_discarded) {
                errno = EAGAIN;
                return -1;
            }
            pending->status = -ENOENT;    /* cancelled */
            pending->actual_length = 0;
            *(struct usbdevfs_urb **)arg = pending;
            pending = NULL;
            return 0;
        }
    }
    return real(fd, req, arg);
}
