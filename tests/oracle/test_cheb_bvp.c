/*
 * test_cheb_bvp.c -- self-test of the Chebyshev BVP oracle against closed
 * form solutions derived by hand (never from the oracle itself).
 *
 * Every exact solution used here has the form
 *
 *     G(u) = P(u) + Re sum_j w_j exp(r_j (u - s_j))
 *
 * with P a polynomial and r_j roots of the characteristic polynomial
 * chi(r) = sum_k c[k] r^{2(n-k)} (derived by hand below; each root is also
 * checked numerically against chi).  Then
 *     G^{(q)}(u) = P^{(q)}(u) + Re sum_j w_j r_j^q exp(r_j (u - s_j)),
 * the right-hand side is p = sum_k c[k] P^{(2(n-k))} (exact polynomial
 * algebra), and the boundary data d are the exact values at u = 0 and 1.
 * The shift s_j is 1 for growing exponentials (Re r > 0) and 0 otherwise,
 * so that the solutions stay O(1) on [0,1] even for |r| ~ 60.
 *
 * Error measure printed and checked (per derivative order q):
 *     err = |got - exact| / max(|exact|, S_q),
 * S_q = max over the evaluation points of |exact G^{(q)}|, i.e. pointwise
 * relative error, but normalised by the size of G^{(q)} on [0,1] where
 * G^{(q)} passes through (or near) zero.  Tolerance: 1e-10.
 */
#include "cheb_bvp.h"

#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846264338327950288
#define MAXR 16
#define MAXP 16
#define TOL 1e-10

typedef struct {
    int nr;
    double complex r[MAXR];
    double complex w[MAXR];
    int np; /* number of polynomial coefficients (degree np-1) */
    double poly[MAXP];
} exact_t;

static int g_fail = 0;
static int g_checks = 0;

/* ---------------------------------------------------------------- helpers */

static double poly_deriv_eval(const double *p, int np, int q, double u)
{
    /* sum_{i>=q} p[i] i!/(i-q)! u^{i-q} */
    double v = 0.0;
    int i, t;
    for (i = np - 1; i >= q; --i) {
        double f = 1.0;
        for (t = 0; t < q; ++t)
            f *= (double)(i - t);
        v = v * u + p[i] * f;
    }
    return v;
}

static double exact_eval(const exact_t *ex, int q, double u)
{
    double v = poly_deriv_eval(ex->poly, ex->np, q, u);
    int j;
    for (j = 0; j < ex->nr; ++j) {
        double complex r = ex->r[j];
        double s = creal(r) > 0.0 ? 1.0 : 0.0;
        double complex rq = cpow(r, q);
        if (q == 0)
            rq = 1.0;
        v += creal(ex->w[j] * rq * cexp(r * (u - s)));
    }
    return v;
}

static void add_exp(exact_t *ex, double complex r, double complex w)
{
    ex->r[ex->nr] = r;
    ex->w[ex->nr] = w;
    ex->nr++;
}

/* Check |chi(r)| small relative to the size of its terms. */
static void check_roots(const char *name, int n, const double *c,
                        const exact_t *ex)
{
    int j, k;
    for (j = 0; j < ex->nr; ++j) {
        double complex r = ex->r[j], s = 0.0;
        double mag = 0.0, rel;
        for (k = 0; k <= n; ++k) {
            double complex t = c[k] * cpow(r, 2 * (n - k));
            if (2 * (n - k) == 0)
                t = c[k];
            s += t;
            mag += cabs(t);
        }
        rel = mag > 0.0 ? cabs(s) / mag : cabs(s);
        ++g_checks;
        printf("  [%s] root r=(%.15g,%.15g): |chi(r)|/sum|terms| = %.3e%s\n",
               name, creal(r), cimag(r), rel, rel > 1e-13 ? "  FAIL" : "");
        if (rel > 1e-13)
            ++g_fail;
    }
}

