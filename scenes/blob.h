/* blob.h - load a scene blob (host/rast8/scene.py to_blob, docs/scene-
 * format.md) at run time into a demo descriptor: host tools preview a
 * model without rebuilding.  Host code (stdio); the meshes live in
 * static pools here, their normals are computed by r8_render_init. */
#ifndef R8_BLOB_H
#define R8_BLOB_H

#include "demo.h"

/* 0 and *out set, or -1 with a one-line reason in err[errlen]. */
int r8_blob_load(const char *path, const r8_demo **out, char *err, unsigned errlen);

/* A scene by name: a built-in scene's name, or a file: a blob, or a
 * .r8s or .obj file (converted to a blob by the scene converter,
 * `python3 -m rast8.scene blob`, from this source tree's host/).  0 and
 * *out set, or -1 with a one-line reason in err[errlen]. */
int r8_scene_open(const char *name, const r8_demo **out, char *err, unsigned errlen);

#endif
