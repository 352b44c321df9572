/*
 * The papers' comparison examples, shared by tests/approx and bench/compare:
 *  - seed 001 eq. 17 (section 3): closed form (c2b_blend from examples/seed001_eq17.json)
 *    against closed form of the first-group data + pseudo-Navier for a2 e^v (eq. 18);
 *  - thesis eqs. 127-129 (Table 3) and 87-88 (Table 1): exact closed form (c2b_blend from
 *    the example specs) against thesis-approx with closed-form v-derivatives of the data.
 * Error measures: seed 001 eq. 24 and thesis section 3.3.2.1 (E1-E4).
 */
#ifndef C2B_APPROX_EXAMPLES_H
#define C2B_APPROX_EXAMPLES_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_approx.h"
#include "c2b_constants.h"
#include "c2b_blend.h"
#include "c2b_navier.h"
#include "c2b_spec.h"
#include "cheb_bvp.h"

#ifndef C2B_EXAMPLES_DIR
#error "define C2B_EXAMPLES_DIR"
#endif

/* ---- data functions with closed-form v-derivatives ---- */

/* amp * e^{k v} */
typedef struct ex_exp { double amp, k; } ex_exp;
static inline double ex_exp_fn(void *ctx, int k, double v, double t)
{
    const ex_exp *e = ctx;
    (void)t;
    return e->amp * pow(e->k, k) * exp(e->k * v);
}

/* amp(t) * trig(2 pi v): kind 0 sin, 1 cos; amp = a0 + a1 * exp(s t) (thesis data) */
typedef struct ex_trig { double a0, a1, s, w; int cosine; } ex_trig;
static inline double ex_trig_fn(void *ctx, int k, double v, double t)
{
    const ex_trig *e = ctx;
    double amp = e->a0 + e->a1 * exp(e->s * t), ph = e->w * v + (e->cosine ? C2B_PI / 2 : 0) + k * C2B_PI / 2;
    return amp * pow(e->w, k) * sin(ph);
}

/* a constant (k = 0 only) */
typedef struct ex_const { double c; } ex_const;
static inline double ex_const_fn(void *ctx, int k, double v, double t)
{
    (void)v, (void)t;
    return k == 0 ? ((const ex_const *)ctx)->c : 0.0;
}

static inline char *ex_read(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", C2B_EXAMPLES_DIR, name);
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, fp) != (size_t)n) {
        free(s);
        s = NULL;
    }
    if (s)
        s[n] = 0;
    fclose(fp);
    return s;
}

/* Load an example spec, optionally replacing the text `from` by `to` first. */
static inline c2b_spec *ex_spec(const char *name, const char *from, const char *to)
{
    char *s = ex_read(name);
    if (!s)
        return NULL;
    if (from) {
        char *p = strstr(s, from);
        if (!p) {
            free(s);
            return NULL;
        }
        size_t n = strlen(s) + strlen(to) + 1;
        char *r = malloc(n);
        memcpy(r, s, (size_t)(p - s));
        strcpy(r + (p - s), to);
        strcat(r, p + strlen(from));
        free(s);
        s = r;
    }
    c2b_spec *sp = NULL;
    c2b_error err;
    if (c2b_spec_parse(s, strlen(s), &sp, &err))
        fprintf(stderr, "%s: %s\n", name, err.msg);
    free(s);
    return sp;
}

/* ---- error measures ---- */

/* seed 001 eq. 24: mean over points of |p - q| / |q| (q the reference). */
static inline double ex_seed001_error(size_t npts, const double *p, const double *q)
{
    double sum = 0;
    for (size_t i = 0; i < npts; i++) {
        double d2 = 0, n2 = 0;
        for (int c = 0; c < 3; c++) {
            double d = p[3 * i + c] - q[3 * i + c];
            d2 += d * d;
            n2 += q[3 * i + c] * q[3 * i + c];
        }
        sum += sqrt(d2) / sqrt(n2);
    }
    return sum / (double)npts;
}

