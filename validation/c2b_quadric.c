/*
 * Implicit-quadric normal and curvature estimation (seed 002, section 6.2 and
 * appendix A). See c2b_quadric.h for the method, the reading of the seed and the
 * conventions.
 */
#include "c2b_quadric.h"
#include "c2b_vec3.h"

#include <float.h>
#include <lapacke.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char XYZ[3] = {'x', 'y', 'z'};

/* Monomials of F in the order of the seed's coefficients a .. i. */
enum { MONO_XX, MONO_YY, MONO_ZZ, MONO_XY, MONO_YZ, MONO_ZX, MONO_X, MONO_Y, MONO_Z, NMONO };

/* ---- small vector helpers ------------------------------------------------------- */



/* y = M x for a symmetric 3x3 matrix stored row-major. */
static void matvec3(const double M[9], const double *x, double *y)
{
    for (int r = 0; r < 3; r++)
        y[r] = M[3 * r] * x[0] + M[3 * r + 1] * x[1] + M[3 * r + 2] * x[2];
}

static double quad_form(const double M[9], const double *x, const double *y)
{
    double t[3];
    matvec3(M, y, t);
    return c2b_vec3_dot(x, t);
}

static void monomials(const double *x, double m[NMONO])
{
    m[MONO_XX] = x[0] * x[0];
    m[MONO_YY] = x[1] * x[1];
    m[MONO_ZZ] = x[2] * x[2];
    m[MONO_XY] = x[0] * x[1];
    m[MONO_YZ] = x[1] * x[2];
    m[MONO_ZX] = x[2] * x[0];
    m[MONO_X] = x[0];
    m[MONO_Y] = x[1];
    m[MONO_Z] = x[2];
}

/* ---- neighbourhoods -------------------------------------------------------------- */

struct c2b_quadric_neighbourhoods {
    size_t nv, nt;
    int rings;
    size_t *off;          /* nv + 1 row offsets into nbr */
    size_t *nbr;          /* n-ring neighbours */
    size_t *vt_off;       /* nv + 1 row offsets into vt */
    size_t *vt;           /* triangles incident to each vertex */
    unsigned char *touch; /* nv flags: the vertex or a neighbour is on the border */
    size_t ndegenerate;
    size_t max_count;
};

void c2b_quadric_neighbourhoods_destroy(c2b_quadric_neighbourhoods *nb)
{
    if (!nb)
        return;
    free(nb->off);
    free(nb->nbr);
    free(nb->vt_off);
    free(nb->vt);
    free(nb->touch);
    free(nb);
}

size_t c2b_quadric_neighbourhoods_nv(const c2b_quadric_neighbourhoods *nb)
{
    return nb ? nb->nv : 0;
}

int c2b_quadric_neighbourhoods_rings(const c2b_quadric_neighbourhoods *nb)
{
    return nb ? nb->rings : 0;
}

size_t c2b_quadric_neighbourhoods_count(const c2b_quadric_neighbourhoods *nb, size_t v)
{
    return (nb && v < nb->nv) ? nb->off[v + 1] - nb->off[v] : 0;
}

const size_t *c2b_quadric_neighbourhoods_list(const c2b_quadric_neighbourhoods *nb, size_t v)
{
    return (nb && v < nb->nv) ? nb->nbr + nb->off[v] : NULL;
}

size_t c2b_quadric_neighbourhoods_max_count(const c2b_quadric_neighbourhoods *nb)
{
    return nb ? nb->max_count : 0;
}

size_t c2b_quadric_neighbourhoods_ndegenerate(const c2b_quadric_neighbourhoods *nb)
{
    return nb ? nb->ndegenerate : 0;
}

int c2b_quadric_neighbourhoods_touches_border(const c2b_quadric_neighbourhoods *nb, size_t v)
{
    return (nb && v < nb->nv) ? nb->touch[v] : 0;
}

static int cmp_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return (x > y) - (x < y);
}

/* Edges are pairs (lo, hi) stored consecutively. */
static int cmp_edge(const void *a, const void *b)
{
    const size_t *x = a, *y = b;
    if (x[0] != y[0])
        return (x[0] > y[0]) - (x[0] < y[0]);
    return (x[1] > y[1]) - (x[1] < y[1]);
}

