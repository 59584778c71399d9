/* r8tfref.h - the C89 references of the Z80's per-frame transform kernels
 * (ports/z80/tframe_z80.s, -DR8_ASM_TFRAME; issue 10):
 *   TFREF_ROT: rot_offset, an object's offset in camera units
 *              (src/transform.c; the kernel is r8k_rotoff, r8kern.h)
 *   TFREF_T14: r8_mat_apply_t14, the light in model space (src/fixed.c)
 * Without R8_ASM_TFRAME the library includes these sections in those two
 * files, each at the place its function always had (the same code on
 * every target); tests/targets/test_z80_kern.c includes them under other
 * names and compares the kernels with them on random inputs. */
#ifdef TFREF_ROT
/* a * b for a Q1.14 entry and a world-unit difference (|b| < 2^17):
 * |sum of three| < 2^31 for a rotation row. */
static r8_s32 mulq(r8_s16 a, r8_s32 b)
{
    r8_s32 p = a;
    p *= b;
    return p;
}

/* out = m * d >> 10 (rounded): world units -> camera units (<< 4) */
static void rot_offset(const r8_mat3 *m, const r8_s32 *d, r8_vec3l *out, int transpose)
{
    r8_s32 *o = &out->x;
    r8_u8 i, j, row = 3, col = 1;     /* one loop for both: less flash */
    if (transpose) {
        row = 1;
        col = 3;
    }
    for (i = 0; i < 3; i++) {
        const r8_s16 *e = m->m + i * row;
        r8_s32 s = 0;
        for (j = 0; j < 3; j++, e += col)
            s += mulq(*e, d[j]);
        o[i] = r8_asr32(s + 512, 10);
    }
}
#endif

#ifdef TFREF_T14
void r8_mat_apply_t14(const r8_mat3 *m, const r8_vec3 *v, r8_vec3 *out)
{
    /* column k of m with v: a loop (once an object a frame; a third of
     * the flash of three copies) */
    r8_s16 *o = &out->x;
    const r8_s16 *c = m->m;
    r8_u8 k;
    for (k = 0; k < 3; k++, c++)
        o[k] = r8_sat16(r8_asr14(r8_mul16(c[0], v->x) + r8_mul16(c[3], v->y) +
                                 r8_mul16(c[6], v->z) + 8192));
}
#endif
