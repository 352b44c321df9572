/* Seed 001 pseudo-Navier solution (eqs. 9-15); see c2b_navier.h. */
#include "c2b_navier.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_constants.h"
#include "c2b_lsq.h"
#include "c2b_poly.h"

struct c2b_navier {
    double shape[C2B_NCOMP][5];
    c2b_vdomain dom;
    c2b_vdata data;
    c2b_navier_options opt;
    double t, kappa;          /* w = kappa (v - v0) */
    c2b_poly h[4];            /* cubic Hermite basis: [S(0), Su(0), S(1), Su(1)] */
    double *A[C2B_NCOMP];     /* M*N coefficients, NULL when the component has no data */
};

c2b_navier_options c2b_navier_options_default(void)
{
    c2b_navier_options o = {3, 3, 6, 6, C2B_NAVIER_GRID_INTERIOR, 1e-13};
    return o;
}

/* d^k/du^k [u (u-1)^2 sin(m u)] by Leibniz (p = u^3 - 2u^2 + u). */
static double q_deriv(int m, int k, double u)
{
    double p[4] = {u * (u - 1) * (u - 1), 3 * u * u - 4 * u + 1, 6 * u - 4, 6};
    double sum = 0, binom = 1;
    for (int j = 0; j <= k && j <= 3; j++) {
        int r = k - j;
        double s;
        switch (r % 4) {
        case 0: s = sin(m * u); break;
        case 1: s = cos(m * u); break;
        case 2: s = -sin(m * u); break;
        default: s = -cos(m * u); break;
        }
        sum += binom * p[j] * pow(m, r) * s;
        binom = binom * (k - j) / (j + 1);
    }
    return sum;
}

void c2b_navier_destroy(c2b_navier *nv)
{
    if (!nv)
        return;
    for (int c = 0; c < C2B_NCOMP; c++)
        free(nv->A[c]);
    free(nv);
}

static double colloc(int i, int NI, c2b_navier_grid g)
{
    return g == C2B_NAVIER_GRID_CLOSED ? (double)i / NI : (double)(i + 1) / (NI + 2);
}