/* thesis section 3.3.2.1: E1 max distance, E2 mean distance, E3 = E1/D, E4 = E2/D, with D
 * the largest distance between two points of the reference with the same u (rows of nv
 * points, index i * nv + j). e[0..3] = E1..E4, e[4] = D. */
static inline void ex_thesis_errors(size_t nu, size_t nv, const double *p, const double *q, double *e)
{
    double emax = 0, esum = 0, D = 0;
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            const double *a = p + 3 * (i * nv + j), *b = q + 3 * (i * nv + j);
            double d = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                            (a[2] - b[2]) * (a[2] - b[2]));
            emax = fmax(emax, d);
            esum += d;
            for (size_t k = j + 1; k < nv; k++) {
                const double *c = q + 3 * (i * nv + k);
                double dd = (b[0] - c[0]) * (b[0] - c[0]) + (b[1] - c[1]) * (b[1] - c[1]) +
                            (b[2] - c[2]) * (b[2] - c[2]);
                D = fmax(D, dd);
            }
        }
    D = sqrt(D);
    e[0] = emax;
    e[1] = esum / (double)(nu * nv);
    e[2] = emax / D;
    e[3] = e[1] / D;
    e[4] = D;
}

static inline void ex_linspace(size_t n, double a, double b, double *x)
{
    for (size_t i = 0; i < n; i++)
        x[i] = a + (b - a) * (double)i / (double)(n - 1);
}

/* ---- thesis examples as v-derivative data ----
 * eqs. 127-129 (cones, trimlines u0, u1) and 87-88 (cylinders, trimlines u1, u2):
 * x: C1 = a u0 e^t sin, C2 = -a e^t sin, C4 = c u1 e^{-t} sin, C5 = c e^{-t} sin
 * y: C1 = b u0 e^{-t} cos, C2 = -b e^{-t} cos, C4 = d u1 e^t cos, C5 = d e^t cos
 * z: constants. Cylinders (87): the x/y u-derivatives vanish (u does not appear). */
typedef struct ex_thesis {
    ex_trig trig[2][2][2]; /* [x/y][side][order] */
    ex_const zc[2][3];
    c2b_vdata vd;
    double shape[3][5];
    c2b_vdomain dom;
    double t;
} ex_thesis;

/* which = 0: eqs. 127-129 at t = 0.1; which = 1: eqs. 87-88 at t = 0.2 */
static inline void ex_thesis_init(ex_thesis *x, int which)
{
    memset(x, 0, sizeof *x);
    const double w = 2 * C2B_PI;
    double a, b, c, d, h1, h2, h3, u0, u1;
    int cones = which == 0;
    if (cones)
        a = 3.6, b = 5.5, c = 6.0, d = 3.0, h1 = 2, h2 = 6, h3 = 20, u0 = 0.4, u1 = 0.55, x->t = 0.1;
    else
        a = 1.6, b = 1.0, c = 0.8, d = 0.6, h1 = 2, h2 = 3, h3 = 5, u0 = 0.2, u1 = 0.3, x->t = 0.2;
    double s0 = cones ? u0 : 1.0, s1 = cones ? u1 : 1.0;
    /* x (sin): side 0 amplitude a e^t, side 1 c e^{-t}; y (cos): b e^{-t}, d e^t */
    ex_trig tx0 = {0, a * s0, 1, w, 0}, tx1 = {0, c * s1, -1, w, 0};
    ex_trig ty0 = {0, b * s0, -1, w, 1}, ty1 = {0, d * s1, 1, w, 1};
    ex_trig dx0 = {0, -a, 1, w, 0}, dx1 = {0, c, -1, w, 0};
    ex_trig dy0 = {0, -b, -1, w, 1}, dy1 = {0, d, 1, w, 1};
    x->trig[0][0][0] = tx0, x->trig[0][1][0] = tx1, x->trig[1][0][0] = ty0, x->trig[1][1][0] = ty1;
    x->trig[0][0][1] = dx0, x->trig[0][1][1] = dx1, x->trig[1][0][1] = dy0, x->trig[1][1][1] = dy1;
    for (int cc = 0; cc < 2; cc++)
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < (cones ? 2 : 1); p++) {
                c2b_vdfunc f = {ex_trig_fn, &x->trig[cc][side][p], 1};
                x->vd.f[cc][side][p] = f;
            }
    /* z: h1 + h2 u0^2, -2 h2 u0, 2 h2 | -h3 u1^3, -3 h3 u1^2, -6 h3 u1 */
    double z[2][3] = {{h1 + h2 * u0 * u0, -2 * h2 * u0, 2 * h2}, {-h3 * u1 * u1 * u1, -3 * h3 * u1 * u1, -6 * h3 * u1}};
    for (int side = 0; side < 2; side++)
        for (int p = 0; p < 3; p++) {
            x->zc[side][p].c = z[side][p];
            c2b_vdfunc f = {ex_const_fn, &x->zc[side][p], 0};
            x->vd.f[2][side][p] = f;
        }
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 4; j++)
            x->shape[k][j] = 1.0;
    x->dom.v0 = 0, x->dom.v1 = 1, x->dom.periodic = 1;
}

