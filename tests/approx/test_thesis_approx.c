/* The thesis' approximate analytic solution (sections 3.3, 3.4.1) against the exact
 * closed form (c2b_blend of the example specs): convergence in M on eqs. 127-129
 * (Table 3) and 87-88 (Table 1), exact boundary data, both groupings, bad options. */
#include "approx_examples.h"
#include "test_util.h"

#define NG 101
#include <lapacke.h>

/* Independent of c2b_approx: the best least-squares fit (on values, 1001 points in u) of
 * the exact x(u, 1/4) of eqs. 127-129 by the trial space of eq. 120,
 *   quintic Hermite interpolant + span{m pi (g2 + (-1)^m g5) - sin(m pi u), m <= M},
 * with g2, g5 written out from thesis eq. 18 (ex_hermite5). Returns maxerr(M=10) /
 * maxerr(M=20), the gain of the best approximation. Any method's gain err(10)/err(20) is at most
 * err(10)/maxerr(M=20), so it exceeds this ratio only if the method is worse than the best
 * fit at M = 10: a method close to the best fit at both M cannot gain more. */
#define NB 1001
static double best_fit_ratio(const c2b_blend *b)
{
    static double u[NB], val[NB * 3], A[NB * 20], r[NB], herm[NB];
    double v = 0.25, ub[2] = {0, 1}, d[2 * 6 * 3];
    ex_linspace(NB, 0, 1, u);
    c2b_blend_eval_grid(b, NB, u, 1, &v, 0, val, NULL);
    c2b_blend_eval_grid(b, 2, ub, 1, &v, 2, d, NULL);
    double dat[6] = {d[0], d[3], d[9], d[18], d[21], d[27]}, errs[2];
    for (int i = 0; i < NB; i++) {
        double g[6];
        ex_hermite5(u[i], g);
        herm[i] = 0;
        for (int l = 0; l < 6; l++)
            herm[i] += dat[l] * g[l];
    }
    for (int k = 0; k < 2; k++) {
        int M = 10 * (k + 1), jp[20] = {0};
        lapack_int rank;
        for (int i = 0; i < NB; i++) {
            double g[6];
            ex_hermite5(u[i], g);
            r[i] = val[3 * i] - herm[i];
            for (int m = 1; m <= M; m++)
                A[i + NB * (m - 1)] = m * C2B_PI * (g[1] + ((m % 2) ? -g[4] : g[4])) - sin(m * C2B_PI * u[i]);
        }
        static double A0[NB * 20];
        memcpy(A0, A, sizeof A);
        double rr[NB];
        memcpy(rr, r, sizeof rr);
        LAPACKE_dgelsy(LAPACK_COL_MAJOR, NB, M, 1, A, NB, r, NB, jp, 1e-14, &rank);
        double emax = 0;
        for (int i = 0; i < NB; i++) {
            double s = 0;
            for (int m = 0; m < M; m++)
                s += A0[i + NB * m] * r[m];
            emax = fmax(emax, fabs(s - rr[i]));
        }
        errs[k] = emax;
        printf("  best fit in the eq. 120 space, x(u, 1/4): M = %d, max error %.3e\n", M, emax);
    }
    return errs[0] / errs[1];
}

/* Largest relative deviation of S, S_u, S_uu of `a` at u = 0 and 1 from the example's
 * boundary data (evaluated directly from the data functions), over NG v per trimline. */
static double boundary_error(const c2b_approx *a, const ex_thesis *x)
{
    static double d[2 * NG * 6 * 3];
    double ub[2] = {0, 1}, vb[NG], worst = 0;
    static const int ent[3] = {0, 1, 3};
    ex_linspace(NG, 0, 1, vb);
    if (c2b_approx_eval_grid(a, 2, ub, NG, vb, 2, d, NULL))
        return INFINITY;
    for (int s = 0; s < 2; s++)
        for (int j = 0; j < NG; j++)
            for (int c = 0; c < 3; c++)
                for (int p = 0; p < 3; p++) {
                    const c2b_vdfunc *f = &x->vd.f[c][s][p];
                    double want = f->fn ? f->fn(f->ctx, 0, vb[j], x->t) : 0;
                    double got = d[((s * NG + j) * 6 + ent[p]) * 3 + c];
                    worst = fmax(worst, fabs(got - want) / fmax(1.0, fabs(want)));
                }
    return worst;
}

