/* transform.c - per frame: the camera and every object's pose become one
 * model -> camera matrix and offset per object; then every vertex once:
 * rotate and translate into camera space (1/16 model unit: 4 fraction
 * bits), project to 12.4 screen coordinates through a reciprocal (no
 * division), and for the depth methods the depth (affine in 1/z) and for
 * Gouraud the vertex shade.  Vertices behind the near plane or outside
 * the guard band are marked (R8_VX_CLIP) and their faces go through the
 * clipper. */
#include "r8int.h"
#include "r8kern.h"

/* rot_offset(m, d, out, transpose): out = m (or its transpose) * d >> 10,
 * rounded (world units -> camera units << 4); src/r8tfref.h, or the Z80's
 * r8k_rotoff (ports/z80/tframe_z80.s) */
#ifdef R8_ASM_TFRAME
#define rot_offset r8k_rotoff
#else
#define TFREF_ROT
#include "r8tfref.h"
#undef TFREF_ROT
#endif

/* World -> camera rotation of cam into c; 0 when it is the identity.
 * R8_CAM_FIXED: a build whose caller has proved its camera never turns
 * (ports/fw_trim.c FW_SPIN checks it before the first frame): always
 * the identity, no matrix code. */
#ifdef R8_CAM_FIXED
#define cam_rotation(cam, c) 0
#else
static int cam_rotation(const r8_camera *cam, r8_mat3 *c)
{
    r8_mat3 ry, t;
    if ((cam->flags & R8_CAM_MATRIX) && cam->m) {
        *c = *cam->m;
        return 1;
    }
    if (!cam->yaw && !cam->pitch && !cam->roll)
        return 0;
    /* camera -> world is Ry(yaw) Rx(pitch) Rz(roll); c its transpose */
    r8_mat_rotate(&ry, 0, cam->yaw, 0);
    r8_mat_rotate(c, cam->pitch, 0, cam->roll);      /* Rx Rz */
    r8_mat_mul(&ry, c, &t);
    r8_mat_transpose(&t, c);
    return 1;
}
#endif

void r8_tf_frame(r8_state *st, const r8_camera *cam)
{
    const r8_scene *sc = st->scene;
    r8_mat3 c, r;
    r8_s32 zn, zf;
    r8_u8 i;
#ifdef R8_CAM_FIXED
#define turned 0       /* (a constant: cc65 folds no local, r8_mat_mul goes) */
    (void)c;
#else
    int turned;
#endif
    r8_proj_init(&st->cam, st->width, st->height, cam->focal,
                 (r8_s32)cam->znear * R8_CSCALE);
#ifndef R8_CAM_FIXED
    turned = cam_rotation(cam, &c);
#endif
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_objx *o = &st->obj[i];
        r8_s32 d[3], *ot = &o->t.x, *oe = &o->eye.x;
        const r8_s16 *pp = &ob->pose.x, *cp = &cam->x;
        r8_u8 k;
        o->hidden = (r8_u8)(ob->pose.flags & R8_POSE_HIDDEN);
        if ((ob->pose.flags & R8_POSE_MATRIX) && ob->pose.m)
            r = *ob->pose.m;
        else
            r8_mat_rotate(&r, ob->pose.ax, ob->pose.ay, ob->pose.az);
        /* (x, y, z one after another, as rot_offset takes them: loops
         * are less flash than three copies of 32-bit code) */
        for (k = 0; k < 3; k++)
            d[k] = (r8_s32)pp[k] - cp[k];
        if (turned) {
            r8_mat_mul(&c, &r, &o->m);
            rot_offset(&c, d, &o->t, 0);
        } else {
            o->m = r;
            for (k = 0; k < 3; k++)
                ot[k] = d[k] * R8_CSCALE;
        }
        for (k = 0; k < 3; k++)
            d[k] = -d[k];
        rot_offset(&r, d, &o->eye, 1);       /* R^T (camera - position) */
        o->eye16 = 1;
#ifndef R8_CULL16       /* (ports/fw_trim.c: proven within 16 bits) */
        for (k = 0; k < 3; k++)
            if ((r8_u32)(oe[k] + 16383) > 32766UL)
                o->eye16 = 0;
#else
        (void)oe;
#endif
        if (st->shading != R8_SHADE_FLAT)
            r8_mat_apply_t14(&r, &sc->light, &o->light);
    }
    zn = (r8_s32)cam->znear * R8_CSCALE;
    zf = (r8_s32)cam->zfar * R8_CSCALE;
    if (zf < zn + (zn >> 3) + 16)
        zf = zn + (zn >> 3) + 16;      /* keeps 1 - zn/zf >= 1/9 */
    st->zn16 = zn;
    st->zf16 = zf;
