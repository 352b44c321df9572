/* Thesis approximate analytic solutions (sections 3.3 and 3.4.1); see c2b_approx.h. */
#include "c2b_approx.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_constants.h"
#include "c2b_lsq.h"
#include "c2b_mode.h"
#include "c2b_operator.h"
#include "c2b_poly.h"

#define NDATA 3 /* constraints per trimline for C2 */
#define NPART 3 /* terms per datum: 1 (differential) or 3 (decomposition, see part_eval) */

typedef struct dsol {
    c2b_approx_group group;
    c2b_mode *closed;        /* group 2 in closed form (group2_closed): owned, else NULL */
    int rank;
    double c[C2B_APPROX_MAX_M];
    double resid_ss;         /* residual sum of squares of the fit, over resid_n points */
    long resid_n;
} dsol;

struct c2b_approx {
    double shape[C2B_NCOMP][5];
    c2b_vdomain dom;
    c2b_vdata data;
    c2b_approx_options opt;
    double t;
    double t0;               /* anchor time of the decomposition (the creation time) */
    double mean0[C2B_NCOMP][2][NDATA]; /* decomposition: mean over v of each datum at t0 */
    double mean[C2B_NCOMP][2][NDATA];  /* ... and at the current time */
    int nparts;              /* 1 (differential) or NPART (decomposition) */
    c2b_poly g[2 * NDATA];   /* quintic Hermite basis, thesis eq. 18 / 65 / 107 */
    dsol sol[C2B_NCOMP][2][NDATA][NPART];
    /* workspace: collocation tables */
    double *phi;   /* [(NI+1)][4][M]: phi_m^{(0,2,4,6)}(u_i) */
    double *gk;    /* [(NI+1)][4][6]: g_l^{(0,2,4,6)}(u_i) */
    double *fv;    /* [(NJ+1)][4]: C^{(0,2,4,6)}(v_j) */
    double *A, *b;
};

c2b_approx_options c2b_approx_options_default(void)
{
    c2b_approx_options o = {20, 100, 100, 1e-13, 1e-12, C2B_APPROX_DIFFERENTIAL, 0};
    return o;
}

/* phi_m^{(k)}(u) = m pi f_m^{(k)}(u) - (m pi)^k sin(m pi u + k pi/2), f_m = g2 + (-1)^m g5
 * (thesis eq. 120; g2, g5 are basis[1], basis[4]). */
static double phi_deriv(const c2b_poly *g, int m, int k, double u)
{
    double d2[7], d5[7];
    c2b_poly_eval(&g[1], u, k, d2);
    c2b_poly_eval(&g[4], u, k, d5);
    double w = m * C2B_PI, sgn = (m % 2) ? -1.0 : 1.0;
    double s;
    switch (k % 4) {
    case 0: s = sin(w * u); break;
    case 1: s = cos(w * u); break;
    case 2: s = -sin(w * u); break;
    default: s = -cos(w * u); break;
    }
    return w * (d2[k] + sgn * d5[k]) - pow(w, k) * s;
}

static double poly_d(const c2b_poly *p, int k, double u)
{
    double d[7];
    c2b_poly_eval(p, u, k, d);
    return d[k];
}

static void free_work(c2b_approx *a)
{
    free(a->phi);
    free(a->gk);
    free(a->fv);
    free(a->A);
    free(a->b);
    a->phi = a->gk = a->fv = a->A = a->b = NULL;
}

/* Each datum term of sol, in order (count C2B_NCOMP * 2 * NDATA * NPART). */
#define SOL_TERMS(sol) (&(sol)[0][0][0][0])
#define NTERMS (C2B_NCOMP * 2 * NDATA * NPART)

void c2b_approx_destroy(c2b_approx *a)
{
    if (!a)
        return;
    for (int e = 0; e < NTERMS; e++)
        c2b_mode_destroy(SOL_TERMS(a->sol)[e].closed);
    free_work(a);
    free(a);
}

static double grid_v(const c2b_approx *a, int j)
{
    return a->dom.v0 + (a->dom.v1 - a->dom.v0) * j / a->opt.cj;
}

static const char *const PART_NAME[NPART] = {"constant and t-only part", "v-only part", "(v, t) part"};