/* Distinct corners of triangle t, in order; returns their number (1..3). */
static int distinct_corners(const size_t *tri, size_t t, size_t c[3])
{
    int k = 0;
    for (int j = 0; j < 3; j++) {
        size_t v = tri[3 * t + (size_t)j];
        int seen = 0;
        for (int i = 0; i < k; i++)
            seen |= c[i] == v;
        if (!seen)
            c[k++] = v;
    }
    return k;
}

static c2b_status validate_mesh(const c2b_quadric_mesh *m, size_t *ndeg, c2b_error *err)
{
    for (size_t v = 0; v < m->nv; v++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(m->xyz[3 * v + (size_t)k]))
                return c2b_error_set(err, C2B_ERR_SPEC, "vertex %zu: coordinate %c = %g is not finite", v,
                                     XYZ[k], m->xyz[3 * v + (size_t)k]);
    size_t nd = 0;
    for (size_t t = 0; t < m->nt; t++) {
        const size_t *c = m->tri + 3 * t;
        for (int j = 0; j < 3; j++)
            if (c[j] >= m->nv)
                return c2b_error_set(err, C2B_ERR_SPEC,
                                     "triangle %zu: corner %d has vertex index %zu, out of range "
                                     "(the mesh has %zu vertices)",
                                     t, j, c[j], m->nv);
        int degenerate = c[0] == c[1] || c[1] == c[2] || c[2] == c[0];
        if (!degenerate) {
            const double *a = m->xyz + 3 * c[0], *b = m->xyz + 3 * c[1], *q = m->xyz + 3 * c[2];
            double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            double e2[3] = {q[0] - a[0], q[1] - a[1], q[2] - a[2]};
            double nrm[3];
            c2b_vec3_cross(e1, e2, nrm);
            degenerate = nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0;
        }
        nd += (size_t)degenerate;
    }
    *ndeg = nd;
    return C2B_OK;
}

/* Vertex -> incident triangle table (each triangle listed once per distinct corner). */
static c2b_status build_incidence(const c2b_quadric_mesh *m, c2b_quadric_neighbourhoods *nb, c2b_error *err)
{
    nb->vt_off = calloc(m->nv + 1, sizeof *nb->vt_off);
    nb->vt = malloc((3 * m->nt > 0 ? 3 * m->nt : 1) * sizeof *nb->vt);
    if (!nb->vt_off || !nb->vt)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the vertex-triangle table");
    size_t c[3];
    for (size_t t = 0; t < m->nt; t++) {
        int k = distinct_corners(m->tri, t, c);
        for (int i = 0; i < k; i++)
            nb->vt_off[c[i] + 1]++;
    }
    for (size_t v = 0; v < m->nv; v++)
        nb->vt_off[v + 1] += nb->vt_off[v];
    size_t *fill = malloc((m->nv > 0 ? m->nv : 1) * sizeof *fill);
    if (!fill)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the vertex-triangle table");
    memcpy(fill, nb->vt_off, m->nv * sizeof *fill);
    for (size_t t = 0; t < m->nt; t++) {
        int k = distinct_corners(m->tri, t, c);
        for (int i = 0; i < k; i++)
            nb->vt[fill[c[i]]++] = t;
    }
    free(fill);
    return C2B_OK;
}

/* 1-rings (sorted, without the vertex) in compressed rows r1_off / r1. */
static c2b_status build_one_rings(const c2b_quadric_mesh *m, const c2b_quadric_neighbourhoods *nb,
                                  size_t **r1_off, size_t **r1, c2b_error *err)
{
    size_t cap = 6 * m->nt > 0 ? 6 * m->nt : 1;
    *r1_off = malloc((m->nv + 1) * sizeof **r1_off);
    *r1 = malloc(cap * sizeof **r1);
    if (!*r1_off || !*r1)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the 1-rings");
    size_t pos = 0, c[3];
    for (size_t v = 0; v < m->nv; v++) {
        (*r1_off)[v] = pos;
        size_t start = pos;
        for (size_t k = nb->vt_off[v]; k < nb->vt_off[v + 1]; k++) {
            int nc = distinct_corners(m->tri, nb->vt[k], c);
            for (int i = 0; i < nc; i++)
                if (c[i] != v)
                    (*r1)[pos++] = c[i];
        }
        qsort(*r1 + start, pos - start, sizeof **r1, cmp_size);
        size_t u = start;
        for (size_t k = start; k < pos; k++)
            if (u == start || (*r1)[u - 1] != (*r1)[k])
                (*r1)[u++] = (*r1)[k];
        pos = u;
    }
    (*r1_off)[m->nv] = pos;
    return C2B_OK;
}

