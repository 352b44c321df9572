/**
 * @file c2b_mesh.h
 * Triangle meshes of a blend and, optionally, strips of its primaries beyond the
 * trimlines, with per-vertex normals, analytic principal curvatures and a region tag
 * (0 blend, 1 primary 1, 2 primary 2). Used by `c2blend mesh`.
 */
#ifndef C2B_MESH_H
#define C2B_MESH_H

#include <stddef.h>

#include "c2b_blend.h"
#include "c2b_spec.h"

typedef struct c2b_mesh {
    size_t nv, nt;
    double *xyz;           /* nv x 3 */
    double *normal;        /* nv x 3, unit */
    double *k;             /* nv x 2: k1 >= k2 (sign follows the normal) */
    unsigned char *region; /* nv */
    unsigned char *valid;  /* nv: 0 where the point is degenerate (no normal/curvature) */
    size_t *tri;           /* nt x 3, counter-clockwise around the normal */
    size_t degenerate;     /* count of vertices with valid == 0 */
} c2b_mesh;

/**
 * Tessellate blend b (built from spec at time t) on an n x n grid (n >= 2). With
 * width > 0 and a spec with primaries, add a strip of each primary of that width in
 * the primary's own cross parameter, continuing the blend's rows (shared trimline
 * vertices belong to the blend). Closed trimlines give a closed seam.
 * @return C2B_OK; C2B_ERR_ARG for n < 2 or a primary strip outside the primary's
 *         domain (message names the primary); C2B_ERR_LIMIT for n above 4096;
 *         C2B_ERR_NOMEM.
 */
c2b_status c2b_mesh_tessellate(const c2b_blend *b, c2b_spec *spec, double t, int n, double width,
                               c2b_mesh *m, c2b_error *err);

/** Write the mesh atomically; the format follows the extension: .obj, .ply (with
 *  normals, k1, k2, region, valid) or .off. @return C2B_OK; C2B_ERR_ARG for an unknown
 *  extension; C2B_ERR_IO. */
c2b_status c2b_mesh_write(const c2b_mesh *m, const char *path, c2b_error *err);

/** Free the arrays (NULL-safe) and zero the struct. */
void c2b_mesh_free(c2b_mesh *m);

#endif