static c2b_status solve_component(c2b_navier *nv, int c, c2b_error *err)
{
    const c2b_navier_options *o = &nv->opt;
    const int M = o->M, N = o->N, nt = M * N;
    const int rows = (o->ci + 1) * (o->cj + 1);
    const double b = nv->shape[c][0], cc = nv->shape[c][1], d = nv->shape[c][2];
    double *A = malloc(sizeof(double) * (size_t)rows * nt);
    double *rhs = malloc(sizeof(double) * (size_t)rows);
    nv->A[c] = calloc((size_t)nt, sizeof(double));
    c2b_status st = C2B_OK;
    if (!A || !rhs || !nv->A[c]) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "pseudo-navier: out of memory");
        goto done;
    }
    for (int i = 0; i <= o->ci; i++) {
        double u = colloc(i, o->ci, o->grid), hd[4][3];
        for (int k = 0; k < 4; k++) {
            double e[5];
            c2b_poly_eval(&nv->h[k], u, 4, e);
            hd[k][0] = e[0], hd[k][1] = e[2], hd[k][2] = e[4];
        }
        double q0[64], q2[64], q4[64];
        for (int m = 1; m <= M; m++)
            q0[m - 1] = q_deriv(m, 0, u), q2[m - 1] = q_deriv(m, 2, u), q4[m - 1] = q_deriv(m, 4, u);
        for (int j = 0; j <= o->cj; j++) {
            double v = nv->dom.v0 + (nv->dom.v1 - nv->dom.v0) * colloc(j, o->cj, o->grid);
            int r = i * (o->cj + 1) + j;
            /* D: residual of the Hermite part, b H'''' g + c H'' g'' + d H g'''' (eq. 12) */
            double D = 0;
            for (int k = 0; k < 4; k++) {
                const c2b_vdfunc *f = &nv->data.f[c][k / 2][k % 2];
                if (!f->fn)
                    continue;
                double g0 = f->fn(f->ctx, 0, v, nv->t), g2 = f->fn(f->ctx, 2, v, nv->t),
                       g4 = f->fn(f->ctx, 4, v, nv->t);
                if (!isfinite(g0) || !isfinite(g2) || !isfinite(g4)) {
                    st = c2b_error_set(err, C2B_ERR_SPEC,
                                       "pseudo-navier: datum %c, side %d, order %d is not finite at v=%g",
                                       "xyz"[c], k / 2, k % 2, v);
                    goto done;
                }
                D += b * hd[k][2] * g0 + cc * hd[k][1] * g2 + d * hd[k][0] * g4;
            }
            rhs[r] = -D;
            /* B(u, m, n) sin(n w) (eq. 13, derived here from the trial function) */
            for (int m = 0; m < M; m++)
                for (int n = 1; n <= N; n++) {
                    double kn = n * nv->kappa;
                    A[r + (size_t)rows * (m * N + n - 1)] =
                        (b * q4[m] - cc * kn * kn * q2[m] + d * kn * kn * kn * kn * q0[m]) *
                        sin(kn * (v - nv->dom.v0));
                }
        }
    }
    /* A sine sin(n w) that vanishes at every collocation v makes its columns zero (up to
     * rounding); column scaling would hide that, so check it structurally. */
    for (int n = 1; n <= N; n++) {
        double vmax = 0;
        for (int j = 0; j <= o->cj; j++) {
            double v = nv->dom.v0 + (nv->dom.v1 - nv->dom.v0) * colloc(j, o->cj, o->grid);
            vmax = fmax(vmax, fabs(sin(n * nv->kappa * (v - nv->dom.v0))));
        }
        if (vmax < 1e-8) {
            st = c2b_error_set(err, C2B_ERR_NUMERIC,
                               "collocation: sin(%d w) vanishes at all %d collocation v of component %c, "
                               "so the least squares are rank deficient; use another grid or J",
                               n, o->cj + 1, "xyz"[c]);
            goto done;
        }
    }
    char what[48];
    snprintf(what, sizeof what, "pseudo-navier: component %c", "xyz"[c]);
    int rank = 0;
    st = c2b_lsq_solve(rows, nt, A, rhs, o->rcond, nv->A[c], &rank, NULL, what, err);
    if (!st && rank < nt)
        st = c2b_error_set(err, C2B_ERR_NUMERIC,
                           "%s: rank %d < M*N = %d at %d collocation points "
                           "(the sin(n w) columns vanish at v = v0 and v1)",
                           what, rank, nt, rows);
done:
    free(A);
    free(rhs);
    return st;
}