/* Border vertices: endpoints of edges used by one triangle or by more than two. */
static c2b_status mark_border(const c2b_quadric_mesh *m, unsigned char *border, c2b_error *err)
{
    size_t *edges = malloc((m->nt > 0 ? 6 * m->nt : 1) * sizeof *edges);
    if (!edges)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the edge table");
    size_t ne = 0, c[3];
    for (size_t t = 0; t < m->nt; t++) {
        int k = distinct_corners(m->tri, t, c);
        for (int i = 0; i < k; i++)
            for (int j = i + 1; j < k; j++) {
                edges[2 * ne] = c[i] < c[j] ? c[i] : c[j];
                edges[2 * ne + 1] = c[i] < c[j] ? c[j] : c[i];
                ne++;
            }
    }
    qsort(edges, ne, 2 * sizeof *edges, cmp_edge);
    for (size_t i = 0; i < ne;) {
        size_t j = i + 1;
        while (j < ne && edges[2 * j] == edges[2 * i] && edges[2 * j + 1] == edges[2 * i + 1])
            j++;
        if (j - i != 2) {
            border[edges[2 * i]] = 1;
            border[edges[2 * i + 1]] = 1;
        }
        i = j;
    }
    free(edges);
    return C2B_OK;
}

/* Breadth-first n-rings from the 1-rings. */
static c2b_status build_rings(size_t nv, int rings, const size_t *r1_off, const size_t *r1,
                              c2b_quadric_neighbourhoods *nb, c2b_error *err)
{
    size_t *mark = malloc((nv > 0 ? nv : 1) * sizeof *mark);
    nb->off = malloc((nv + 1) * sizeof *nb->off);
    size_t cap = r1_off[nv] > 0 ? r1_off[nv] : 1;
    nb->nbr = malloc(cap * sizeof *nb->nbr);
    if (!mark || !nb->off || !nb->nbr) {
        free(mark);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the %d-ring neighbourhoods", rings);
    }
    for (size_t v = 0; v < nv; v++)
        mark[v] = SIZE_MAX;
    size_t pos = 0;
    for (size_t v = 0; v < nv; v++) {
        nb->off[v] = pos;
        mark[v] = v;
        size_t fs = 0, fe = 0; /* frontier [fs, fe) in nb->nbr; ring 0 is v itself */
        for (int r = 1; r <= rings; r++) {
            size_t ring_start = pos;
            size_t nfront = r == 1 ? 1 : fe - fs;
            for (size_t f = 0; f < nfront; f++) {
                size_t u = r == 1 ? v : nb->nbr[fs + f];
                for (size_t k = r1_off[u]; k < r1_off[u + 1]; k++) {
                    size_t w = r1[k];
                    if (mark[w] == v)
                        continue;
                    mark[w] = v;
                    if (pos == cap) {
                        if (cap > SIZE_MAX / 2 / sizeof *nb->nbr) {
                            free(mark);
                            return c2b_error_set(err, C2B_ERR_LIMIT,
                                                 "the %d-ring neighbourhoods exceed the addressable size",
                                                 rings);
                        }
                        size_t *grown = realloc(nb->nbr, 2 * cap * sizeof *nb->nbr);
                        if (!grown) {
                            free(mark);
                            return c2b_error_set(err, C2B_ERR_NOMEM,
                                                 "out of memory for the %d-ring neighbourhoods", rings);
                        }
                        nb->nbr = grown;
                        cap *= 2;
                    }
                    nb->nbr[pos++] = w;
                }
            }
            fs = ring_start;
            fe = pos;
            if (fe == fs)
                break; /* no new vertices: the component is exhausted */
        }
        if (pos - nb->off[v] > nb->max_count)
            nb->max_count = pos - nb->off[v];
    }
    nb->off[nv] = pos;
    free(mark);
    return C2B_OK;
}

