/* r8flash.h - constant tables and meshes in flash: the one place that
 * says how they are declared and read.
 *
 *   static const r8_s16 table[4] R8_FLASH = { 1, 2, 3, 4 };
 *   r8_s16 v = R8_RDS16(&table[i]);
 *   (R8_RDPTR reads a data pointer stored in flash: const void *.)
 *
 * On AVR (avr-gcc, unless R8_NO_PROGMEM is defined) R8_FLASH places the
 * object in program memory (PROGMEM) and the R8_RD* macros read it with
 * pgm_read_byte/pgm_read_word: constant data then costs flash, not
 * SRAM.  Everywhere else (host, 6502, Z80) R8_FLASH is empty and the
 * macros are plain loads, so the same source runs on every target.
 *
 * Rules: an object declared R8_FLASH is read only through R8_RD*, never
 * through a plain pointer dereference (on AVR that would read SRAM at the
 * same address).  Mesh arrays (vertices, faces, normals) are R8_FLASH
 * data: meshes built at run time in SRAM work on every target but AVR,
 * where a build with -DR8_NO_PROGMEM reads everything from SRAM.
 */
#ifndef R8FLASH_H
#define R8FLASH_H

#include "r8types.h"

#if defined(__AVR__) && !defined(R8_NO_PROGMEM)
#include <avr/pgmspace.h>
#define R8_FLASH PROGMEM
#define R8_RDU8(p) ((r8_u8)pgm_read_byte(p))
#define R8_RDS8(p) ((r8_s8)pgm_read_byte(p))
#define R8_RDU16(p) ((r8_u16)pgm_read_word(p))
#define R8_RDS16(p) ((r8_s16)pgm_read_word(p))
#define R8_RDPTR(p) ((const void *)pgm_read_word(p))
#define R8_HAVE_PROGMEM 1
#else
#define R8_FLASH
#define R8_RDU8(p) (*(const r8_u8 *)(p))
#define R8_RDS8(p) (*(const r8_s8 *)(p))
#define R8_RDU16(p) (*(const r8_u16 *)(p))
#define R8_RDS16(p) (*(const r8_s16 *)(p))
#define R8_RDPTR(p) (*(const void *const *)(p))
#define R8_HAVE_PROGMEM 0
#endif

#endif
