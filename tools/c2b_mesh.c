#include "c2b_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_atomic.h"
#include "c2b_curv.h"

void c2b_mesh_free(c2b_mesh *m)
{
    if (!m)
        return;
    free(m->xyz);
    free(m->normal);
    free(m->k);
    free(m->region);
    free(m->valid);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

/* Fill vertex i from an 18-double derivative block. */
static void set_vertex(c2b_mesh *m, size_t i, const double *d, unsigned char region)
{
    c2b_curv_point cp;
    memcpy(m->xyz + 3 * i, d, 3 * sizeof *d);
    m->region[i] = region;
    if (c2b_curv_eval(d, 0, &cp, NULL) == C2B_OK) {
        memcpy(m->normal + 3 * i, cp.normal, sizeof cp.normal);
        m->k[2 * i] = cp.k1;
        m->k[2 * i + 1] = cp.k2;
        m->valid[i] = 1;
    } else {
        memset(m->normal + 3 * i, 0, 3 * sizeof *m->normal);
        m->k[2 * i] = m->k[2 * i + 1] = 0.0;
        m->valid[i] = 0;
        m->degenerate++;
    }
}

c2b_status c2b_mesh_tessellate(const c2b_blend *b, c2b_spec *spec, double t, int n, double width,
                               c2b_mesh *m, c2b_error *err)
{
    memset(m, 0, sizeof *m);
    if (n < 2 || !(width >= 0) || !isfinite(width))
        return c2b_error_set(err, C2B_ERR_ARG, "mesh: --n must be >= 2 and the width >= 0");
    if (n > 4096)
        return c2b_error_set(err, C2B_ERR_LIMIT, "mesh: --n %d exceeds the limit 4096", n);
    c2b_vdomain dom = c2b_blend_domain(b);
    int per = dom.periodic;
    int cols = n; /* distinct v columns: periodic seams wrap */
    double du = 1.0 / (n - 1);
    int strip = 0;
    if (width > 0 && spec && c2b_spec_has_primaries(spec))
        strip = (int)ceil(width / du - 1e-9);
    int rows = n + 2 * strip; /* strip rows ub = -strip du .. -du, blend rows, 1 + du .. */
    double *ub = malloc((size_t)rows * sizeof *ub), *v = malloc((size_t)cols * sizeof *v);
    if (!ub || !v) {
        free(ub);
        free(v);
        return c2b_error_set(err, C2B_ERR_NOMEM, "mesh: out of memory");
    }
    for (int r = 0; r < rows; r++)
        ub[r] = (r - strip) * du;
    for (int j = 0; j < cols; j++)
        v[j] = dom.v0 + (dom.v1 - dom.v0) * j / (per ? cols : cols - 1);
    m->nv = (size_t)rows * (size_t)cols;
    size_t cells_v = (size_t)(per ? cols : cols - 1);
    m->nt = 2 * (size_t)(rows - 1) * cells_v;
    m->xyz = malloc(m->nv * 3 * sizeof *m->xyz);
    m->normal = malloc(m->nv * 3 * sizeof *m->normal);
    m->k = malloc(m->nv * 2 * sizeof *m->k);
    m->region = malloc(m->nv);
    m->valid = malloc(m->nv);
    m->tri = malloc(m->nt * 3 * sizeof *m->tri);
    double *blk = malloc((size_t)n * (size_t)cols * 18 * sizeof *blk);
    c2b_status st = C2B_OK;
    if (!m->xyz || !m->normal || !m->k || !m->region || !m->valid || !m->tri || !blk) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "mesh: out of memory");
        goto done;
    }
    st = c2b_blend_eval_grid(b, (size_t)n, ub + strip, (size_t)cols, v, 2, blk, err);
    for (int i = 0; !st && i < n; i++)
        for (int j = 0; j < cols; j++)
            set_vertex(m, (size_t)(i + strip) * (size_t)cols + (size_t)j,
                       blk + ((size_t)i * (size_t)cols + (size_t)j) * 18, 0);
    for (int r = 0; !st && r < rows; r++) {
        if (r >= strip && r < strip + n)
            continue;
        int side = r < strip ? 0 : 1;
        for (int j = 0; !st && j < cols; j++) {
            double d[18];
            st = c2b_spec_primary_eval(spec, side, ub[r], v[j], t, 2, d, err);
            if (st)
                c2b_error_prefix(err, "mesh: strip of width %g: ", width);
            else
                set_vertex(m, (size_t)r * (size_t)cols + (size_t)j, d, (unsigned char)(side + 1));
        }
    }
    if (st)
        goto done;
    size_t k = 0;
    for (int r = 0; r + 1 < rows; r++)
        for (size_t j = 0; j < cells_v; j++) {
            size_t j1 = (j + 1) % (size_t)cols;
            size_t a = (size_t)r * (size_t)cols + j, bq = (size_t)r * (size_t)cols + j1;
            size_t c = a + (size_t)cols, d = bq + (size_t)cols;
            /* (u, v) -> counter-clockwise around Su x Sv */
            m->tri[k++] = a, m->tri[k++] = c, m->tri[k++] = d;
            m->tri[k++] = a, m->tri[k++] = d, m->tri[k++] = bq;
        }