c2b_status c2b_quadric_neighbourhoods_create(const c2b_quadric_mesh *m, int rings,
                                             c2b_quadric_neighbourhoods **out, c2b_error *err)
{
    if (out)
        *out = NULL;
    if (!m || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_quadric_neighbourhoods_create: %s is NULL",
                             !m ? "mesh" : "out");
    if ((m->nv > 0 && !m->xyz) || (m->nt > 0 && !m->tri))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_quadric_neighbourhoods_create: mesh %s is NULL",
                             (m->nv > 0 && !m->xyz) ? "xyz" : "tri");
    if (rings < 1)
        return c2b_error_set(err, C2B_ERR_ARG, "rings = %d must be >= 1", rings);
    if (rings > C2B_QUADRIC_MAX_RINGS)
        return c2b_error_set(err, C2B_ERR_LIMIT, "rings = %d exceeds the limit %d", rings,
                             C2B_QUADRIC_MAX_RINGS);
    /* 6 nt size_t (edge and 1-ring tables) and nv + 1 row offsets must be addressable. */
    if (m->nt > SIZE_MAX / 6 / sizeof(size_t) || m->nv > SIZE_MAX / 3 / sizeof(double) - 1)
        return c2b_error_set(err, C2B_ERR_LIMIT, "mesh too large: %zu vertices, %zu triangles", m->nv, m->nt);

    size_t ndeg = 0;
    c2b_status st = validate_mesh(m, &ndeg, err);
    if (st != C2B_OK)
        return st;

    c2b_quadric_neighbourhoods *nb = calloc(1, sizeof *nb);
    if (!nb)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the neighbourhoods");
    nb->nv = m->nv;
    nb->nt = m->nt;
    nb->rings = rings;
    nb->ndegenerate = ndeg;

    size_t *r1_off = NULL, *r1 = NULL;
    unsigned char *border = NULL;
    st = build_incidence(m, nb, err);
    if (st == C2B_OK)
        st = build_one_rings(m, nb, &r1_off, &r1, err);
    if (st == C2B_OK)
        st = build_rings(m->nv, rings, r1_off, r1, nb, err);
    if (st == C2B_OK) {
        border = calloc(m->nv > 0 ? m->nv : 1, 1);
        nb->touch = calloc(m->nv > 0 ? m->nv : 1, 1);
        if (!border || !nb->touch)
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the border flags");
    }
    if (st == C2B_OK)
        st = mark_border(m, border, err);
    if (st == C2B_OK)
        for (size_t v = 0; v < m->nv; v++) {
            unsigned char t = border[v];
            for (size_t k = nb->off[v]; k < nb->off[v + 1] && !t; k++)
                t = border[nb->nbr[k]];
            nb->touch[v] = t;
        }
    free(r1_off);
    free(r1);
    free(border);
    if (st != C2B_OK) {
        c2b_quadric_neighbourhoods_destroy(nb);
        return st;
    }
    *out = nb;
    return C2B_OK;
}

/* ---- the fit ---------------------------------------------------------------------- */

/* Workspace for neighbourhoods of up to cap points. */
typedef struct fit_work {
    size_t cap;
    lapack_int lwork;
    double *x; /* cap x 3 scaled local coordinates */
    double *a; /* cap x 8 least-squares matrix, column-major */
    double *b; /* max(cap, 8) right-hand side / solution */
    double *s; /* 8 singular values */
    double *w; /* LAPACK workspace */
} fit_work;

static void work_free(fit_work *ws)
{
    free(ws->x);
    free(ws->a);
    free(ws->b);
    free(ws->s);
    free(ws->w);
    memset(ws, 0, sizeof *ws);
}

static c2b_status work_alloc(fit_work *ws, size_t cap, c2b_error *err)
{
    memset(ws, 0, sizeof *ws);
    if (cap < C2B_QUADRIC_UNKNOWNS)
        cap = C2B_QUADRIC_UNKNOWNS;
    if (cap > (size_t)INT_MAX / C2B_QUADRIC_UNKNOWNS)
        return c2b_error_set(err, C2B_ERR_LIMIT, "%zu neighbours exceed the size LAPACK can index (%d)", cap,
                             INT_MAX / C2B_QUADRIC_UNKNOWNS);
    lapack_int m = (lapack_int)cap, rank = 0;
    double dummy_a = 0, dummy_b = 0, dummy_s[C2B_QUADRIC_UNKNOWNS], query = 0;
    lapack_int info = LAPACKE_dgelss_work(LAPACK_COL_MAJOR, m, C2B_QUADRIC_UNKNOWNS, 1, &dummy_a, m, &dummy_b,
                                          m, dummy_s, C2B_QUADRIC_RCOND, &rank, &query, -1);
    /* Documented minimum: 3 min(M,N) + max(2 min(M,N), max(M,N), NRHS). */
    double minimum =
        3.0 * C2B_QUADRIC_UNKNOWNS + (double)(m > 2 * C2B_QUADRIC_UNKNOWNS ? m : 2 * C2B_QUADRIC_UNKNOWNS);
    /* That minimum also covers dgesvd of the n x 3 coordinates: max(3*3 + n, 5*3). */
    double lw = (info == 0 && query > minimum) ? query : minimum;
    if (lw > (double)INT_MAX)
        lw = minimum;
    ws->cap = cap;
    ws->lwork = (lapack_int)lw;
    ws->x = malloc(3 * cap * sizeof *ws->x);
    ws->a = malloc(C2B_QUADRIC_UNKNOWNS * cap * sizeof *ws->a);
    ws->b = malloc(cap * sizeof *ws->b);
    ws->s = malloc(C2B_QUADRIC_UNKNOWNS * sizeof *ws->s);
    ws->w = malloc((size_t)ws->lwork * sizeof *ws->w);
    if (!ws->x || !ws->a || !ws->b || !ws->s || !ws->w) {
        work_free(ws);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the fit of %zu neighbours", cap);
    }
    return C2B_OK;
}

