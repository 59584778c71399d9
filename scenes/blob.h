/* blob.h - load a scene blob (host/rast8/scene.py to_blob, docs/scene-
 * format.md) at run time into a demo descriptor: host tools preview a
 * model without rebuilding.  Host code (stdio); the meshes live in
 * static pools here, their normals are computed by r8_render_init. */
#ifndef R8_BLOB_H
#define R8_BLOB_H

#include "demo.h"

/* 0 and *out set, or -1 with a one-line reason in err[errlen]. */
int r8_blob_load(const char *path, const r8_demo **out, char *err, unsigned errlen);

#endif
