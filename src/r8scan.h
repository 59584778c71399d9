/* r8scan.h - what scan.c shares with scanattr.c. */
#ifndef R8SCAN_H
#define R8SCAN_H

#include "r8raster.h"

/* Start row y of a scan: move either edge on to its next vertex where it
 * ended, then Judd's test.  0: a back face (the scan is over). */
int r8_scan_row(r8_scanx *s, r8_s16 y, int judd);
/* The same for a scan with attributes: an edge that moves on to its next
 * vertex gets its depth and shade interpolators set up again. */
int r8_scan_row_attrs(r8_scan *s, r8_s16 y, int judd);

#endif
