/* plat_host.h - host-only controls of the emulator's platform layer. */
#ifndef PLAT_HOST_H
#define PLAT_HOST_H

/* Where UART bytes go: a file descriptor.  baud > 0 paces the output in
 * real time as 8N1 would (10 bits a byte); 0 = as fast as possible. */
void plat_host_output(int fd, long baud);
/* Bytes written so far; non-zero once a write failed (reader gone). */
unsigned long plat_host_bytes(void);
int plat_host_failed(void);
/* Number of plat_mark calls with each id (0..7). */
unsigned long plat_host_marks(int id);
/* Seconds since plat_host_output (monotonic). */
double plat_host_elapsed(void);

#endif
