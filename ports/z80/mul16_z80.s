;; mul16_z80.s - r8_s32 r8_mul16(r8_s16 a, r8_s16 b) for the Z80: the
;; full signed product (issue 10).  Its C89 reference is src/fixed.c's,
;; left out of the library with -DR8_ASM_MUL16 (mk/targets.mk, Z80_ASM);
;; the work is r8z_smul16 (mulz_z80.s): ~330 T when a factor is below 256
;; in magnitude, ~640 T otherwise (sdcc's long multiply: ~3900 T).
;; tests/targets/test_z80_kern.c checks it against a C89 model.
;; sdcc's __sdcccall(1): a in HL, b in DE; the product in HL:DE.
        .module mul16_z80
        .area   _CODE
        .globl  _r8_mul16
        .globl  r8z_smul16

_r8_mul16:
        jp      r8z_smul16
