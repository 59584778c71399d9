/* kern.c - the C89 references of the kernels in r8kern.h.  A port that
 * links its own (assembly) version defines R8_ASM_<NAME>, and this one
 * is left out. */
#include "r8kern.h"
#include "r8fb.h"
#include "r8flash.h"

#ifndef R8_ASM_XFORM
void r8k_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out)
{
    r8_s16 x = R8_RDS16(v), y = R8_RDS16(v + 1), z = R8_RDS16(v + 2);
    const r8_s16 *a = m->m;
    out->x = R8_ASR32C(R8_MUL16(a[0], x) + R8_MUL16(a[1], y) + R8_MUL16(a[2], z) + 512, 10) + t->x;
    out->y = R8_ASR32C(R8_MUL16(a[3], x) + R8_MUL16(a[4], y) + R8_MUL16(a[5], z) + 512, 10) + t->y;
    out->z = R8_ASR32C(R8_MUL16(a[6], x) + R8_MUL16(a[7], y) + R8_MUL16(a[8], z) + 512, 10) + t->z;
}
#endif

#ifndef R8_ASM_PROJECT
int r8k_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out, r8_u16 *m, r8_s8 *e)
{
    *m = r8_recip(c->z, e);
    return r8_project_recip(p, c, *m, *e, &out[0], &out[1]);
}
#endif

#ifndef R8_ASM_TRAP
void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows)
{
    r8_u8 *page = t->page, m = t->m, k = t->k;
    r8_s16 w = t->w;
    /* the edges in locals (registers on 8-bit CPUs) for the loop */
    r8_s16 lv = l->val, lq = l->q, rv = r->val, rq = r->q;
    r8_u16 le = l->err, lr = l->r, ld = l->den, re = r->err, rr = r->r, rd = r->den;
    while (rows--) {
        r8_s16 xl = lv, xr = rv;
        if (xl < 0)
            xl = 0;
        if (xr > w)
            xr = w;
        if (xl < xr)
            r8_fb_page_run(page + xl, (unsigned)(xr - xl), m, t->pat[k], (r8_u8)(xl & 3));
        lv = (r8_s16)(lv + lq);
        le = (r8_u16)(le + lr);
        if (le >= ld) {
            le = (r8_u16)(le - ld);
            lv++;
        }
        rv = (r8_s16)(rv + rq);
        re = (r8_u16)(re + rr);
        if (re >= rd) {
            re = (r8_u16)(re - rd);
            rv++;
        }
        k = (r8_u8)((k + 1) & 3);
        m = (r8_u8)(m << 1);
        if (!m) {
            m = 1;
            page += w;
        }
    }
    l->val = lv;
    l->err = le;
    r->val = rv;
    r->err = re;
    t->page = page;
    t->m = m;
    t->k = k;
}
#endif