/* Run one case: build rhs and d from the exact solution, solve, compare. */
static double run_case(const char *name, int n, const double *c,
                       const exact_t *ex, int N)
{
    double rhs[MAXP];
    int rhs_deg = -1;
    double d[8];
    double ue[32], out[32 * 4], S[4] = {0, 0, 0, 0};
    double cond = 0.0, maxerr = 0.0;
    int ne = 0, i, k, q, rc;

    printf("=== %s (n=%d, N=%d%s)\n", name, n, N, N <= 0 ? " auto" : "");
    check_roots(name, n, c, ex);

    /* rhs = sum_k c[k] P^{(2(n-k))} */
    for (i = 0; i < MAXP; ++i)
        rhs[i] = 0.0;
    for (k = 0; k <= n; ++k) {
        int o = 2 * (n - k);
        for (i = o; i < ex->np; ++i) {
            double f = 1.0;
            int t;
            for (t = 0; t < o; ++t)
                f *= (double)(i - t);
            rhs[i - o] += c[k] * ex->poly[i] * f;
        }
    }
    for (i = 0; i < MAXP; ++i)
        if (rhs[i] != 0.0)
            rhs_deg = i;

    for (q = 0; q < n; ++q) {
        d[q] = exact_eval(ex, q, 0.0);
        d[n + q] = exact_eval(ex, q, 1.0);
    }

    for (i = 0; i <= 20; ++i)
        ue[ne++] = 0.05 * i;
    ue[ne++] = 0.1234567;
    ue[ne++] = 0.70710678118654752;
    ue[ne++] = 0.987654;
    ue[ne++] = 0.0123;

    rc = oracle_cheb_bvp(n, c, rhs_deg, rhs_deg >= 0 ? rhs : NULL, d, N, ne,
                         ue, out, &cond);
    ++g_checks;
    if (rc != 0) {
        printf("  FAIL: oracle returned %d (cond %.3e)\n", rc, cond);
        ++g_fail;
        return INFINITY;
    }
    printf("  cond(equilibrated system) = %.3e\n", cond);

    for (i = 0; i < ne; ++i)
        for (q = 0; q < 4; ++q) {
            double v = fabs(exact_eval(ex, q, ue[i]));
            if (v > S[q])
                S[q] = v;
        }

    for (i = 0; i < ne; ++i) {
        for (q = 0; q < 4; ++q) {
            double got = out[i * 4 + q];
            double exv = exact_eval(ex, q, ue[i]);
            double den = fabs(exv) > S[q] ? fabs(exv) : S[q];
            double err = den > 0.0 ? fabs(got - exv) / den : fabs(got - exv);
            int bad = !(err <= TOL);
            ++g_checks;
            if (bad)
                ++g_fail;
            if (!(err <= maxerr))
                maxerr = err;
            printf("  u=%-10.7g G^(%d) got=% .16e exact=% .16e err=%.2e%s\n",
                   ue[i], q, got, exv, err, bad ? "  FAIL" : "");
        }
    }
    printf("  --> %s: max err %.3e\n", name, maxerr);
    return maxerr;
}

/* ------------------------------------------------------------ summaries */

#define MAXCASES 64
static const char *s_name[MAXCASES];
static double s_err[MAXCASES];
static double s_rmax[MAXCASES];
static int s_n = 0;

static void record(const char *name, const exact_t *ex, double err)
{
    double rmax = 0.0;
    int j;
    for (j = 0; j < ex->nr; ++j)
        if (cabs(ex->r[j]) > rmax)
            rmax = cabs(ex->r[j]);
    if (s_n < MAXCASES) {
        s_name[s_n] = name;
        s_err[s_n] = err;
        s_rmax[s_n] = rmax;
        ++s_n;
    }
}

static void run(const char *name, int n, const double *c, const exact_t *ex,
                int N)
{
    record(name, ex, run_case(name, n, c, ex, N));
}

/* ------------------------------------------------------ individual cases */

/* Thesis quintic Hermite basis, monomial coefficients u^0..u^5. */
static const double HB[6][6] = {
    {1, 0, 0, -10, 15, -6},     /* g1 = 1-10u^3+15u^4-6u^5            */
    {0, 1, 0, -6, 8, -3},       /* g2 = (1-6u^2+8u^3-3u^4) u          */
    {0, 0, 0.5, -1.5, 1.5, -0.5}, /* g3 = (0.5-1.5u+1.5u^2-0.5u^3) u^2 */
    {0, 0, 0, 10, -15, 6},      /* g4 = (10-15u+6u^2) u^3             */
    {0, 0, 0, -4, 7, -3},       /* g5 = (-4+7u-3u^2) u^3              */
    {0, 0, 0, 0.5, -1, 0.5},    /* g6 = (0.5-u+0.5u^2) u^3            */
};