/* d^k/dv^k of term `part` of datum l = (c, side, p), f, at (v, t), t being the current
 * time. Differential approach: the datum itself. Decomposition (thesis eq. 59), with
 * <C>(t) the mean over v (trapezoid rule on the collocation v's) and t0 the creation time:
 *   part 0  <C>(t)                                = C^(1) + C^(2)(t)
 *   part 1  C(v, t0) - <C>(t0)                    = C^(3)(v)
 *   part 2  C(v, t) - C(v, t0) - <C>(t) + <C>(t0) = C^(4)(v, t)
 * They sum to C(v, t) for any data. The mean (not the value at one v) makes the split
 * leave periodic modes such as cos(2 pi v) whole. */
static double part_eval(const c2b_approx *a, const c2b_vdfunc *f, int c, int side, int p, int part,
                        int k, double v, double t)
{
    if (a->nparts == 1)
        return f->fn(f->ctx, k, v, t);
    double m = a->mean[c][side][p], m0 = a->mean0[c][side][p];
    switch (part) {
    case 0:
        return k ? 0.0 : m;
    case 1:
        return f->fn(f->ctx, k, v, a->t0) - (k ? 0.0 : m0);
    default:
        if (!f->time_dependent)
            return 0.0;
        return f->fn(f->ctx, k, v, t) - f->fn(f->ctx, k, v, a->t0) - (k ? 0.0 : m - m0);
    }
}

/* Trapezoid mean over the collocation v's of datum f at time t. */
static double datum_mean(const c2b_approx *a, const c2b_vdfunc *f, double t)
{
    const int NJ = a->opt.cj;
    double sum = 0;
    for (int j = 0; j <= NJ; j++)
        sum += (j == 0 || j == NJ ? 0.5 : 1.0) * f->fn(f->ctx, 0, grid_v(a, j), t);
    return sum / NJ;
}

/* Classify and solve term `part` of one datum at time t into *s. */
static c2b_status solve_datum(c2b_approx *a, int c, int side, int p, int part, double t, dsol *s,
                              c2b_error *err)
{
    const c2b_vdfunc *f = &a->data.f[c][side][p];
    const int NI = a->opt.ci, NJ = a->opt.cj, M = a->opt.M;
    const int l = side * NDATA + p;
    memset(s, 0, sizeof *s);
    if (!f->fn)
        return C2B_OK;
    double scale = 0, d1 = 0, d2 = 0, beta_num = 0, beta_den = 0;
    for (int j = 0; j <= NJ; j++) {
        double v = grid_v(a, j), *fj = a->fv + 4 * j;
        for (int q = 0; q < 4; q++)
            fj[q] = part_eval(a, f, c, side, p, part, 2 * q, v, t);
        double f1 = part_eval(a, f, c, side, p, part, 1, v, t);
        for (int q = 0; q < 4; q++)
            if (!isfinite(fj[q]))
                return c2b_error_set(err, C2B_ERR_SPEC,
                                     "thesis-approx: datum %c, side %d, order %d: d^%d/dv^%d is not finite at v=%g, t=%g",
                                     "xyz"[c], side, p, 2 * q, 2 * q, v, t);
        scale = fmax(scale, fabs(fj[0]));
        d1 = fmax(d1, fabs(f1));
        d2 = fmax(d2, fabs(fj[1]));
        beta_num += fj[1] * fj[0];
        beta_den += fj[0] * fj[0];
    }
    if (scale == 0 && d2 == 0) {
        s->group = C2B_APPROX_ZERO;
        return C2B_OK;
    }
    double tol = a->opt.zero_rel * fmax(scale, 1e-300);
    int exact = a->opt.approach == C2B_APPROX_DECOMPOSITION ? (d1 <= tol && d2 <= tol) : (d2 <= tol);
    if (exact) {
        s->group = C2B_APPROX_HERMITE;
        return C2B_OK;
    }
    s->group = C2B_APPROX_SERIES;
    double beta = 0;
    if (beta_den > 0) {
        double dev = 0;
        beta = beta_num / beta_den;
        for (int j = 0; j <= NJ; j++)
            dev = fmax(dev, fabs(a->fv[4 * j + 1] - beta * a->fv[4 * j]));
        if (dev <= 1e3 * a->opt.zero_rel * fmax(d2, 1e-300))
            s->group = C2B_APPROX_MODE;
    }
    char what[96];
    snprintf(what, sizeof what, "thesis-approx: datum %c, side %d, order %d%s%s", "xyz"[c], side, p,
             a->nparts > 1 ? ", " : "", a->nparts > 1 ? PART_NAME[part] : "");
    const double *sh = a->shape[c];
    if (s->group == C2B_APPROX_MODE && a->opt.group2_closed) {
        /* H_l: the mode ODE's response to unit datum l (thesis section 3.4.1, group 2) */
        c2b_operator op;
        c2b_status st = c2b_operator_init(&op, C2B_C2, sh, 4, err);
        if (!st)
            st = c2b_mode_create(&op, beta, NULL, &s->closed, err);
        if (st)
            c2b_error_prefix(err, "%s (closed form, beta = %g): ", what, beta);
        return st;
    }
    /* Residual rows (eq. 123): alpha_m(u_i, v_j), rhs phi(u_i, v_j) (eq. 122). */
    const long rows = (long)(NI + 1) * (NJ + 1);
    for (int i = 0; i <= NI; i++) {
        const double *ph = a->phi + (size_t)i * 4 * M;
        const double *gl = a->gk + (size_t)i * 4 * 6;
        for (int j = 0; j <= NJ; j++) {
            const double *fj = a->fv + 4 * j;
            long r = (long)i * (NJ + 1) + j;
            /* L[h f] = gamma h6 f + eta h4 f2 + lambda h2 f4 + rho h f6 */
            for (int m = 0; m < M; m++)
                a->A[r + rows * m] = sh[0] * ph[3 * M + m] * fj[0] + sh[1] * ph[2 * M + m] * fj[1] +
                                     sh[2] * ph[1 * M + m] * fj[2] + sh[3] * ph[m] * fj[3];
            a->b[r] = sh[0] * gl[3 * 6 + l] * fj[0] + sh[1] * gl[2 * 6 + l] * fj[1] +
                      sh[2] * gl[1 * 6 + l] * fj[2] + sh[3] * gl[l] * fj[3];
        }
    }
    int rank = 0;
    double rs = 0;
    c2b_status st = c2b_lsq_solve(rows, M, a->A, a->b, a->opt.rcond, s->c, &rank, &rs, what, err);
    if (st)
        return st;
    if (rank < M)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "%s: least squares rank %d < M = %d (reduce M or refine the collocation grid)",
                             what, rank, M);
    s->rank = rank;
    s->resid_ss = rs;
    s->resid_n = rows;
    return C2B_OK;
}

