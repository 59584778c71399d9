/* interp.c - the seed's stepwise linear interpolator, in an exact form:
 * an integer value and an integer error term instead of an accumulating
 * rounded delta, so the last step lands exactly on the end value. */
#include "r8raster.h"
#include "r8fixed.h"
#include "r8int.h"

/* floor(65536 / n), n = 2..256 ([1] unused: n = 1 is the quotient
 * itself): the divisions of r8_zfill's spans and of the attribute
 * set-ups (scanattr.c) as products (src/r8int.h). */
const r8_u16 r8_rcp256[257] R8_FLASH = {
    0u, 65535u, 32768u, 21845u, 16384u, 13107u, 10922u, 9362u, 8192u, 7281u,
    6553u, 5957u, 5461u, 5041u, 4681u, 4369u, 4096u, 3855u, 3640u, 3449u,
    3276u, 3120u, 2978u, 2849u, 2730u, 2621u, 2520u, 2427u, 2340u, 2259u,
    2184u, 2114u, 2048u, 1985u, 1927u, 1872u, 1820u, 1771u, 1724u, 1680u,
    1638u, 1598u, 1560u, 1524u, 1489u, 1456u, 1424u, 1394u, 1365u, 1337u,
    1310u, 1285u, 1260u, 1236u, 1213u, 1191u, 1170u, 1149u, 1129u, 1110u,
    1092u, 1074u, 1057u, 1040u, 1024u, 1008u, 992u, 978u, 963u, 949u,
    936u, 923u, 910u, 897u, 885u, 873u, 862u, 851u, 840u, 829u,
    819u, 809u, 799u, 789u, 780u, 771u, 762u, 753u, 744u, 736u,
    728u, 720u, 712u, 704u, 697u, 689u, 682u, 675u, 668u, 661u,
    655u, 648u, 642u, 636u, 630u, 624u, 618u, 612u, 606u, 601u,
    595u, 590u, 585u, 579u, 574u, 569u, 564u, 560u, 555u, 550u,
    546u, 541u, 537u, 532u, 528u, 524u, 520u, 516u, 512u, 508u,
    504u, 500u, 496u, 492u, 489u, 485u, 481u, 478u, 474u, 471u,
    468u, 464u, 461u, 458u, 455u, 451u, 448u, 445u, 442u, 439u,
    436u, 434u, 431u, 428u, 425u, 422u, 420u, 417u, 414u, 412u,
    409u, 407u, 404u, 402u, 399u, 397u, 394u, 392u, 390u, 387u,
    385u, 383u, 381u, 378u, 376u, 374u, 372u, 370u, 368u, 366u,
    364u, 362u, 360u, 358u, 356u, 354u, 352u, 350u, 348u, 346u,
    344u, 343u, 341u, 339u, 337u, 336u, 334u, 332u, 330u, 329u,
    327u, 326u, 324u, 322u, 321u, 319u, 318u, 316u, 315u, 313u,
    312u, 310u, 309u, 307u, 306u, 304u, 303u, 302u, 300u, 299u,
    297u, 296u, 295u, 293u, 292u, 291u, 289u, 288u, 287u, 286u,
    284u, 283u, 282u, 281u, 280u, 278u, 277u, 276u, 275u, 274u,
    273u, 271u, 270u, 269u, 268u, 267u, 266u, 265u, 264u, 263u,
    262u, 261u, 260u, 259u, 258u, 257u, 256u
};

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