/*
 * Eq. 23 (appendix A, eqs. 42-48) for F with coefficients c = (a .. i) at the origin:
 * normal, K, H, and k1 >= k2 from the shape operator in a tangent frame.
 */
static void curvature_from_coef(const double c[NMONO], double n[3], double *K, double *H, double *k1,
                                double *k2)
{
    const double G[3] = {c[MONO_X], c[MONO_Y], c[MONO_Z]};
    /* Hessian M (eq. 42), row-major, symmetric. */
    /* clang-format off */
    const double M[9] = {2 * c[MONO_XX], c[MONO_XY],     c[MONO_ZX],
                         c[MONO_XY],     2 * c[MONO_YY], c[MONO_YZ],
                         c[MONO_ZX],     c[MONO_YZ],     2 * c[MONO_ZZ]};
    /* clang-format on */
    /* Adjoint M* (eq. 43): the cofactor matrix, symmetric for symmetric M. */
    double A[9];
    A[0] = M[4] * M[8] - M[5] * M[7];
    A[4] = M[0] * M[8] - M[2] * M[6];
    A[8] = M[0] * M[4] - M[1] * M[3];
    A[1] = A[3] = M[2] * M[5] - M[1] * M[8];
    A[2] = A[6] = M[1] * M[5] - M[2] * M[4];
    A[5] = A[7] = M[1] * M[2] - M[0] * M[5];

    double D2 = c2b_vec3_dot(G, G), D = sqrt(D2);
    *K = quad_form(A, G, G) / (D2 * D2);                                  /* eq. 44 */
    *H = (quad_form(M, G, G) - D2 * (M[0] + M[4] + M[8])) / (2 * D2 * D); /* eq. 45 */
    for (int k = 0; k < 3; k++)
        n[k] = G[k] / D; /* eq. 46 */

    /* Orthonormal tangent frame: t1 = n x e_j (j the smallest |n_j|), t2 = n x t1. */
    int j = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(n[k]) < fabs(n[j]))
            j = k;
    double e[3] = {0, 0, 0}, t1[3], t2[3];
    e[j] = 1;
    c2b_vec3_cross(n, e, t1);
    double l = sqrt(c2b_vec3_dot(t1, t1));
    for (int k = 0; k < 3; k++)
        t1[k] /= l;
    c2b_vec3_cross(n, t1, t2);
    /* Shape operator s_ab = -t_a^T M t_b / D; H^2 - K = ((s11 - s22)/2)^2 + s12^2. */
    double s11 = -quad_form(M, t1, t1) / D, s22 = -quad_form(M, t2, t2) / D;
    double s12 = -quad_form(M, t1, t2) / D;
    double r = hypot(0.5 * (s11 - s22), s12);
    *k1 = *H + r;
    *k2 = *H - r;
}

/*
 * The fit of one neighbourhood; q holds n points (3 doubles each), ws has room for n.
 * Writes *out only on success.
 */