static c2b_status solve_all(c2b_approx *a, double t, int only_time_dependent, c2b_error *err)
{
    dsol tmp[C2B_NCOMP][2][NDATA][NPART];
    int redone[NTERMS] = {0}; /* terms solved anew: their closed-form modes are tmp's own */
    double mean_prev[C2B_NCOMP][2][NDATA];
    memcpy(tmp, a->sol, sizeof tmp);
    memcpy(mean_prev, a->mean, sizeof mean_prev);
    if (a->nparts > 1)
        for (int c = 0; c < C2B_NCOMP; c++)
            for (int side = 0; side < 2; side++)
                for (int p = 0; p < NDATA; p++) {
                    const c2b_vdfunc *f = &a->data.f[c][side][p];
                    if (f->fn && (!only_time_dependent || f->time_dependent))
                        a->mean[c][side][p] = datum_mean(a, f, t);
                }
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < NDATA; p++)
                for (int part = 0; part < a->nparts; part++) {
                    /* a new time changes only time-dependent data, and of the
                     * decomposition only the parts 0 and 2 */
                    if (only_time_dependent &&
                        (!a->data.f[c][side][p].time_dependent || part == 1))
                        continue;
                    redone[&tmp[c][side][p][part] - SOL_TERMS(tmp)] = 1;
                    c2b_status st = solve_datum(a, c, side, p, part, t, &tmp[c][side][p][part], err);
                    if (st) {
                        for (int e = 0; e < NTERMS; e++)
                            if (redone[e])
                                c2b_mode_destroy(SOL_TERMS(tmp)[e].closed);
                        memcpy(a->mean, mean_prev, sizeof mean_prev);
                        return st;
                    }
                }
    for (int e = 0; e < NTERMS; e++)
        if (redone[e])
            c2b_mode_destroy(SOL_TERMS(a->sol)[e].closed);
    memcpy(a->sol, tmp, sizeof tmp);
    a->t = t;
    return C2B_OK;
}