done:
    free(ub);
    free(v);
    free(blk);
    if (st)
        c2b_mesh_free(m);
    return st;
}

static const char *extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot ? dot + 1 : "";
}

c2b_status c2b_mesh_write(const c2b_mesh *m, const char *path, c2b_error *err)
{
    const char *ext = extension(path);
    int obj = !strcmp(ext, "obj"), ply = !strcmp(ext, "ply"), off = !strcmp(ext, "off");
    if (!obj && !ply && !off)
        return c2b_error_set(err, C2B_ERR_ARG, "mesh: %s: the extension must be .obj, .ply or .off",
                             path);
    c2b_atomic_file f;
    c2b_status st = c2b_atomic_open(&f, path, err);
    if (st)
        return st;
    FILE *o = f.fp;
    if (ply) {
        fprintf(o, "ply\nformat ascii 1.0\ncomment C2Blend mesh: region 0 blend, 1 primary 1, "
                   "2 primary 2; k1 >= k2 analytic principal curvatures along the normal\n"
                   "element vertex %zu\nproperty double x\nproperty double y\nproperty double z\n"
                   "property double nx\nproperty double ny\nproperty double nz\n"
                   "property double k1\nproperty double k2\nproperty uchar region\n"
                   "property uchar valid\nelement face %zu\n"
                   "property list uchar int vertex_indices\nend_header\n",
                m->nv, m->nt);
        for (size_t i = 0; i < m->nv; i++)
            fprintf(o, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %u %u\n", m->xyz[3 * i],
                    m->xyz[3 * i + 1], m->xyz[3 * i + 2], m->normal[3 * i], m->normal[3 * i + 1],
                    m->normal[3 * i + 2], m->k[2 * i], m->k[2 * i + 1], m->region[i], m->valid[i]);
        for (size_t i = 0; i < m->nt; i++)
            fprintf(o, "3 %zu %zu %zu\n", m->tri[3 * i], m->tri[3 * i + 1], m->tri[3 * i + 2]);
    } else if (off) {
        fprintf(o, "OFF\n%zu %zu 0\n", m->nv, m->nt);
        for (size_t i = 0; i < m->nv; i++)
            fprintf(o, "%.17g %.17g %.17g\n", m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
        for (size_t i = 0; i < m->nt; i++)
            fprintf(o, "3 %zu %zu %zu\n", m->tri[3 * i], m->tri[3 * i + 1], m->tri[3 * i + 2]);
    } else {
        fprintf(o, "# C2Blend mesh: %zu vertices, %zu triangles\n", m->nv, m->nt);
        for (size_t i = 0; i < m->nv; i++)
            fprintf(o, "v %.17g %.17g %.17g\n", m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
        for (size_t i = 0; i < m->nv; i++)
            fprintf(o, "vn %.17g %.17g %.17g\n", m->normal[3 * i], m->normal[3 * i + 1],
                    m->normal[3 * i + 2]);
        for (size_t i = 0; i < m->nt; i++)
            fprintf(o, "f %zu//%zu %zu//%zu %zu//%zu\n", m->tri[3 * i] + 1, m->tri[3 * i] + 1,
                    m->tri[3 * i + 1] + 1, m->tri[3 * i + 1] + 1, m->tri[3 * i + 2] + 1,
                    m->tri[3 * i + 2] + 1);
    }
    return c2b_atomic_commit(&f, err);
}