/* The quintic Hermite basis g_1..g_6 at u (thesis eq. 18), written out independently of
 * the kernel's c2b_poly_hermite: g_l and its first two derivatives are 1 for datum l
 * (S, S_u, S_uu at u = 0, then at u = 1) and 0 for the others. */
static inline void ex_hermite5(double u, double g[6])
{
    double u2 = u * u, u3 = u2 * u;
    g[0] = 1 - 10 * u3 + 15 * u2 * u2 - 6 * u3 * u2;
    g[1] = (1 - 6 * u2 + 8 * u3 - 3 * u2 * u2) * u;
    g[2] = (0.5 - 1.5 * u + 1.5 * u2 - 0.5 * u3) * u2;
    g[3] = (10 - 15 * u + 6 * u2) * u3;
    g[4] = (-4 + 7 * u - 3 * u2) * u3;
    g[5] = (0.5 - u + 0.5 * u2) * u3;
}

/* Independent reference for the thesis examples (ex_thesis_init): each of x, y is G(u)
 * times sin/cos(2 pi v), G from the Chebyshev collocation oracle (tests/oracle) for the
 * mode beta = -(2 pi)^2; z is the quintic Hermite polynomial of its constants (thesis
 * eq. 18). s receives n x n points (u_i, v_j) at s[3 (i n + j) + c]. Returns 0, or 1
 * when the oracle fails. */
static inline int ex_oracle_surface(const ex_thesis *x, size_t n, const double *u, const double *v,
                                    double *s)
{
    double beta = -4 * C2B_PI * C2B_PI, c[4] = {1, beta, beta * beta, beta * beta * beta};
    double *G = malloc(sizeof(double) * 4 * n * 2);
    if (!G)
        return 1;
    for (int cc = 0; cc < 2; cc++) {
        double d[6] = {0};
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < 2; p++) {
                const ex_trig *tr = &x->trig[cc][side][p];
                if (x->vd.f[cc][side][p].fn) /* the cylinders have no u-derivative data */
                    d[3 * side + p] = tr->a0 + tr->a1 * exp(tr->s * x->t);
            }
        if (oracle_cheb_bvp(3, c, -1, NULL, d, 0, (int)n, u, G + 4 * n * cc, NULL)) {
            free(G);
            return 1;
        }
    }
    double zc[6];
    for (int l = 0; l < 6; l++)
        zc[l] = x->zc[l / 3][l % 3].c;
    for (size_t i = 0; i < n; i++) {
        double g[6], z = 0;
        ex_hermite5(u[i], g);
        for (int l = 0; l < 6; l++)
            z += zc[l] * g[l];
        for (size_t j = 0; j < n; j++) {
            double *p = s + 3 * (i * n + j);
            p[0] = G[4 * i] * sin(2 * C2B_PI * v[j]);
            p[1] = G[4 * n + 4 * i] * cos(2 * C2B_PI * v[j]);
            p[2] = z;
        }
    }
    free(G);
    return 0;
}