/* Sanity check of the hand-written basis: D^q g_i at 0 and 1 must be the
 * identity pattern (g1..g3 <-> G,G',G'' at 0; g4..g6 <-> at 1). */
static void check_hermite_basis(void)
{
    int i, q;
    printf("=== quintic Hermite basis sanity check\n");
    for (i = 0; i < 6; ++i)
        for (q = 0; q < 3; ++q) {
            double v0 = poly_deriv_eval(HB[i], 6, q, 0.0);
            double v1 = poly_deriv_eval(HB[i], 6, q, 1.0);
            double e0 = (i == q) ? 1.0 : 0.0;
            double e1 = (i == q + 3) ? 1.0 : 0.0;
            ++g_checks;
            if (fabs(v0 - e0) > 1e-15 || fabs(v1 - e1) > 1e-15) {
                ++g_fail;
                printf("  FAIL g%d D^%d: (%g,%g) expected (%g,%g)\n", i + 1,
                       q, v0, v1, e0, e1);
            }
        }
}

static void cases_order6_poly(void)
{
    static const double c[4] = {1, 0, 0, 0};
    static const double dd[6] = {0.3, -1.2, 2.5, -0.7, 0.9, -3.1};
    exact_t ex;
    int i, k;

    check_hermite_basis();

    /* G^(6) = 0: G = sum d_i g_i (quintic Hermite interpolant). */
    memset(&ex, 0, sizeof ex);
    ex.np = 6;
    for (i = 0; i < 6; ++i)
        for (k = 0; k < 6; ++k)
            ex.poly[k] += dd[i] * HB[i][k];
    run("n3 G6=0 quintic Hermite", 3, c, &ex, 0);
    run("n3 G6=0 quintic Hermite N=8", 3, c, &ex, 8);

    /* G^(6) = 720, zero data: G = u^6 - (g4 + 6 g5 + 30 g6) = u^3 (u-1)^3. */
    memset(&ex, 0, sizeof ex);
    ex.np = 7;
    ex.poly[3] = -1;
    ex.poly[4] = 3;
    ex.poly[5] = -3;
    ex.poly[6] = 1;
    run("n3 G6=720 u^3(u-1)^3", 3, c, &ex, 0);

    /* G^(6) = 720 with data dd: G = u^6 + sum (dd_i - D_i[u^6]) g_i, where
     * D[u^6] = (0,0,0, 1,6,30) (values/derivs at 0 and at 1). */
    memset(&ex, 0, sizeof ex);
    ex.np = 7;
    ex.poly[6] = 1;
    {
        static const double du6[6] = {0, 0, 0, 1, 6, 30};
        for (i = 0; i < 6; ++i)
            for (k = 0; k < 6; ++k)
                ex.poly[k] += (dd[i] - du6[i]) * HB[i][k];
    }
    run("n3 G6=720 u^6+Hermite", 3, c, &ex, 0);
}