static c2b_status fit_core(const double *p, size_t n, const double *q, const double *hint, fit_work *ws,
                           c2b_quadric_result *out, c2b_error *err)
{
    if (n < C2B_QUADRIC_MIN_NEIGHBOURS)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "too few neighbours: %zu given, at least %d needed for the %d unknowns "
                             "of the implicit quadric (seed 002, section 6.2); use a larger ring",
                             n, C2B_QUADRIC_MIN_NEIGHBOURS, C2B_QUADRIC_UNKNOWNS);
    for (int k = 0; k < 3; k++)
        if (!isfinite(p[k]))
            return c2b_error_set(err, C2B_ERR_NUMERIC, "query point: coordinate %c = %g is not finite",
                                 XYZ[k], p[k]);
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(q[3 * i + (size_t)k]))
                return c2b_error_set(err, C2B_ERR_NUMERIC, "neighbour %zu: coordinate %c = %g is not finite",
                                     i, XYZ[k], q[3 * i + (size_t)k]);

    /* Step 1: translate p to the origin; scale by a power of two 2^e >= the radius. */
    double rho = 0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            double d = q[3 * i + (size_t)k] - p[k];
            if (!isfinite(d))
                return c2b_error_set(err, C2B_ERR_NUMERIC,
                                     "neighbour %zu: offset %c from the query point overflows", i, XYZ[k]);
            ws->x[3 * i + (size_t)k] = d;
            if (fabs(d) > rho)
                rho = fabs(d);
        }
    if (rho == 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "all %zu neighbours coincide with the query point", n);
    int ex;
    frexp(rho, &ex); /* rho = f 2^ex with f in [0.5, 1): rho < 2^ex */
    if (ex >= DBL_MAX_EXP)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "neighbourhood radius %g too large to scale", rho);
    for (size_t i = 0; i < 3 * n; i++)
        ws->x[i] = ldexp(ws->x[i], -ex);

    /* Degeneracy and the least-squares plane through p: SVD of the n x 3 matrix of local
     * coordinates (singular values accurate to eps relative to the largest, unlike the
     * eigenvalues of the scatter matrix, which square them). */
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            ws->a[(size_t)k * n + i] = ws->x[3 * i + (size_t)k];
    double sv[3], vt[9];
    lapack_int info = LAPACKE_dgesvd_work(LAPACK_COL_MAJOR, 'N', 'A', (lapack_int)n, 3, ws->a, (lapack_int)n,
                                          sv, NULL, 1, vt, 3, ws->w, ws->lwork);
    if (info != 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "SVD of the neighbourhood coordinates failed (LAPACK dgesvd info %d)",
                             (int)info);
    if (sv[1] <= C2B_QUADRIC_RCOND * sv[0])
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "the %zu neighbours are collinear with the query point (singular values of "
                             "the local coordinates %.3g, %.3g, %.3g): no quadric is determined",
                             n, sv[0], sv[1], sv[2]);
    if (sv[2] <= C2B_QUADRIC_RCOND * sv[0])
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "the %zu neighbours are coplanar with the query point (singular values of "
                             "the local coordinates %.3g, %.3g, %.3g): every quadric containing the plane "
                             "fits, the 8-unknown system has rank <= 5",
                             n, sv[0], sv[1], sv[2]);
    /* The right singular vector of the smallest singular value: row 2 of V^T. */
    const double plane_normal[3] = {vt[2], vt[5], vt[8]};

    /* Steps 3-4: the tentative normal selects the coefficient of g, h, i set to 1. */
    const double *tn = hint ? hint : plane_normal;
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(tn[k]) > fabs(tn[axis]))
            axis = k;
    int col[C2B_QUADRIC_UNKNOWNS], nc = 0;
    for (int k = 0; k < NMONO; k++)
        if (k != MONO_X + axis)
            col[nc++] = k;

    /* Step 5 / eqs. 20-22: one row F(x_i) = 0 per neighbour, j = 0 (step 2). */
    for (size_t i = 0; i < n; i++) {
        double mono[NMONO];
        monomials(ws->x + 3 * i, mono);
        for (int j = 0; j < C2B_QUADRIC_UNKNOWNS; j++)
            ws->a[(size_t)j * n + i] = mono[col[j]];
        ws->b[i] = -mono[MONO_X + axis];
    }
    lapack_int rank = 0;
    info = LAPACKE_dgelss_work(LAPACK_COL_MAJOR, (lapack_int)n, C2B_QUADRIC_UNKNOWNS, 1, ws->a, (lapack_int)n,
                               ws->b, (lapack_int)n, ws->s, C2B_QUADRIC_RCOND, &rank, ws->w, ws->lwork);
    if (info != 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "least-squares solve failed (LAPACK dgelss info %d%s)",
                             (int)info, info > 0 ? ": the SVD did not converge" : "");
    const double *s = ws->s;
    if (rank < C2B_QUADRIC_UNKNOWNS)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "rank-deficient: the 8-unknown system (seed 002, eqs. 20-21) of %zu "
                             "neighbours has numerical rank %d < 8 (relative threshold %g; singular "
                             "values relative to the largest: %.2g %.2g %.2g %.2g %.2g %.2g %.2g); the "
                             "neighbours do not determine a unique quadric",
                             n, (int)rank, C2B_QUADRIC_RCOND, s[1] / s[0], s[2] / s[0], s[3] / s[0],
                             s[4] / s[0], s[5] / s[0], s[6] / s[0], s[7] / s[0]);

    c2b_quadric_result res;
    memset(&res, 0, sizeof res);
    for (int j = 0; j < C2B_QUADRIC_UNKNOWNS; j++)
        res.coef[col[j]] = ws->b[j];
    res.coef[MONO_X + axis] = 1;
    res.axis = axis;
    res.condition = s[0] / s[C2B_QUADRIC_UNKNOWNS - 1];

    double Ks, Hs, k1s, k2s;
    curvature_from_coef(res.coef, res.normal, &Ks, &Hs, &k1s, &k2s);
    const double *g = res.coef + MONO_X;
    if (hint && c2b_vec3_dot(g, hint) < 0) {
        for (int k = 0; k < NMONO; k++)
            res.coef[k] = -res.coef[k];
        for (int k = 0; k < 3; k++)
            res.normal[k] = -res.normal[k];
        Hs = -Hs;
        double t = k1s;
        k1s = -k2s;
        k2s = -t;
    }

    /* Residual: RMS of F(x_i) / |grad F(0)|, back in model units. */
    double D = sqrt(c2b_vec3_dot(g, g)), ss = 0;
    for (size_t i = 0; i < n; i++) {
        double mono[NMONO], f = 0;
        monomials(ws->x + 3 * i, mono);
        for (int k = 0; k < NMONO; k++)
            f += res.coef[k] * mono[k];
        ss += f * f;
    }
    res.residual = ldexp(sqrt(ss / (double)n) / D, ex);
    res.scale = ldexp(1.0, ex);

    /* Undo the scaling: lengths were divided by 2^ex. */
    res.K = ldexp(Ks, -2 * ex);
    res.H = ldexp(Hs, -ex);
    res.k1 = ldexp(k1s, -ex);
    res.k2 = ldexp(k2s, -ex);
    if (!isfinite(res.K) || !isfinite(res.H) || !isfinite(res.k1) || !isfinite(res.k2) ||
        !isfinite(res.normal[0]) || !isfinite(res.normal[1]) || !isfinite(res.normal[2]) ||
        !isfinite(res.residual))
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "curvature does not fit a double (K = %g, H = %g at scale 2^%d)", res.K, res.H,
                             ex);
    *out = res;
    return C2B_OK;
}