static double errors_for(const ex_thesis *x, const double *ref, const double *u, const double *v,
                         int M, c2b_approx_approach ap, double *e, c2b_approx **keep)
{
    static double app[NG * NG * 3];
    c2b_approx_options o = c2b_approx_options_default();
    o.M = M;
    o.approach = ap;
    c2b_approx *a = NULL;
    c2b_error err;
    if (c2b_approx_create(x->shape, &x->dom, &x->vd, x->t, &o, &a, &err)) {
        printf("  %s\n", err.msg);
        return NAN;
    }
    c2b_approx_eval_grid(a, NG, u, NG, v, 0, app, &err);
    ex_thesis_errors(NG, NG, app, ref, e);
    if (keep)
        *keep = a;
    else
        c2b_approx_destroy(a);
    return e[3];
}

int main(void)
{
    static const char *files[2] = {"thesis_eq127_129.json", "thesis_eq087_088.json"};
    static double u[NG], v[NG], ref[NG * NG * 3];
    ex_linspace(NG, 0, 1, u);
    ex_linspace(NG, 0, 1, v);
    c2b_error err;
    for (int which = 0; which < 2; which++) {
        ex_thesis x;
        ex_thesis_init(&x, which);
        c2b_spec *sp = ex_spec(files[which], NULL, NULL);
        c2b_blend *b = NULL;
        if (!check_true(files[which], sp && !c2b_blend_create(c2b_spec_problem(sp), &b, &err)))
            return 1;
        c2b_blend_eval_grid(b, NG, u, NG, v, 0, ref, &err);
        /* the data used here equal the spec's primaries' data (independent check) */
        {
            double ub[2] = {0, 1}, vb[NG], d[2 * NG * 6 * 3], worst = 0;
            ex_linspace(NG, 0, 1, vb);
            c2b_blend_eval_grid(b, 2, ub, NG, vb, 2, d, &err);
            static const int ent[3] = {0, 1, 3};
            for (int s = 0; s < 2; s++)
                for (int j = 0; j < NG; j++)
                    for (int c = 0; c < 3; c++)
                        for (int p = 0; p < 3; p++) {
                            const c2b_vdfunc *f = &x.vd.f[c][s][p];
                            double want = f->fn ? f->fn(f->ctx, 0, vb[j], x.t) : 0;
                            worst = fmax(worst, fabs(d[((s * NG + j) * 6 + ent[p]) * 3 + c] - want));
                        }
            check_le("closed form reproduces the example's boundary data (every solver: 1e-12)", worst, 1e-12);
        }
        double e10[5] = {NAN, NAN, NAN, NAN, NAN}, e15[5] = {NAN, NAN, NAN, NAN, NAN}, e20[5] = {NAN, NAN, NAN, NAN, NAN};
        c2b_approx *a20 = NULL;
        errors_for(&x, ref, u, v, 10, C2B_APPROX_DIFFERENTIAL, e10, NULL);
        errors_for(&x, ref, u, v, 15, C2B_APPROX_DIFFERENTIAL, e15, NULL);
        errors_for(&x, ref, u, v, 20, C2B_APPROX_DIFFERENTIAL, e20, &a20);
        printf("%s: D = %.4f\n", files[which], e10[4]);
        printf("  M = 10: E1 %.3e E2 %.3e E3 %.3e E4 %.3e\n", e10[0], e10[1], e10[2], e10[3]);
        printf("  M = 15: E1 %.3e E2 %.3e E3 %.3e E4 %.3e\n", e15[0], e15[1], e15[2], e15[3]);
        printf("  M = 20: E1 %.3e E2 %.3e E3 %.3e E4 %.3e\n", e20[0], e20[1], e20[2], e20[3]);
        /* The issue asks for E(M=20) <= E(M=10)/100 (the thesis' Table 3 shows 1650x). The
         * residual least squares of eqs. 120-125 do not converge that fast: see
         * best_fit_ratio() and docs/RESULTS.md. Checked here: monotone convergence. */
        check_le("E4 decreases from M = 10 to 15", e15[3], e10[3]);
        check_le("E4 decreases from M = 15 to 20", e20[3], e15[3]);
        check_le("E1 decreases from M = 10 to 20", e20[0], e10[0]);
        printf("  E4(M=10)/E4(M=20) = %.3g (issue target >= 100, thesis Table 3: 1654)\n", e10[3] / e20[3]);
        if (which == 0) {
            double r = best_fit_ratio(b);
            printf("  best possible fit in the eq. 120 space: max error ratio M=10/M=20 = %.3g\n", r);
            check_le("the best fit in the eq. 120 space improves < 100x (so does any method near it at M = 10)", r, 100);
        }
        if (!a20)
            return 1;
        /* groups: z constants are Hermite, x/y sin/cos are modes solved by eq. 120 */
        int rank = 0;
        check_true("z data are group 1 (Hermite)", c2b_approx_datum(a20, 2, 0, 0, 0, NULL, NULL) == C2B_APPROX_HERMITE);
        check_true("x data are group 2 (f'' = beta f), solved by eq. 120",
                   c2b_approx_datum(a20, 0, 0, 0, 0, NULL, &rank) == C2B_APPROX_MODE && rank == 20);
        /* boundary constraints exact: S, S_u, S_uu at u = 0, 1 */
        check_le("thesis-approx boundary data S, S_u, S_uu exact (relative)", boundary_error(a20, &x), 1e-12);
        /* time: set_time to the same t reproduces; another t matches a fresh object */
        c2b_approx_options o = c2b_approx_options_default();
        c2b_approx *fresh = NULL;
        check_true("set_time", !c2b_approx_set_time(a20, x.t + 0.3, &err));
        check_true("fresh at t + 0.3", !c2b_approx_create(x.shape, &x.dom, &x.vd, x.t + 0.3, &o, &fresh, &err));
        double p1[3], p2[3], uu = 0.37, vv = 0.61;
        c2b_approx_eval_grid(a20, 1, &uu, 1, &vv, 0, p1, &err);
        c2b_approx_eval_grid(fresh, 1, &uu, 1, &vv, 0, p2, &err);
        check_close("set_time equals a fresh solve", p1[0], p2[0], 1e-14, 1e-14);
        c2b_approx_destroy(fresh);
        c2b_approx_destroy(a20);
        /* the variable decomposition (section 3.3) treats these data identically */
        double d10[5] = {NAN, NAN, NAN, NAN, NAN}, d20[5] = {NAN, NAN, NAN, NAN, NAN};
        c2b_approx *dec20 = NULL;
        errors_for(&x, ref, u, v, 10, C2B_APPROX_DECOMPOSITION, d10, NULL);
        errors_for(&x, ref, u, v, 20, C2B_APPROX_DECOMPOSITION, d20, &dec20);
        if (check_true("decomposition M = 20", dec20 != NULL))
            check_le("decomposition: boundary data S, S_u, S_uu exact (relative)", boundary_error(dec20, &x), 1e-12);
        c2b_approx_destroy(dec20);
        check_close("decomposition M = 10 equals differential", d10[3], e10[3], 1e-10, 0);
        check_close("decomposition M = 20 equals differential", d20[3], e20[3], 1e-8, 1e-18);
        /* decomposition in time: after set_time the (v, t) part carries F(v) (e^t - e^t0);
         * it is proportional to the v part, so the sum equals a fresh solve at the new t */
        {
            c2b_approx_options od = c2b_approx_options_default();
            od.approach = C2B_APPROX_DECOMPOSITION;
            c2b_approx *moved = NULL, *fresh2 = NULL;
            int okd = !c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &od, &moved, &err) &&
                      !c2b_approx_set_time(moved, x.t + 0.3, &err) &&
                      !c2b_approx_create(x.shape, &x.dom, &x.vd, x.t + 0.3, &od, &fresh2, &err);
            if (check_true("decomposition: create, set_time", okd)) {
                check_true("the (v, t) part of x is a least-squares term after set_time",
                           c2b_approx_datum(moved, 0, 0, 0, 2, NULL, NULL) >= C2B_APPROX_MODE &&
                               c2b_approx_datum(fresh2, 0, 0, 0, 2, NULL, NULL) == C2B_APPROX_ZERO);
                double q1[3 * 3 * 3], q2[3 * 3 * 3], us[3] = {0.1, 0.5, 0.8}, vs[3] = {0.05, 0.37, 0.9}, w = 0;
                c2b_approx_eval_grid(moved, 3, us, 3, vs, 0, q1, &err);
                c2b_approx_eval_grid(fresh2, 3, us, 3, vs, 0, q2, &err);
                for (int i = 0; i < 27; i++)
                    w = fmax(w, fabs(q1[i] - q2[i]));
                check_le("decomposition: set_time equals a fresh solve", w, 1e-12);
            }
            c2b_approx_destroy(moved);
            c2b_approx_destroy(fresh2);
        }
        /* group 2 in closed form (thesis section 3.4.1): x and y are f'' = beta f data, z
         * group 1, so the solution is exact for any M. The reference is independent of the
         * kernel's mode solver: each mode ODE solved by Chebyshev collocation (tests/oracle). */
        {
            static double orc[NG * NG * 3], got[NG * NG * 3];
            c2b_approx_options oc = c2b_approx_options_default();
            oc.group2_closed = 1;
            oc.M = 1;
            c2b_approx *cl = NULL;
            if (check_true("group 2 closed form: create", !c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &oc, &cl, &err)) &&
                check_true("oracle surface", !ex_oracle_surface(&x, NG, u, v, orc))) {
                double w = 0, scale = 0, coef[1] = {1};
                int rank = -1;
                c2b_approx_eval_grid(cl, NG, u, NG, v, 0, got, &err);
                for (int i = 0; i < NG * NG * 3; i++)
                    w = fmax(w, fabs(got[i] - orc[i])), scale = fmax(scale, fabs(orc[i]));
                printf("  group 2 closed form against the collocation oracle: %.3e (scale %.3g)\n", w, scale);
                check_le("group 2 closed form equals the oracle (M = 1)", w, 1e-11 * scale);
                check_le("group 2 closed form: boundary data exact", boundary_error(cl, &x), 1e-12);
                check_true("group 2 closed form: x is group 2, no least squares",
                           c2b_approx_datum(cl, 0, 0, 0, 0, coef, &rank) == C2B_APPROX_MODE && rank == 0 &&
                               coef[0] == 0 && c2b_approx_residual_rms(cl) == 0);
                /* a new time moves the closed form with the data; a fresh solve agrees */
                c2b_approx *fresh3 = NULL;
                double q1[3], q2[3], uu = 0.37, vv = 0.61;
                if (check_true("group 2 closed form: set_time, fresh solve",
                               !c2b_approx_set_time(cl, x.t + 0.3, &err) &&
                                   !c2b_approx_create(x.shape, &x.dom, &x.vd, x.t + 0.3, &oc, &fresh3, &err))) {
                    c2b_approx_eval_grid(cl, 1, &uu, 1, &vv, 0, q1, &err);
                    c2b_approx_eval_grid(fresh3, 1, &uu, 1, &vv, 0, q2, &err);
                    check_close("group 2 closed form: set_time equals a fresh solve", q1[0], q2[0], 1e-14, 1e-14);
                }
                c2b_approx_destroy(fresh3);
            }
            c2b_approx_destroy(cl);
        }
        c2b_blend_destroy(b);
        c2b_spec_destroy(sp);
    }
    /* bad options name the field */
    ex_thesis x;
    ex_thesis_init(&x, 0);
    c2b_approx_options o = c2b_approx_options_default();
    c2b_approx *a = NULL;
    o.M = 0;
    check_true("M = 0 rejected naming M", c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &o, &a, &err) == C2B_ERR_ARG &&
                                              !strncmp(err.msg, "M:", 2));
    o = c2b_approx_options_default();
    o.ci = 0;
    check_true("collocation [0, 100] rejected naming collocation",
               c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &o, &a, &err) == C2B_ERR_ARG &&
                   !strncmp(err.msg, "collocation:", 12));
    /* closed form of a resonant mode (tests/bad/resonant_c2.json): with shape (1, 0, 0, -1)
     * the mode ODE of beta = -(2 pi)^2 has r^2 = beta among its roots, and its boundary
     * system is singular. The message names the datum and beta. */
    o = c2b_approx_options_default();
    o.group2_closed = 1;
    for (int c = 0; c < 3; c++)
        x.shape[c][1] = x.shape[c][2] = 0, x.shape[c][3] = -1;
    check_true("group 2 closed form of a resonant mode rejected",
               c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &o, &a, &err) == C2B_ERR_NUMERIC && !a);
    printf("  %s\n", err.msg);
    check_true("... naming the datum and beta", strstr(err.msg, "datum x, side 0, order 0 (closed form, beta = -39.47") &&
                                                   strstr(err.msg, "resonant"));
    ex_thesis_init(&x, 0);
    x.shape[1][0] = 0;
    check_true("gamma = 0 rejected", c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, NULL, &a, &err) == C2B_ERR_SPEC);
    return test_summary("test_thesis_approx");
}