static void cases_order2(void)
{
    exact_t ex;
    double c[2];

    /* G'' - k^2 G = 0, k = 2: G = 1.5 cosh(2u) - 0.8 sinh(2u)
     *   = 0.35 e^{2u} + 1.15 e^{-2u}; written with the shift convention:
     *   0.35 e^{2} e^{2(u-1)}. */
    c[0] = 1;
    c[1] = -4;
    memset(&ex, 0, sizeof ex);
    add_exp(&ex, 2.0, 0.35 * exp(2.0));
    add_exp(&ex, -2.0, 1.15);
    run("n1 G''-4G=0 cosh/sinh", 1, c, &ex, 0);

    /* G'' - 3600 G = 0 (k = 60): G = e^{-60u} + 0.5 e^{60(u-1)}. */
    c[1] = -3600;
    memset(&ex, 0, sizeof ex);
    add_exp(&ex, -60.0, 1.0);
    add_exp(&ex, 60.0, 0.5);
    run("n1 G''-3600G=0 k=60", 1, c, &ex, 0);

    /* G'' + 9 G = 0: G = 2 cos 3u - 0.7 sin 3u = Re[(2+0.7i) e^{3iu}]. */
    c[1] = 9;
    memset(&ex, 0, sizeof ex);
    add_exp(&ex, 3.0 * I, 2.0 + 0.7 * I);
    run("n1 G''+9G=0 sin/cos", 1, c, &ex, 0);
    run("n1 G''+9G=0 sin/cos N=24", 1, c, &ex, 24);

    /* G'' + 3600 G = 0: G = cos 60u + 0.4 sin 60u = Re[(1-0.4i) e^{60iu}]. */
    c[1] = 3600;
    memset(&ex, 0, sizeof ex);
    add_exp(&ex, 60.0 * I, 1.0 - 0.4 * I);
    run("n1 G''+3600G=0 k=60", 1, c, &ex, 0);

    /* G'' - 4 G = 6u - 4u^3 - 4 (+ homogeneous): P = u^3 + 1. */
    c[1] = -4;
    memset(&ex, 0, sizeof ex);
    ex.np = 4;
    ex.poly[0] = 1;
    ex.poly[3] = 1;
    add_exp(&ex, -2.0, -0.6);
    run("n1 G''-4G=poly", 1, c, &ex, 0);
}

static void cases_order4(void)
{
    exact_t ex;
    double c[3];
    static const double dd[4] = {0.4, -1.1, 0.25, 2.0};

    /* G'''' = 24: G = u^4 + (d0) h1 + d1 h2 + (d2 - 1) h3 + (d3 - 4) h4,
     * h1 = 1-3u^2+2u^3, h2 = u-2u^2+u^3, h3 = 3u^2-2u^3, h4 = -u^2+u^3. */
    c[0] = 1;
    c[1] = 0;
    c[2] = 0;
    memset(&ex, 0, sizeof ex);
    ex.np = 5;
    ex.poly[4] = 1;
    {
        static const double h[4][4] = {
            {1, 0, -3, 2}, {0, 1, -2, 1}, {0, 0, 3, -2}, {0, 0, -1, 1}};
        /* d order: G(0), G'(0), G(1), G'(1); u^4 gives (0,0,1,4) */
        const double coef[4] = {dd[0], dd[1], dd[2] - 1.0, dd[3] - 4.0};
        int i, k;
        for (i = 0; i < 4; ++i)
            for (k = 0; k < 4; ++k)
                ex.poly[k] += coef[i] * h[i][k];
    }
    run("n2 G''''=24 u^4+cubic Hermite", 2, c, &ex, 0);

    /* Beam G'''' - k^4 G = 0, k = 3: roots +-3, +-3i.
     * G = cos 3u + 2 sinh 3u - 0.5 cosh 3u + 0.3 sin 3u
     *   = Re[(1 - 0.3i) e^{3iu}] + 0.75 e^{3u} - 1.25 e^{-3u}. */
    c[2] = -81;
    memset(&ex, 0, sizeof ex);
    add_exp(&ex, 3.0 * I, 1.0 - 0.3 * I);
    add_exp(&ex, 3.0, 0.75 * exp(3.0));
    add_exp(&ex, -3.0, -1.25);
    run("n2 beam k=3", 2, c, &ex, 0);
    run("n2 beam k=3 N=40", 2, c, &ex, 40);

    /* Beam k = 40 and k = 60, well-scaled combination. */
    {
        static const double ks[2] = {40.0, 60.0};
        static const char *nm[2] = {"n2 beam k=40", "n2 beam k=60"};
        int t;
        for (t = 0; t < 2; ++t) {
            double k = ks[t];
            c[2] = -k * k * k * k;
            memset(&ex, 0, sizeof ex);
            add_exp(&ex, -k, 1.0);
            add_exp(&ex, k, -0.7);
            add_exp(&ex, k * I, 1.0 - 0.2 * I);
            run(nm[t], 2, c, &ex, 0);
        }
    }

    /* c = {1,5,4}: r^4 + 5r^2 + 4 = (r^2+1)(r^2+4): r = +-i, +-2i.
     * Particular solution P = 2 - u (rhs 8 - 4u). */
    c[0] = 1;
    c[1] = 5;
    c[2] = 4;
    memset(&ex, 0, sizeof ex);
    ex.np = 2;
    ex.poly[0] = 2;
    ex.poly[1] = -1;
    add_exp(&ex, I, 0.5 + 0.25 * I);
    add_exp(&ex, 2.0 * I, -1.0 + 0.1 * I);
    run("n2 (D2+1)(D2+4) + poly", 2, c, &ex, 0);
}