static c2b_status check_hint(const double *h, const char *name, c2b_error *err)
{
    for (int k = 0; k < 3; k++)
        if (!isfinite(h[k]))
            return c2b_error_set(err, C2B_ERR_ARG, "%s: component %c = %g is not finite", name, XYZ[k], h[k]);
    if (h[0] == 0 && h[1] == 0 && h[2] == 0)
        return c2b_error_set(err, C2B_ERR_ARG, "%s is the zero vector", name);
    return C2B_OK;
}

c2b_status c2b_quadric_estimate(const double *p, size_t n_nbrs, const double *nbr_xyz,
                                const double *normal_hint, c2b_quadric_result *out, c2b_error *err)
{
    if (!p || !out || (n_nbrs > 0 && !nbr_xyz))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_quadric_estimate: %s is NULL",
                             !p     ? "p"
                             : !out ? "out"
                                    : "nbr_xyz");
    if (normal_hint) {
        c2b_status st = check_hint(normal_hint, "normal_hint", err);
        if (st != C2B_OK)
            return st;
    }
    if (n_nbrs < C2B_QUADRIC_MIN_NEIGHBOURS) /* before allocating */
        return fit_core(p, n_nbrs, nbr_xyz, normal_hint, NULL, out, err);
    fit_work ws;
    c2b_status st = work_alloc(&ws, n_nbrs, err);
    if (st != C2B_OK)
        return st;
    st = fit_core(p, n_nbrs, nbr_xyz, normal_hint, &ws, out, err);
    work_free(&ws);
    return st;
}

