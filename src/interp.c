/* interp.c - the seed's stepwise linear interpolator, in an exact form:
 * an integer value and an integer error term instead of an accumulating
 * rounded delta, so the last step lands exactly on the end value. */
#include "r8raster.h"
#include "r8fixed.h"

void r8_interp_init(r8_interp *it, r8_s16 base, r8_s32 num0, r8_s32 step,
                    r8_u16 den)
{
    r8_s32 d = den ? (r8_s32)den : 1;
    r8_s32 q0, qs;
    if (num0 > -32768L && num0 < 32768L && step > -32768L && step < 32768L) {
        /* 16-bit floor division and remainder: several times cheaper on
         * 8-bit targets (no product can overflow here) */
        r8_u16 dd = (r8_u16)d, un, ur;
        if (num0 >= 0) {
            un = (r8_u16)num0;
            it->val = r8_sat16((r8_s32)base + (r8_s32)(un / dd));
            it->err = (r8_u16)(un % dd);
        } else {
            un = (r8_u16)(-(num0 + 1));            /* -num0 - 1 >= 0 */
            ur = (r8_u16)(un % dd);
            it->val = r8_sat16((r8_s32)base - (r8_s32)(un / dd) - 1);
            it->err = (r8_u16)(dd - 1u - ur);
        }
        if (step >= 0) {
            un = (r8_u16)step;
            it->q = (r8_s16)(un / dd);
            it->r = (r8_u16)(un % dd);
        } else {
            un = (r8_u16)(-(step + 1));
            ur = (r8_u16)(un % dd);
            it->q = (r8_s16)(-(r8_s16)(un / dd) - 1);
            it->r = (r8_u16)(dd - 1u - ur);
        }
        it->den = dd;
        return;
    }
    q0 = r8_floordiv(num0, d);
    qs = r8_floordiv(step, d);
    it->den = (r8_u16)d;
    it->val = r8_sat16((r8_s32)base + q0);
    it->err = (r8_u16)(num0 - q0 * d);
    it->q = r8_sat16(qs);
    it->r = (r8_u16)(step - qs * d);
}

void r8_interp_init_mul(r8_interp *it, r8_s16 base, r8_s32 a, r8_s32 b,
                        r8_s32 step, r8_u16 den)
{
    r8_s32 d = den ? (r8_s32)den : 1;
    r8_s32 q, qs;
    r8_u32 rem;
    if (a > -32768L && a < 32768L && b > -32768L && b < 32768L) {
        r8_interp_init(it, base, a * b, step, den);
        return;
    }
    /* a * b may need 64 bits: truncated quotient from r8_muldiv, the
     * remainder from arithmetic mod 2^32 (it lies in (-d, d)). */
    q = r8_muldiv(a, b, d);
    rem = (r8_u32)a * (r8_u32)b - (r8_u32)q * (r8_u32)d;
    if (rem & 0x80000000UL) {          /* negative remainder: floor */
        q--;
        rem += (r8_u32)d;
    }
    qs = r8_floordiv(step, d);
    it->den = (r8_u16)d;
    it->val = r8_sat16((r8_s32)base + q);
    it->err = (r8_u16)rem;
    it->q = r8_sat16(qs);
    it->r = (r8_u16)(step - qs * d);
}

void r8_interp_reset(r8_interp *it, r8_s16 a, r8_s16 b, r8_u16 n)
{
    r8_interp_init(it, a, 0, (r8_s32)b - a, n);
}

void r8_interp_step(r8_interp *it)
{
    R8_INTERP_STEP(it);
}