/* n = 3, c = {1, beta, beta^2, beta^3}:
 * chi = s^3 + beta s^2 + beta^2 s + beta^3 (s = r^2)
 *     = s^2 (s + beta) + beta^2 (s + beta) = (s + beta)(s^2 + beta^2).
 * With K = sqrt(-beta) > 0: s = K^2 -> r = +-K; s = +-i K^2 ->
 * r = K e^{+-i pi/4}, K e^{+-3i pi/4} = (K/sqrt2)(+-1 +- i). */
static void case_beta3(const char *name, double K)
{
    exact_t ex;
    double beta = -K * K;
    double c[4];
    double al = K / sqrt(2.0);
    c[0] = 1;
    c[1] = beta;
    c[2] = beta * beta;
    c[3] = beta * beta * beta;
    memset(&ex, 0, sizeof ex);
    add_exp(&ex, -K, 0.3);
    add_exp(&ex, K, 1.0);
    add_exp(&ex, al + al * I, 1.0 - 0.5 * I);
    add_exp(&ex, -al + al * I, 0.2 + 0.4 * I);
    run(name, 3, c, &ex, 0);
}

static void cases_order6(void)
{
    exact_t ex;
    double c[4];

    case_beta3("n3 beta=-(2pi)^2", 2.0 * PI);
    case_beta3("n3 beta=-(4pi)^2", 4.0 * PI);
    case_beta3("n3 beta=-(8pi)^2", 8.0 * PI);
    case_beta3("n3 beta=-40^2", 40.0);
    case_beta3("n3 beta=-60^2", 60.0);
    case_beta3("n3 beta=-200^2", 200.0);

    /* c = {1,1,1,0}: chi = r^2 (r^4 + r^2 + 1); r = 0 (double) and
     * r^2 = e^{+-2i pi/3} -> r = +-e^{+-i pi/3} = +-1/2 +- i sqrt3/2
     * (1 + w + w^2 = 0 for w = e^{2i pi/3}).
     * P = 1 - 2u + 0.5u^2 (rhs = lambda * P'' = 1). */
    c[0] = 1;
    c[1] = 1;
    c[2] = 1;
    c[3] = 0;
    memset(&ex, 0, sizeof ex);
    ex.np = 3;
    ex.poly[0] = 1;
    ex.poly[1] = -2;
    ex.poly[2] = 0.5;
    add_exp(&ex, 0.5 + 0.5 * sqrt(3.0) * I, 0.7 + 0.2 * I);
    add_exp(&ex, -0.5 + 0.5 * sqrt(3.0) * I, -0.3 + 1.0 * I);
    run("n3 c={1,1,1,0} + poly", 3, c, &ex, 0);

    /* Same operator scaled: rho G6 + eta G4 + lambda G'' with
     * chi = r^2 (r^4 + a^2 r^2 + a^4) (rho=1, eta=a^2, lambda=a^4), a = 20:
     * r = a(+-1/2 +- i sqrt3/2). */
    {
        double a = 20.0;
        c[0] = 1;
        c[1] = a * a;
        c[2] = a * a * a * a;
        c[3] = 0;
        memset(&ex, 0, sizeof ex);
        ex.np = 2;
        ex.poly[0] = 0.5;
        ex.poly[1] = 1.5;
        add_exp(&ex, a * (0.5 + 0.5 * sqrt(3.0) * I), 0.7 + 0.2 * I);
        add_exp(&ex, a * (-0.5 + 0.5 * sqrt(3.0) * I), -0.3 + 1.0 * I);
        run("n3 c={1,a^2,a^4,0} a=20", 3, c, &ex, 0);
    }
}