c2b_status c2b_approx_create(const double shape[C2B_NCOMP][5], const c2b_vdomain *dom,
                             const c2b_vdata *data, double t, const c2b_approx_options *opt,
                             c2b_approx **out, c2b_error *err)
{
    if (!shape || !dom || !data || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_approx_create: NULL argument");
    *out = NULL;
    c2b_approx_options o = opt ? *opt : c2b_approx_options_default();
    if (o.M < 1 || o.M > C2B_APPROX_MAX_M)
        return c2b_error_set(err, C2B_ERR_ARG, "M: %d is outside 1..%d", o.M, C2B_APPROX_MAX_M);
    if (o.ci < 1 || o.cj < 1 || (long)(o.ci + 1) * (o.cj + 1) < o.M || o.ci > 100000 || o.cj > 100000)
        return c2b_error_set(err, C2B_ERR_ARG,
                             "collocation: [%d, %d] must be >= 1 with (I+1)(J+1) >= M = %d", o.ci, o.cj, o.M);
    if (!(o.rcond > 0 && o.rcond < 1) || !(o.zero_rel > 0 && o.zero_rel < 1))
        return c2b_error_set(err, C2B_ERR_ARG, "thesis-approx: rcond and zero_rel must be in (0, 1)");
    if (!isfinite(t))
        return c2b_error_set(err, C2B_ERR_ARG, "time: not finite");
    if (!(dom->v1 > dom->v0) || !isfinite(dom->v0) || !isfinite(dom->v1))
        return c2b_error_set(err, C2B_ERR_SPEC, "v_range: [%g, %g] is empty", dom->v0, dom->v1);
    c2b_status sst = c2b_operator_check_shapes(C2B_C2, C2B_NCOMP, shape, err);
    if (sst)
        return sst;
    c2b_approx *a = calloc(1, sizeof *a);
    if (!a)
        return c2b_error_set(err, C2B_ERR_NOMEM, "thesis-approx: out of memory");
    memcpy(a->shape, shape, sizeof a->shape);
    a->dom = *dom;
    a->data = *data;
    a->opt = o;
    a->t0 = t;
    a->nparts = o.approach == C2B_APPROX_DECOMPOSITION ? NPART : 1;
    c2b_status st = c2b_poly_hermite(NDATA, a->g, err);
    if (st) {
        c2b_approx_destroy(a);
        return st;
    }
    const int NI = o.ci, NJ = o.cj, M = o.M;
    const size_t rows = (size_t)(NI + 1) * (NJ + 1);
    a->phi = malloc(sizeof(double) * (size_t)(NI + 1) * 4 * M);
    a->gk = malloc(sizeof(double) * (size_t)(NI + 1) * 4 * 6);
    a->fv = malloc(sizeof(double) * (size_t)(NJ + 1) * 4);
    a->A = malloc(sizeof(double) * rows * M);
    a->b = malloc(sizeof(double) * rows);
    if (!a->phi || !a->gk || !a->fv || !a->A || !a->b) {
        c2b_approx_destroy(a);
        return c2b_error_set(err, C2B_ERR_NOMEM, "thesis-approx: out of memory for a %zu x %d system",
                             rows, M);
    }
    for (int i = 0; i <= NI; i++) {
        double u = (double)i / NI;
        for (int q = 0; q < 4; q++) {
            for (int m = 0; m < M; m++)
                a->phi[(size_t)i * 4 * M + q * M + m] = phi_deriv(a->g, m + 1, 2 * q, u);
            for (int l = 0; l < 6; l++)
                a->gk[(size_t)i * 24 + q * 6 + l] = poly_d(&a->g[l], 2 * q, u);
        }
    }
    if (a->nparts > 1)
        for (int c = 0; c < C2B_NCOMP; c++)
            for (int side = 0; side < 2; side++)
                for (int p = 0; p < NDATA; p++)
                    if (a->data.f[c][side][p].fn)
                        a->mean0[c][side][p] = datum_mean(a, &a->data.f[c][side][p], t);
    st = solve_all(a, t, 0, err);
    if (st) {
        c2b_approx_destroy(a);
        return st;
    }
    *out = a;
    return C2B_OK;
}

c2b_status c2b_approx_set_time(c2b_approx *a, double t, c2b_error *err)
{
    if (!a || !isfinite(t))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_approx_set_time: NULL object or non-finite t");
    return solve_all(a, t, 1, err);
}

c2b_status c2b_approx_eval_grid(const c2b_approx *a, size_t nu, const double *u, size_t nv,
                                const double *v, int order, double *out, c2b_error *err)
{
    if (!a || (!u && nu) || (!v && nv) || (!out && nu && nv) || order < 0 || order > 2)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_approx_eval_grid: NULL buffer or order outside 0..2");
    const int nd = (order + 1) * (order + 2) / 2, M = a->opt.M;
    const int nk = order + 1; /* u- and v-derivatives 0..order */
    const int nt = 6 * a->nparts; /* terms per component: datum l, part q at l * nparts + q */
    double *hu = malloc(sizeof(double) * (nu ? nu : 1) * C2B_NCOMP * nt * nk);
    double *fvv = malloc(sizeof(double) * (nv ? nv : 1) * C2B_NCOMP * nt * nk);
    if (!hu || !fvv) {
        free(hu);
        free(fvv);
        return c2b_error_set(err, C2B_ERR_NOMEM, "c2b_approx_eval_grid: out of memory");
    }
    /* H_l^{(k)}(u_i) per component and datum */
    for (size_t i = 0; i < nu; i++) {
        double gd[6][3], ph[C2B_APPROX_MAX_M][3];
        for (int l = 0; l < 6; l++) {
            double d[7];
            c2b_poly_eval(&a->g[l], u[i], order, d);
            for (int k = 0; k < nk; k++)
                gd[l][k] = d[k];
        }
        for (int m = 0; m < M; m++)
            for (int k = 0; k < nk; k++)
                ph[m][k] = phi_deriv(a->g, m + 1, k, u[i]);
        for (int c = 0; c < C2B_NCOMP; c++)
            for (int e = 0; e < nt; e++) {
                int l = e / a->nparts;
                const dsol *s = &a->sol[c][l / NDATA][l % NDATA][e % a->nparts];
                double hc[4] = {0};
                if (s->closed) {
                    double unit[2 * NDATA] = {0};
                    unit[l] = 1.0;
                    c2b_mode_eval(s->closed, unit, u[i], order, hc);
                }
                for (int k = 0; k < nk; k++) {
                    double h = s->closed ? hc[k] : gd[l][k];
                    if (s->group >= C2B_APPROX_MODE && !s->closed)
                        for (int m = 0; m < M; m++)
                            h -= s->c[m] * ph[m][k];
                    hu[((i * C2B_NCOMP + c) * nt + e) * nk + k] = s->group ? h : 0.0;
                }
            }
    }
    for (size_t j = 0; j < nv; j++)
        for (int c = 0; c < C2B_NCOMP; c++)
            for (int e = 0; e < nt; e++) {
                int l = e / a->nparts;
                const c2b_vdfunc *f = &a->data.f[c][l / NDATA][l % NDATA];
                for (int k = 0; k < nk; k++)
                    fvv[((j * C2B_NCOMP + c) * nt + e) * nk + k] =
                        f->fn ? part_eval(a, f, c, l / NDATA, l % NDATA, e % a->nparts, k, v[j], a->t)
                              : 0.0;
            }
    static const int du[6] = {0, 1, 0, 2, 1, 0}, dv[6] = {0, 0, 1, 0, 1, 2};
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            double *o = out + (i * nv + j) * (size_t)nd * 3;
            for (int e = 0; e < nd; e++)
                for (int c = 0; c < C2B_NCOMP; c++) {
                    double sum = 0;
                    const double *h = hu + (i * C2B_NCOMP + c) * (size_t)nt * nk;
                    const double *f = fvv + (j * C2B_NCOMP + c) * (size_t)nt * nk;
                    for (int l = 0; l < nt; l++)
                        sum += h[l * nk + du[e]] * f[l * nk + dv[e]];
                    o[e * 3 + c] = sum;
                }
        }
    free(hu);
    free(fvv);
    return C2B_OK;
}

c2b_approx_group c2b_approx_datum(const c2b_approx *a, int c, int side, int p, int part,
                                  double *coef, int *rank)
{
    if (!a || c < 0 || c >= C2B_NCOMP || side < 0 || side > 1 || p < 0 || p >= NDATA ||
        part < 0 || part >= a->nparts)
        return C2B_APPROX_ZERO;
    const dsol *s = &a->sol[c][side][p][part];
    if (coef)
        for (int m = 0; m < a->opt.M; m++)
            coef[m] = s->group >= C2B_APPROX_MODE && !s->closed ? s->c[m] : 0.0;
    if (rank)
        *rank = s->rank;
    return s->group;
}

double c2b_approx_residual_rms(const c2b_approx *a)
{
    if (!a)
        return 0.0;
    double ss = 0;
    long n = 0;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int l = 0; l < 2 * NDATA; l++)
            for (int part = 0; part < a->nparts; part++) {
                ss += a->sol[c][l / NDATA][l % NDATA][part].resid_ss;
                n += a->sol[c][l / NDATA][l % NDATA][part].resid_n;
            }
    return n ? sqrt(ss / (double)n) : 0.0;
}
