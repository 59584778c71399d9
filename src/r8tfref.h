/* r8tfref.h - the C89 references of the Z80's per-frame transform kernels
 * (ports/z80/tframe_z80.s, -DR8_ASM_TFRAME; issue 10):
 *   TFREF_ROT: rot_offset, an object's offset in camera units
 *              (src/transform.c; the kernel is r8k_rotoff, r8kern.h)
 *   TFREF_T14: r8_mat_apply_t14, the light in model space (src/fixed.c)
 *   TFREF_ROTATE: r8_mat_rotate, a pose's rotation matrix (src/fixed.c)
 * Without R8_ASM_TFRAME the library includes these sections in those
 * files, each at the place its function always had (the same code on
 * every target); tests/targets/test_z80_kern.c includes them under other
 * names and compares the kernels with them on random inputs. */
#ifdef TFREF_ROTATE
/* r8_sat16(R8_ASR32C(q, 14)) on the 16-bit halves of q: floor(q / 2^14)
 * is hi * 4 + (lo >> 14), in range when hi is in -2^13 .. 2^13 - 1 (no
 * 32-bit shift or compare on 8-bit CPUs) */
static r8_s16 sat_asr14(r8_s32 q)
{
    r8_u16 hi = (r8_u16)((r8_u32)q >> 16), lo = (r8_u16)((r8_u32)q & 0xFFFFu);
    if ((r8_u16)(hi + 0x2000u) < 0x4000u)
        return (r8_s16)((r8_u16)(hi << 2) | (lo >> 14));
    if (hi & 0x8000u)
        return (r8_s16)(-32767 - 1);
    return 32767;
}

/* round(a * b / 2^14) as r8_mat_mul rounds each entry */
static r8_s16 rmul(r8_s16 a, r8_s16 b)
{
    return sat_asr14(R8_MUL16(a, b) + 8192);
}

/* round((a * b + c * d) / 2^14), saturated */
static r8_s16 rmul2(r8_s16 a, r8_s16 b, r8_s16 c, r8_s16 d)
{
    return sat_asr14(R8_MUL16(a, b) + R8_MUL16(c, d) + 8192);
}

void r8_mat_rotate(r8_mat3 *m, r8_u8 ax, r8_u8 ay, r8_u8 az)
{
    /* Rx (Ry Rz) with the zero and one entries of each factor left out:
     * the same entries, rounded the same way, as two r8_mat_mul calls
     * on the three axis matrices, in 16 products instead of 54 */
    r8_s16 sa = r8_sin(ax), ca = r8_cos(ax), sb = r8_sin(ay), cb = r8_cos(ay);
    r8_s16 sc = r8_sin(az), cc = r8_cos(az);
    r8_s16 t0 = rmul(cb, cc), t1 = rmul(cb, (r8_s16)-sc);
    r8_s16 t6 = rmul((r8_s16)-sb, cc), t7 = rmul(sb, sc);
    /* Ry Rz = [t0 t1 sb; sc cc 0; t6 t7 cb] */
    m->m[0] = t0;
    m->m[1] = t1;
    m->m[2] = sb;
    m->m[3] = rmul2(ca, sc, (r8_s16)-sa, t6);
    m->m[4] = rmul2(ca, cc, (r8_s16)-sa, t7);
    m->m[5] = rmul((r8_s16)-sa, cb);
    m->m[6] = rmul2(sa, sc, ca, t6);
    m->m[7] = rmul2(sa, cc, ca, t7);
    m->m[8] = rmul(ca, cb);
}
#endif

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