/* n = 4, c = {1, beta, ..., beta^4}: with s = r^2,
 * chi = s^4 + beta s^3 + beta^2 s^2 + beta^3 s + beta^4 = (s^5 - beta^5)/(s - beta),
 * so s = beta e^{2 pi i j/5}, j = 1..4, and r = +-sqrt(s). */
static void case_beta4(const char *name, double K)
{
    exact_t ex;
    double beta = -K * K;
    double c[5];
    int j;
    c[0] = 1;
    c[1] = beta;
    c[2] = beta * beta;
    c[3] = beta * beta * beta;
    c[4] = beta * beta * beta * beta;
    memset(&ex, 0, sizeof ex);
    for (j = 1; j <= 4; ++j) {
        double complex s = beta * cexp(2.0 * PI * I * j / 5.0);
        double complex r = csqrt(s);
        add_exp(&ex, r, (0.3 * j - 0.5) + 0.2 * j * I);
        add_exp(&ex, -r, 0.4 - 0.1 * j * I);
    }
    run(name, 4, c, &ex, 0);
}

static void cases_order8(void)
{
    exact_t ex;
    double c[5];
    int j;

    /* G^(8) = 8! : G = u^4 (u-1)^4 + (degree-7 polynomial); here
     * u^4(u-1)^4 = u^4 - 4u^5 + 6u^6 - 4u^7 + u^8. */
    c[0] = 1;
    c[1] = c[2] = c[3] = c[4] = 0;
    memset(&ex, 0, sizeof ex);
    ex.np = 9;
    ex.poly[4] = 1;
    ex.poly[5] = -4;
    ex.poly[6] = 6;
    ex.poly[7] = -4;
    ex.poly[8] = 1;
    run("n4 G8=8! u^4(u-1)^4", 4, c, &ex, 0);
    ex.poly[0] = 0.7;
    ex.poly[1] = -1.3;
    ex.poly[2] = 2.1;
    ex.poly[3] = 0.4;
    ex.poly[7] += 0.9;
    run("n4 G8=8! u^4(u-1)^4 + septic", 4, c, &ex, 0);

    /* General coefficients, exact polynomial solution of degree 10:
     * rhs = sum_k c[k] P^{(8-2k)} computed exactly. */
    c[0] = 2;
    c[1] = -3;
    c[2] = 1.5;
    c[3] = 0.5;
    c[4] = -1;
    memset(&ex, 0, sizeof ex);
    ex.np = 11;
    {
        static const double P[11] = {0.2, -1, 0.5, 3, -2, 1, 0.25, -0.5,
                                     0.75, -0.3, 0.1};
        memcpy(ex.poly, P, sizeof P);
    }
    run("n4 general c, poly deg 10", 4, c, &ex, 0);

    /* G^(8) - k^8 G = 0: roots r = k e^{i pi j/4}, j = 0..7. */
    {
        static const double ks[4] = {3.0, 20.0, 60.0, 200.0};
        static const char *nm[4] = {"n4 G8=k^8 G k=3", "n4 G8=k^8 G k=20",
                                    "n4 G8=k^8 G k=60", "n4 G8=k^8 G k=200"};
        int t;
        for (t = 0; t < 4; ++t) {
            double k = ks[t];
            c[0] = 1;
            c[1] = c[2] = c[3] = 0;
            c[4] = -pow(k, 8);
            memset(&ex, 0, sizeof ex);
            for (j = 0; j < 8; ++j)
                add_exp(&ex, k * cexp(I * PI * j / 4.0),
                        (0.1 * j - 0.3) + (0.05 * j) * I);
            run(nm[t], 4, c, &ex, 0);
        }
    }

    case_beta4("n4 beta=-(2pi)^2", 2.0 * PI);
    case_beta4("n4 beta=-(4pi)^2", 4.0 * PI);
    case_beta4("n4 beta=-(8pi)^2", 8.0 * PI);
}