static void fill_nan(c2b_quadric_result *r)
{
    double nan = NAN;
    r->normal[0] = r->normal[1] = r->normal[2] = nan;
    r->K = r->H = r->k1 = r->k2 = r->residual = r->condition = r->scale = nan;
    for (int k = 0; k < NMONO; k++)
        r->coef[k] = nan;
    r->axis = -1;
}

c2b_status c2b_quadric_estimate_mesh(const c2b_quadric_mesh *m, const c2b_quadric_neighbourhoods *nb,
                                     const double *normals, c2b_quadric_result *out, unsigned char *ok,
                                     c2b_error *err)
{
    if (!m || !nb || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_quadric_estimate_mesh: %s is NULL",
                             !m    ? "mesh"
                             : !nb ? "neighbourhoods"
                                   : "out");
    if (m->nv > 0 && !m->xyz)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_quadric_estimate_mesh: mesh xyz is NULL");
    if (m->nv != nb->nv || m->nt != nb->nt)
        return c2b_error_set(err, C2B_ERR_ARG,
                             "the neighbourhoods were built for %zu vertices and %zu triangles, the mesh "
                             "has %zu and %zu",
                             nb->nv, nb->nt, m->nv, m->nt);
    if (nb->nt > 0 && !m->tri)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_quadric_estimate_mesh: mesh tri is NULL");
    if (normals)
        for (size_t v = 0; v < m->nv; v++)
            for (int k = 0; k < 3; k++)
                if (!isfinite(normals[3 * v + (size_t)k]))
                    return c2b_error_set(err, C2B_ERR_ARG, "normals[%zu]: component %c = %g is not finite", v,
                                         XYZ[k], normals[3 * v + (size_t)k]);
    if (m->nv == 0)
        return C2B_OK;

    fit_work ws;
    c2b_status st = work_alloc(&ws, nb->max_count, err);
    if (st != C2B_OK)
        return st;
    double *q = malloc(3 * ws.cap * sizeof *q);
    if (!q) {
        work_free(&ws);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for the neighbour coordinates");
    }

    size_t nfail = 0, first = 0;
    c2b_error first_err, tmp;
    c2b_error_clear(&first_err);
    for (size_t v = 0; v < m->nv; v++) {
        size_t cnt = nb->off[v + 1] - nb->off[v];
        const size_t *list = nb->nbr + nb->off[v];
        for (size_t i = 0; i < cnt; i++)
            memcpy(q + 3 * i, m->xyz + 3 * list[i], 3 * sizeof *q);

        double hint[3] = {0, 0, 0};
        if (normals) {
            memcpy(hint, normals + 3 * v, sizeof hint);
        } else {
            /* Seed 002, section 6.2: "a cross-product between two adjacent edges". */
            for (size_t k = nb->vt_off[v]; k < nb->vt_off[v + 1]; k++) {
                const size_t *t = m->tri + 3 * nb->vt[k];
                const double *a = m->xyz + 3 * t[0], *b = m->xyz + 3 * t[1], *c = m->xyz + 3 * t[2];
                double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
                double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]}, cr[3];
                c2b_vec3_cross(e1, e2, cr);
                for (int j = 0; j < 3; j++)
                    hint[j] += cr[j];
            }
        }
        int has_hint = isfinite(hint[0]) && isfinite(hint[1]) && isfinite(hint[2]) &&
                       (hint[0] != 0 || hint[1] != 0 || hint[2] != 0);

        c2b_error_clear(&tmp);
        st = fit_core(m->xyz + 3 * v, cnt, q, has_hint ? hint : NULL, &ws, out + v, &tmp);
        if (st == C2B_OK) {
            if (ok)
                ok[v] = 1;
            continue;
        }
        if (st != C2B_ERR_NUMERIC) { /* not expected: the workspace is preallocated */
            free(q);
            work_free(&ws);
            if (err)
                *err = tmp;
            c2b_error_prefix(err, "vertex %zu: ", v);
            return st;
        }
        fill_nan(out + v);
        if (ok)
            ok[v] = 0;
        if (nfail++ == 0) {
            first = v;
            first_err = tmp;
        }
    }
    free(q);
    work_free(&ws);
    if (nfail == 0)
        return C2B_OK;
    return c2b_error_set(err, C2B_ERR_NUMERIC, "vertex %zu: %.900s [%zu of %zu vertices failed]", first,
                         first_err.msg, nfail, m->nv);
}