c2b_status c2b_navier_create(const double shape[C2B_NCOMP][5], const c2b_vdomain *dom,
                             const c2b_vdata *data, double t, const c2b_navier_options *opt,
                             c2b_navier **out, c2b_error *err)
{
    if (!shape || !dom || !data || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_navier_create: NULL argument");
    *out = NULL;
    c2b_navier_options o = opt ? *opt : c2b_navier_options_default();
    if (o.M < 1 || o.M > 64)
        return c2b_error_set(err, C2B_ERR_ARG, "M: %d is outside 1..64", o.M);
    if (o.N < 1 || o.N > 64 || o.M * o.N > C2B_NAVIER_MAX_TERMS)
        return c2b_error_set(err, C2B_ERR_ARG, "N: %d must be in 1..64 with M*N <= %d", o.N,
                             C2B_NAVIER_MAX_TERMS);
    if (o.ci < 1 || o.cj < 1 || o.ci > 10000 || o.cj > 10000 || (o.ci + 1) * (o.cj + 1) < o.M * o.N)
        return c2b_error_set(err, C2B_ERR_ARG, "collocation: [%d, %d] gives fewer than M*N = %d points",
                             o.ci, o.cj, o.M * o.N);
    if (!(o.rcond > 0 && o.rcond < 1))
        return c2b_error_set(err, C2B_ERR_ARG, "pseudo-navier: rcond must be in (0, 1)");
    if (!(dom->v1 > dom->v0) || !isfinite(dom->v0) || !isfinite(dom->v1) || !isfinite(t))
        return c2b_error_set(err, C2B_ERR_SPEC, "v_range: [%g, %g] is empty or time not finite",
                             dom->v0, dom->v1);
    c2b_status sst = c2b_operator_check_shapes(C2B_C1, C2B_NCOMP, shape, err);
    if (sst)
        return sst;
    c2b_navier *nv = calloc(1, sizeof *nv);
    if (!nv)
        return c2b_error_set(err, C2B_ERR_NOMEM, "pseudo-navier: out of memory");
    memcpy(nv->shape, shape, sizeof nv->shape);
    nv->dom = *dom;
    nv->data = *data;
    nv->opt = o;
    nv->t = t;
    nv->kappa = 2 * C2B_PI / (dom->v1 - dom->v0);
    c2b_status st = c2b_poly_hermite(2, nv->h, err);
    for (int c = 0; c < C2B_NCOMP && !st; c++) {
        int any = 0;
        for (int k = 0; k < 4; k++)
            any |= nv->data.f[c][k / 2][k % 2].fn != NULL;
        if (any)
            st = solve_component(nv, c, err);
    }
    if (st) {
        c2b_navier_destroy(nv);
        return st;
    }
    *out = nv;
    return C2B_OK;
}

c2b_status c2b_navier_eval_grid(const c2b_navier *nv, size_t nu, const double *u, size_t nvv,
                                const double *v, int order, double *out, c2b_error *err)
{
    if (!nv || (!u && nu) || (!v && nvv) || (!out && nu && nvv) || order < 0 || order > 2)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_navier_eval_grid: NULL buffer or order outside 0..2");
    static const int du[6] = {0, 1, 0, 2, 1, 0}, dv[6] = {0, 0, 1, 0, 1, 2};
    const int nd = (order + 1) * (order + 2) / 2, M = nv->opt.M, N = nv->opt.N;
    for (size_t i = 0; i < nu; i++) {
        double hd[4][3], q[64][3];
        for (int k = 0; k < 4; k++)
            c2b_poly_eval(&nv->h[k], u[i], 2, hd[k]);
        for (int m = 0; m < M; m++)
            for (int k = 0; k <= 2; k++)
                q[m][k] = q_deriv(m + 1, k, u[i]);
        for (size_t j = 0; j < nvv; j++) {
            double *o = out + (i * nvv + j) * (size_t)nd * 3;
            for (int c = 0; c < C2B_NCOMP; c++) {
                double g[4][3] = {{0}};
                for (int k = 0; k < 4; k++) {
                    const c2b_vdfunc *f = &nv->data.f[c][k / 2][k % 2];
                    if (f->fn)
                        for (int e = 0; e <= order; e++)
                            g[k][e] = f->fn(f->ctx, e, v[j], nv->t);
                }
                double sn[64][3];
                for (int n = 1; n <= N; n++) {
                    double kn = n * nv->kappa, w = kn * (v[j] - nv->dom.v0);
                    sn[n - 1][0] = sin(w), sn[n - 1][1] = kn * cos(w), sn[n - 1][2] = -kn * kn * sin(w);
                }
                for (int e = 0; e < nd; e++) {
                    double s = 0;
                    for (int k = 0; k < 4; k++)
                        s += hd[k][du[e]] * g[k][dv[e]];
                    if (nv->A[c])
                        for (int m = 0; m < M; m++)
                            for (int n = 0; n < N; n++)
                                s += nv->A[c][m * N + n] * q[m][du[e]] * sn[n][dv[e]];
                    o[e * 3 + c] = s;
                }
            }
        }
    }
    return C2B_OK;
}

void c2b_navier_coefficients(const c2b_navier *nv, int c, double *A)
{
    if (!nv || !A || c < 0 || c >= C2B_NCOMP)
        return;
    for (int k = 0; k < nv->opt.M * nv->opt.N; k++)
        A[k] = nv->A[c] ? nv->A[c][k] : 0.0;
}