/* ---- seed 001 eq. 17 ---- */
typedef struct ex_seed001 {
    ex_exp ev;       /* a2 e^v, x at u = 0 */
    c2b_vdata vd;    /* only that datum */
    double shape[3][5];
    c2b_vdomain dom;
} ex_seed001;

static inline void ex_seed001_init(ex_seed001 *s)
{
    memset(s, 0, sizeof *s);
    s->ev.amp = 1.02e-4, s->ev.k = 1.0;
    c2b_vdfunc f = {ex_exp_fn, &s->ev, 0};
    s->vd.f[0][0][0] = f;
    for (int c = 0; c < 3; c++)
        s->shape[c][0] = 1, s->shape[c][1] = 18, s->shape[c][2] = 81;
    s->dom.v0 = 0, s->dom.v1 = 2 * C2B_PI, s->dom.periodic = 0;
}

/* ---- seed 001 eq. 20-21: the Fourier-series method (Bloor and Wilson) ----
 * Data of eq. 17 with v and e^v replaced by their N-term Fourier series on [0, 2 pi]
 * (eq. 20); every mode is then solved exactly by the kernel (eq. 21). */
typedef struct ex_fourier { double c0, c1, c2, r; int N, kind; } ex_fourier;
static inline double ex_fourier_fn(void *ctx, double v, double t)
{
    const ex_fourier *f = ctx;
    (void)t;
    switch (f->kind) {
    case 1: return -f->r * cos(v);
    case 2: return f->r * sin(v);
    case 3: return f->c0;
    default: break;
    }
    double sv = C2B_PI, se = 0.5;
    for (int n = 1; n <= f->N; n++) {
        sv -= 2.0 / n * sin(n * v);
        se += (cos(n * v) - n * sin(n * v)) / (1.0 + (double)n * n);
    }
    return f->c0 + f->c1 * sv + f->c2 * (exp(2 * C2B_PI) - 1) / C2B_PI * se;
}

typedef struct ex_fourier_problem { ex_fourier f[3][2][2]; c2b_problem pb; } ex_fourier_problem;

static inline void ex_fourier_init(ex_fourier_problem *q, int N)
{
    memset(q, 0, sizeof *q);
    q->pb = c2b_problem_default();
    q->pb.continuity = C2B_C1;
    for (int c = 0; c < 3; c++)
        q->pb.shape[c][0] = 1, q->pb.shape[c][1] = 18, q->pb.shape[c][2] = 81;
    q->pb.dom.v0 = 0, q->pb.dom.v1 = 2 * C2B_PI, q->pb.dom.periodic = 1;
    ex_fourier x0 = {-0.5, 0.158, 1.02e-4, 1, N, 0}, y0 = {1.5, -0.477, 0, 1, N, 0};
    ex_fourier x1 = {0, 0, 0, 1, N, 1}, y1 = {0, 0, 0, 1, N, 2};
    ex_fourier z00 = {2, 0, 0, 0, N, 3}, z01 = {-2, 0, 0, 0, N, 3}, z10 = {0, 0, 0, 0, N, 3}, z11 = {-2, 0, 0, 0, N, 3};
    q->f[0][0][0] = x0, q->f[0][1][0] = x1, q->f[1][0][0] = y0, q->f[1][1][0] = y1;
    q->f[2][0][0] = z00, q->f[2][0][1] = z01, q->f[2][1][0] = z10, q->f[2][1][1] = z11;
    for (int c = 0; c < 3; c++)
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < 2; p++)
                if (c == 2 || p == 0) {
                    c2b_bfunc b = {ex_fourier_fn, NULL, &q->f[c][side][p], 0, NULL, 0, 0, "seed 001 eq. 20"};
                    q->pb.data[c][side][p] = b;
                }
}

#endif