#undef turned
#if R8_W_PAINTER
    if (st->method == R8_VIS_PAINTER) {
        st->kmul = (r8_u32)r8_muldiv(R8_JEFF_BUCKETS, 1L << 16, zf - zn);
        st->kmul3 = st->kmul / 3u;
    }
#endif
#if R8_W_DEPTH || R8_W_TEXTURE
    if (!(st->attrs & R8_ATTR_D))
        return;                        /* no vertex depth this frame */
    /* depth = 32767 (zn/z - zn/zf) / (1 - zn/zf), through W = zn/z in Q20 */
    st->zne = 0;
    while (zn >= 0x8000L) {
        zn >>= 1;
        st->zne++;
    }
    while (zn < 0x4000L) {
        zn <<= 1;
        st->zne--;
    }
    st->znm = (r8_s16)zn;     /* znear = znm * 2^zne */
    st->wf = (r8_u32)r8_muldiv(st->zn16, 1L << 20, zf);
    st->gh = (r8_u32)r8_muldiv(32767L, 1L << 16, (r8_s32)((1L << 20) - (r8_s32)st->wf));
#endif
}

/* r8k_depth (r8kern.h): r8_tf_depth's arithmetic (AVR: vertex.S) */
#ifndef R8_ASM_DEPTH
r8_s16 r8k_depth(r8_u16 m, r8_u16 znm, r8_s16 sh, r8_u32 wf, r8_u32 gh)
{
    r8_u32 p = (r8_u32)m * znm;         /* [2^29, 2^31) from r8_tf_depth */
    r8_u32 w, dw;
    if (sh <= 0)
        w = 1UL << 20;                  /* z <= znear/2^k: nearest */
    else if (sh > 31)
        w = 0;
    else
        w = (r8_u32)r8_asr32((r8_s32)p, (r8_u8)sh);
    if (w > (1UL << 20))
        w = 1UL << 20;
    if (w <= wf)
        return 0;
    dw = w - wf;
    return (r8_s16)((dw * gh + 32768UL) >> 16);
}
#endif

r8_s16 r8_tf_depth(const r8_state *st, r8_u16 m, r8_s8 e)
{
    /* W = zn/z = znm 2^zne m 2^(e-31), in Q20 */
    return r8k_depth(m, (r8_u16)st->znm, (r8_s16)(11 - st->zne - e), st->wf, st->gh);
}

/* Shade in 8.8 (level 0..16 << 8) of a surface with unit normal n under
 * `light`, for brightness `colour`: colour * (ambient + (1-ambient) *
 * max(0, n.l)). */
r8_s16 r8_tf_shade(const r8_state *st, const r8_vec3 *n, const r8_vec3 *light,
                   r8_u8 colour)
{
    /* Q1.14 cosine, clamped to [0, 1]: 16-bit from here on */
    r8_s32 d = R8_MUL16(n->x, light->x) + R8_MUL16(n->y, light->y) +
               R8_MUL16(n->z, light->z);
    r8_s16 i = 0, amb = st->scene->ambient;
    r8_u32 p;
    if (d > 0) {
        i = (r8_s16)R8_SHR14U(d);          /* d < 3 * 2^28 */
        if (i > R8_ONE14)
            i = R8_ONE14;
    }
    if (amb < 0)
        amb = 0;                          /* an ambient outside [0, 1] */
    if (amb > R8_ONE14)
        amb = R8_ONE14;                   /* is taken as 0 or 1 */
    p = R8_MUL16(R8_ONE14 - amb, i);
    p = (r8_u16)(amb + R8_SHR14U(p));     /* Q1.14 intensity */
    p *= (r8_u16)((r8_u16)colour << 8);
    return (r8_s16)R8_SHR14U(p + 8192u);  /* < 2^30 */
}

