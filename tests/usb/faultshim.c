/*
 * faultshim.so - LD_PRELOAD fault injector for the USB tests.
 *
 * umockdev's ioctl replay answers every bulk IN request at once, so it
 * cannot express a silent device, a busy interface or a device node the
 * user may not open.  This shim sits in front of umockdev's preload
 * library (LD_PRELOAD=faultshim.so:libumockdev-preload.so, see
 * tests/usb/mockrun.sh) and fakes those kernel answers at the usbdevfs
 * ioctl level, so libusb, pyusb and rast8-usbcat run their real code
 * paths.  Selected by RAST8_USB_FAULT (comma-separated, e.g. driver,silent=5):
 *   access       open() of /dev/bus/usb/... fails with EACCES
 *   busy         USBDEVFS_CLAIMINTERFACE fails with EBUSY
 *   silent=K     the first K bulk IN requests go to umockdev as usual;
 *                later ones never complete (the device sends nothing),
 *                until libusb cancels them on its timeout
 *   nodetach     (with driver) detaching the driver fails with EPERM
 *   driver       a kernel driver ("rast8drv") is bound to the interface:
 *                claiming fails with EBUSY until it is detached
 *                (USBDEVFS_DISCONNECT); detach and re-attach
 *                (USBDEVFS_CONNECT) are logged on stderr as
 *                "faultshim: detach N" / "faultshim: attach N"
 * Test code only (gnu99).
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <linux/usbdevice_fs.h>

static int inited;
static int f_access, f_busy, f_silent, f_driver, f_nodetach;
static int driver_bound = 1;
static long silent_after;
static long in_submits;
static struct usbdevfs_urb *pending;
static int pending_discarded;

static void init_mode(void)
{
    const char *f, *p;
    if (inited) return;
    inited = 1;
    f = getenv("RAST8_USB_FAULT");
    for (p = f; p && *p; p = strchr(p, ',') ? strchr(p, ',') + 1 : NULL) {
        if (!strncmp(p, "access", 6)) f_access = 1;
        else if (!strncmp(p, "busy", 4)) f_busy = 1;
        else if (!strncmp(p, "driver", 6)) f_driver = 1;
        else if (!strncmp(p, "nodetach", 8)) f_nodetach = 1;
        else if (!strncmp(p, "silent=", 7)) { f_silent = 1; silent_after = strtol(p + 7, NULL, 10); }
    }
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
    if (f_access && is_usb_node(path)) {
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
    if (f_access && is_usb_node(path)) {
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
    if (f_busy && req == USBDEVFS_CLAIMINTERFACE) {
        errno = EBUSY;
        return -1;
    }
    if (f_driver) {
        if (req == USBDEVFS_GETDRIVER) {
            struct usbdevfs_getdriver *g = arg;
            if (!driver_bound) {
                errno = ENODATA;
                return -1;
            }
            strcpy(g->driver, "rast8drv");
            return 0;
        }
        if (req == USBDEVFS_IOCTL) {
            struct usbdevfs_ioctl *c = arg;
            if (c->ioctl_code == (int)USBDEVFS_DISCONNECT) {
                if (!driver_bound) {
                    errno = ENODATA;
                    return -1;
                }
                if (f_nodetach) {       /* the driver refuses to let go */
                    errno = EPERM;
                    return -1;
                }
                driver_bound = 0;
                fprintf(stderr, "faultshim: detach %d\n", c->ifno);
                return 0;
            }
            if (c->ioctl_code == (int)USBDEVFS_CONNECT) {
                driver_bound = 1;
                fprintf(stderr, "faultshim: attach %d\n", c->ifno);
                return 0;
            }
        }
        if (req == USBDEVFS_CLAIMINTERFACE && driver_bound) {
            errno = EBUSY;
            return -1;
        }
    }
    if (f_silent) {
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