static void case_singular(void)
{
    /* Clamped beam: first eigenvalue l of cos(l)cosh(l) = 1.  G'''' = l^4 G
     * with G = G' = 0 at both ends has a nontrivial solution, so the
     * collocation system must be (numerically) singular. */
    const double l = 4.730040744862704;
    double c[3] = {1, 0, 0};
    double d[4] = {0, 0, 0, 0};
    double ue[1] = {0.5}, out[4];
    double cond = 0.0;
    int rc;
    c[2] = -l * l * l * l;
    printf("=== singular: clamped beam at first eigenvalue l=%.15g\n", l);
    printf("  cos(l)cosh(l) - 1 = %.3e\n", cos(l) * cosh(l) - 1.0);
    rc = oracle_cheb_bvp(2, c, -1, NULL, d, 0, 1, ue, out, &cond);
    ++g_checks;
    printf("  rc=%d cond=%.3e (need rc!=0 or cond>1e10)%s\n", rc, cond,
           (rc != 0 || cond > 1e10) ? "" : "  FAIL");
    if (!(rc != 0 || cond > 1e10))
        ++g_fail;

    /* Nearby regular problem for contrast. */
    c[2] = -pow(0.9 * l, 4);
    rc = oracle_cheb_bvp(2, c, -1, NULL, d, 0, 1, ue, out, &cond);
    printf("  contrast 0.9*l: rc=%d cond=%.3e G(0.5)=%.3e\n", rc, cond, out[0]);
    ++g_checks;
    if (rc != 0 || !(cond < 1e8) || fabs(out[0]) > 1e-14) {
        printf("  FAIL contrast\n");
        ++g_fail;
    }
}

static void case_invalid(void)
{
    double c[5] = {1, 0, 0, 0, 0}, d[8] = {0}, u = 0.5, out[4];
    double cz[3] = {0, 1, 1};
    int r1, r2, r3, r4;
    printf("=== invalid arguments\n");
    r1 = oracle_cheb_bvp(0, c, -1, NULL, d, 0, 1, &u, out, NULL);
    r2 = oracle_cheb_bvp(5, c, -1, NULL, d, 0, 1, &u, out, NULL);
    r3 = oracle_cheb_bvp(2, cz, -1, NULL, d, 0, 1, &u, out, NULL);
    r4 = oracle_cheb_bvp(2, c, 2, NULL, d, 0, 1, &u, out, NULL);
    printf("  n=0 -> %d, n=5 -> %d, c[0]=0 -> %d, rhs NULL -> %d\n", r1, r2,
           r3, r4);
    g_checks += 4;
    if (r1 == 0 || r2 == 0 || r3 == 0 || r4 == 0) {
        printf("  FAIL: invalid input accepted\n");
        ++g_fail;
    }
    /* Valid call with cond_out == NULL (and with n_eval == 0) must succeed.
     * c = {1,0,0}: G(4) = 0 with G(0)=1 and the other data 0 gives
     * G = 1 - 3u^2 + 2u^3, so G(0.5) = 0.5. */
    d[0] = 1.0;
    r1 = oracle_cheb_bvp(2, c, -1, NULL, d, 16, 0, NULL, NULL, NULL);
    r2 = oracle_cheb_bvp(2, c, -1, NULL, d, 16, 1, &u, out, NULL);
    printf("  valid, cond_out=NULL: rc=%d, %d (G(0.5)=%.16g, exact 0.5)\n", r1,
           r2, out[0]);
    g_checks += 2;
    if (r1 != 0 || r2 != 0 || fabs(out[0] - 0.5) > 1e-14) {
        printf("  FAIL: valid call\n");
        ++g_fail;
    }
}

int main(void)
{
    int i;
    cases_order6_poly();
    cases_order2();
    cases_order4();
    cases_order6();
    cases_order8();
    case_singular();
    case_invalid();

    printf("\n=== summary (max normalised error, max |root|)\n");
    for (i = 0; i < s_n; ++i)
        printf("  %-36s max err %.3e  max|r| %7.3f%s\n", s_name[i], s_err[i],
               s_rmax[i], s_err[i] <= TOL ? "" : "  FAIL");
    printf("%d checks, %d failures\n", g_checks, g_fail);
    return g_fail ? 1 : 0;
}