/* Camera point c (<< R8_CFRAC) to screen vertex g: x, y (and depth). */
void r8_tf_camera(const r8_vec3l *c, r8_state *st, r8_u16 g)
{
    r8_s16 *out = st->sv + 2u * g;      /* vsh 1: 2 entries a vertex */
    r8_s8 e;
    r8_u16 m;
#if R8_W_DEPTH || R8_W_GOURAUD || R8_W_TEXTURE
    if (st->vsh != 1)                   /* (no run-time multiply) */
        out += 2u * g;
#endif
    if (c->z < st->zn16) {
        out[0] = R8_VX_CLIP;
        return;
    }
    if (r8k_project(&st->cam, c, out, &m, &e)) {
        out[0] = R8_VX_CLIP;
        return;
    }
#if R8_W_DEPTH || R8_W_GOURAUD || R8_W_TEXTURE
    if (st->vsh == 2)
        out[2] = st->attrs & R8_ATTR_D ? r8_tf_depth(st, m, e) : 0;
#endif
}

/* Model vertex mv (flash) of object o to screen vertex g. */
void r8_tf_vertex(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g)
{
    r8_vec3l c;
    r8k_xform(&o->m, &o->t, mv, &c);
    r8_tf_camera(&c, st, g);
#if R8_W_GOURAUD
    if (st->attrs & R8_ATTR_S) {
        r8_vec3 n;
        const r8_s16 *vn = st->vnorm + 3u * g;
        n.x = vn[0];
        n.y = vn[1];
        n.z = vn[2];
        st->sv[((unsigned)g << 2) + 3u] = r8_tf_shade(st, &n, &o->light, 16);
    }
#endif
}

/* r8k_vertex (r8kern.h): the reference is r8_tf_vertex itself (not on
 * the 6502 and Z80, whose face loop calls r8_tf_vertex). */
#if !defined(R8_ASM_VERTEX) && !defined(__SDCC) && !defined(__CC65__)
void r8k_vertex(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g)
{
    r8_tf_vertex(st, o, mv, g);
}
#elif defined(R8_ASM_VERTEX)
#include <stddef.h>
/* AVR: ports/avr/vertex.S reads these offsets */
R8_CASSERT(vertex_cam_at_2, offsetof(r8_state, cam) == 2);
R8_CASSERT(vertex_vsh_at_26, offsetof(r8_state, vsh) == 26 && offsetof(r8_state, attrs) == 25);
R8_CASSERT(vertex_sv_at_37, offsetof(r8_state, sv) == 37);
R8_CASSERT(vertex_zn16_at_83, offsetof(r8_state, zn16) == 83);
R8_CASSERT(vertex_t_at_18, offsetof(r8_objx, t) == 18 && offsetof(r8_objx, m) == 0);
R8_CASSERT(vertex_proj, offsetof(r8_proj, guard) == 10 && offsetof(r8_proj, fn) == 12 &&
                        offsetof(r8_proj, fsh) == 14 && offsetof(r8_proj, cy) == 2);
#endif
#if defined(R8_ASM_VERTEX) && (R8_W_DEPTH || R8_W_TEXTURE)
/* vertex.S's depth of a vsh-2 vertex, as r8_tf_camera sets out[2] (a
 * build without depth or texture has vertex.S's weak r8k_vdepth) */
r8_s16 r8k_vdepth(const r8_state *st, r8_u16 m, r8_s8 e)
{
    return st->attrs & R8_ATTR_D ? r8_tf_depth(st, m, e) : 0;
}
#endif

/* Every vertex of every shown object, or (lazy) only marked R8_VX_TODO:
 * the frame loop then transforms the vertices of the faces it keeps. */
void r8_tf_vertices(r8_state *st, int lazy)
{
    const r8_scene *sc = st->scene;
    r8_u8 i, vsh = R8_VSH(st);
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        const r8_objx *o = &st->obj[i];
        const r8_s16 *mv = me->verts;
        r8_u16 k, g = o->vbase;
        if (o->hidden)
            continue;
#if !defined(R8_CFG_CULL) || R8_CFG_CULL != R8_CULL_NORMAL
        if (!lazy) {
            for (k = 0; k < me->nverts; k++, mv += 3)
                r8_tf_vertex(st, o, mv, g++);
            continue;
        }
#else
        (void)lazy;    /* (render.c: always, with the normal cull) */
        (void)mv;
#endif
        {
            r8_s16 *out = st->sv + ((unsigned)g << vsh);
            for (k = 0; k < me->nverts; k++, out += 1u << vsh)
                *out = R8_VX_TODO;
        }
    }
}
