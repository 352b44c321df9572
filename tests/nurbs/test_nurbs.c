/*
 * Unit tests of the NURBS module (c2b_nurbs.h, c2b_nurbs_json.h). Every expectation is
 * independent of the implementation: exact geometry (circle, cylinder, sphere), partition
 * of unity, finite differences of the evaluator, invariance of the shape under knot
 * insertion and degree elevation, projection of points placed at a known distance along
 * the normal, periodic continuity, and the messages of every kind of bad input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_nurbs.h"
#include "c2b_nurbs_json.h"
#include "test_util.h"

#define SQ2 0.70710678118654752440
#define NDER ((C2B_NURBS_MAX_DERIV + 1) * (C2B_NURBS_MAX_DERIV + 1) * 3)

/* ---- small helpers ------------------------------------------------------------------- */

typedef struct rng {
    unsigned long long s;
} rng;

static double rnd(rng *r) /* uniform in [0, 1) */
{
    r->s ^= r->s << 13;
    r->s ^= r->s >> 7;
    r->s ^= r->s << 17;
    return (double)(r->s >> 11) * (1.0 / 9007199254740992.0);
}

static double rnd_in(rng *r, double a, double b) { return a + (b - a) * rnd(r); }

static double norm3(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static double dist3(const double *a, const double *b)
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return norm3(d);
}

/* Expect a failure with the given code and message fragment. */
static void expect_err(const char *what, c2b_status st, const c2b_error *err, c2b_status code,
                       const char *fragment)
{
    int ok = st == code && err->code == code && strstr(err->msg, fragment) != NULL;
    printf("%s %s: status %d (want %d), message \"%s\" (want \"%s\")\n", ok ? "ok  " : "FAIL", what,
           (int)st, (int)code, err->msg, fragment);
    ok ? t_passed++ : t_failed++;
}

/* Random non-decreasing clamped knot vector on [a, b] with n poles, degree p and some
 * repeated interior knots (multiplicity <= maxm <= p). */
static void random_knots(rng *r, int p, int n, double a, double b, int maxm, double *U)
{
    int nk = n + p + 1, k = 0;
    if (maxm > p)
        maxm = p;
    for (int i = 0; i <= p; i++)
        U[k++] = a;
    int interior = n - p - 1;
    double x = a;
    while (interior > 0) {
        int m = 1 + (int)(rnd(r) * maxm);
        if (m > interior)
            m = interior;
        x += (b - a) / (n - p) * rnd_in(r, 0.3, 1.0);
        if (x >= b)
            x = 0.5 * (U[k - 1] + b);
        for (int i = 0; i < m; i++)
            U[k++] = x;
        interior -= m;
    }
    while (k < nk)
        U[k++] = b;
}

static c2b_nurbs_surface *random_surface(rng *r, int p, int q, int nu, int nv, int rational,
                                         int maxm)
{
    double *ku = malloc((size_t)(nu + p + 1) * sizeof(double));
    double *kv = malloc((size_t)(nv + q + 1) * sizeof(double));
    double *P = malloc(4 * (size_t)nu * (size_t)nv * sizeof(double));
    random_knots(r, p, nu, -0.5, 1.25, maxm, ku);
    random_knots(r, q, nv, 0.25, 2.0, maxm, kv);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double *Q = P + 4 * (i * nv + j);
            Q[0] = i + rnd_in(r, -0.3, 0.3);
            Q[1] = j + rnd_in(r, -0.3, 0.3);
            Q[2] = rnd_in(r, -1.0, 1.0);
            Q[3] = rational ? rnd_in(r, 0.5, 2.0) : 1.0;
        }
    c2b_nurbs_surface *s = NULL;
    c2b_error err;
    if (c2b_nurbs_surface_create(p, q, nu, nv, ku, kv, P, NULL, &s, &err))
        printf("random_surface: %s\n", err.msg);
    free(ku);
    free(kv);
    free(P);
    return s;
}

static c2b_nurbs_curve *random_curve(rng *r, int p, int n, int rational, int maxm)
{
    double *U = malloc((size_t)(n + p + 1) * sizeof(double));
    double *P = malloc(4 * (size_t)n * sizeof(double));
    random_knots(r, p, n, 1.0, 3.0, maxm, U);
    for (int i = 0; i < n; i++) {
        P[4 * i + 0] = i + rnd_in(r, -0.3, 0.3);
        P[4 * i + 1] = rnd_in(r, -1.0, 1.0);
        P[4 * i + 2] = rnd_in(r, -1.0, 1.0);
        P[4 * i + 3] = rational ? rnd_in(r, 0.5, 2.0) : 1.0;
    }
    c2b_nurbs_curve *c = NULL;
    c2b_error err;
    if (c2b_nurbs_curve_create(p, n, U, P, 0, &c, &err))
        printf("random_curve: %s\n", err.msg);
    free(U);
    free(P);
    return c;
}

/* ---- basis functions ------------------------------------------------------------------ */

/* N_i(t) read through a curve whose poles are e_x at index i and 0 elsewhere. */
static void test_partition_of_unity(void)
{
    rng r = {0x1234567ULL};
    int worst_neg = 0;
    double worst_sum = 0.0;
    for (int trial = 0; trial < 12; trial++) {
        int p = 1 + trial % 6, n = p + 1 + (int)(rnd(&r) * 8);
        double U[64], P[4 * 32];
        random_knots(&r, p, n, -1.0, 2.0, p, U);
        for (int k = 0; k < 30; k++) {
            double t = k == 0 ? -1.0 : (k == 1 ? 2.0 : rnd_in(&r, -1.0, 2.0)), sum = 0.0;
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    P[4 * j + 0] = j == i;
                    P[4 * j + 1] = P[4 * j + 2] = 0.0;
                    P[4 * j + 3] = 1.0;
                }
                c2b_nurbs_curve *c = NULL;
                double out[3];
                c2b_nurbs_curve_create(p, n, U, P, 0, &c, NULL);
                if (!c || c2b_nurbs_curve_eval(c, t, 0, out, NULL)) {
                    worst_neg = 1;
                    c2b_nurbs_curve_destroy(c);
                    continue;
                }
                if (out[0] < 0.0)
                    worst_neg = 1;
                sum += out[0];
                c2b_nurbs_curve_destroy(c);
            }
            if (fabs(sum - 1.0) > worst_sum)
                worst_sum = fabs(sum - 1.0);
        }
    }
    check_true("basis functions are non-negative (12 knot vectors x 30 parameters)", !worst_neg);
    check_le("partition of unity: max |sum N_i - 1|", worst_sum, 4e-16 * 8);

    /* All poles at one point with random weights: S constant, every derivative zero. */
    c2b_nurbs_surface *s = random_surface(&r, 4, 3, 7, 6, 1, 3);
    const double Q[3] = {0.3, -1.7, 2.5};
    double dom[4];
    c2b_nurbs_surface_domain(s, dom);
    int nu = 7, nv = 6;
    double ku[16], kv[16], P[4 * 42];
    memcpy(ku, c2b_nurbs_surface_knots(s, 0), sizeof(double) * (size_t)c2b_nurbs_surface_nknots(s, 0));
    memcpy(kv, c2b_nurbs_surface_knots(s, 1), sizeof(double) * (size_t)c2b_nurbs_surface_nknots(s, 1));
    for (int i = 0; i < nu * nv; i++) {
        P[4 * i + 0] = Q[0];
        P[4 * i + 1] = Q[1];
        P[4 * i + 2] = Q[2];
        P[4 * i + 3] = rnd_in(&r, 0.5, 2.0);
    }
    c2b_nurbs_surface *c = NULL;
    c2b_nurbs_surface_create(4, 3, nu, nv, ku, kv, P, NULL, &c, NULL);
    /* Rounding model for the derivatives that should vanish: d^(a+b) of the basis
     * functions scale like (p / h)^a (q / k)^b with h, k the shortest knot spans. */
    double hu = INFINITY, hv = INFINITY;
    for (int i = 0; i + 1 < nu + 5; i++)
        if (ku[i + 1] > ku[i])
            hu = fmin(hu, ku[i + 1] - ku[i]);
    for (int i = 0; i + 1 < nv + 4; i++)
        if (kv[i + 1] > kv[i])
            hv = fmin(hv, kv[i + 1] - kv[i]);
    double ep = 0.0, ed = 0.0;
    for (int k = 0; k < 100; k++) {
        double u = rnd_in(&r, dom[0], dom[1]), v = rnd_in(&r, dom[2], dom[3]), skl[NDER];
        c2b_nurbs_surface_derivs(c, u, v, 4, 4, skl, NULL);
        ep = fmax(ep, dist3(skl, Q));
        for (int i = 1; i < 25; i++) {
            int a = i / 5, b = i % 5;
            double model = 1e-16 * norm3(Q) * pow(4 * 2 / hu, a) * pow(3 * 2 / hv, b);
            ed = fmax(ed, norm3(skl + 3 * i) / model);
        }
    }
    check_le("all poles at Q: max |S - Q| / |Q|", ep / norm3(Q), 1e-15);
    check_le("all poles at Q: max |d^(a+b)S| (a, b <= 4) / rounding model eps |Q| (2p/h)^a (2q/k)^b",
             ed, 100.0);
    c2b_nurbs_surface_destroy(s);
    c2b_nurbs_surface_destroy(c);
}

/* ---- exact geometry -------------------------------------------------------------------- */

/* The 9-pole full circle of radius R in the plane z = 0 (rational quadratic). */
static c2b_nurbs_curve *circle(double R)
{
    static const double U[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double xy[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                                    {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    double P[36];
    for (int i = 0; i < 9; i++) {
        P[4 * i + 0] = R * xy[i][0];
        P[4 * i + 1] = R * xy[i][1];
        P[4 * i + 2] = 0.0;
        P[4 * i + 3] = i % 2 ? SQ2 : 1.0;
    }
    c2b_nurbs_curve *c = NULL;
    c2b_nurbs_curve_create(2, 9, U, P, 0, &c, NULL);
    return c;
}

static void test_circle(void)
{
    const double radii[] = {1e-6, 1.0, 1e6};
    for (int ir = 0; ir < 3; ir++) {
        double R = radii[ir];
        c2b_nurbs_curve *c = circle(R);
        double er = 0, ep = 0, ek = 0;
        for (int k = 0; k <= 400; k++) {
            double t = k / 400.0, D[9], x[3];
            c2b_nurbs_curve_eval(c, t, 2, D, NULL);
            er = fmax(er, fabs(norm3(D) - R) / R);
            ep = fmax(ep, fabs(dot3(D, D + 3)) / (norm3(D) * norm3(D + 3)));
            cross3(D + 3, D + 6, x);
            double kappa = norm3(x) / pow(norm3(D + 3), 3);
            ek = fmax(ek, fabs(kappa * R - 1.0));
        }
        char what[128];
        snprintf(what, sizeof what, "circle R = %g: max | |C| / R - 1 | (401 points)", R);
        check_le(what, er, 1e-15);
        snprintf(what, sizeof what, "circle R = %g: max |cos(C, C')|", R);
        check_le(what, ep, 1e-14);
        snprintf(what, sizeof what, "circle R = %g: max |kappa R - 1|, kappa = |C' x C''| / |C'|^3", R);
        check_le(what, ek, 1e-13);
        c2b_nurbs_curve_destroy(c);
    }
}

/* Cylinder: the circle of radius R times the segment z in [0, H]. */
static c2b_nurbs_surface *cylinder(double R, double H)
{
    static const double U[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double V[4] = {0, 0, 1, 1};
    static const double xy[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                                    {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    double P[9 * 2 * 4];
    for (int i = 0; i < 9; i++)
        for (int j = 0; j < 2; j++) {
            double *Q = P + 4 * (i * 2 + j);
            Q[0] = R * xy[i][0];
            Q[1] = R * xy[i][1];
            Q[2] = H * j;
            Q[3] = i % 2 ? SQ2 : 1.0;
        }
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_surface_create(2, 1, 9, 2, U, V, P, NULL, &s, NULL);
    return s;
}

/* Sphere of radius R as a surface of revolution: meridian half circle (u, from the south
 * to the north pole, 5 poles) times the full circle (v, 9 poles). */
static c2b_nurbs_surface *sphere(double R)
{
    static const double U[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    static const double rz[5][2] = {{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}};
    static const double V[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double xy[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                                    {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    double P[5 * 9 * 4];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 9; j++) {
            double *Q = P + 4 * (i * 9 + j);
            Q[0] = R * rz[i][0] * xy[j][0];
            Q[1] = R * rz[i][0] * xy[j][1];
            Q[2] = R * rz[i][1];
            Q[3] = (i % 2 ? SQ2 : 1.0) * (j % 2 ? SQ2 : 1.0);
        }
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_surface_create(2, 2, 5, 9, U, V, P, NULL, &s, NULL);
    return s;
}

/* Octant of the unit sphere (x, y, z >= 0): quarter meridian times quarter circle. */
static c2b_nurbs_surface *octant(void)
{
    static const double U[6] = {0, 0, 0, 1, 1, 1};
    static const double rz[3][2] = {{1, 0}, {1, 1}, {0, 1}};
    static const double xy[3][2] = {{1, 0}, {1, 1}, {0, 1}};
    double P[3 * 3 * 4];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *Q = P + 4 * (i * 3 + j);
            Q[0] = rz[i][0] * xy[j][0];
            Q[1] = rz[i][0] * xy[j][1];
            Q[2] = rz[i][1];
            Q[3] = (i == 1 ? SQ2 : 1.0) * (j == 1 ? SQ2 : 1.0);
        }
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_surface_create(2, 2, 3, 3, U, U, P, NULL, &s, NULL);
    return s;
}

/*
 * Finite-difference check of SKL[a][b], 1 <= a + b <= 3 (and a, b <= 3): central
 * differences of the (a-1, b) entry in u (or (a, b-1) in v) with Richardson
 * extrapolation, D = (4 D(h/2) - D(h)) / 3, over a sweep of h; the best h is kept.
 * Returns the worst relative error over the points.
 */
static double fd_check(const c2b_nurbs_surface *s, rng *r, int npts)
{
    double dom[4], worst = 0.0;
    c2b_nurbs_surface_domain(s, dom);
    for (int k = 0; k < npts; k++) {
        double lu = dom[1] - dom[0], lv = dom[3] - dom[2];
        double u = rnd_in(r, dom[0] + 0.05 * lu, dom[1] - 0.05 * lu);
        double v = rnd_in(r, dom[2] + 0.05 * lv, dom[3] - 0.05 * lv);
        double skl[4 * 4 * 3], scale = 0.0;
        c2b_nurbs_surface_derivs(s, u, v, 3, 3, skl, NULL);
        for (int i = 0; i < 16; i++)
            scale = fmax(scale, norm3(skl + 3 * i));
        for (int a = 0; a <= 3; a++)
            for (int b = 0; b <= 3; b++) {
                if (a + b == 0 || a + b > 3)
                    continue;
                int du = a > 0, lo = (a - du) * 4 + (b - !du);
                double best = INFINITY;
                for (double h = 1e-2; h >= 1e-5; h *= 0.5) {
                    double est[2][3];
                    for (int e = 0; e < 2; e++) {
                        double hh = e ? h / 2 : h, sp[48], sm[48];
                        double up = u + (du ? hh : 0), vp = v + (du ? 0 : hh);
                        double um = u - (du ? hh : 0), vm = v - (du ? 0 : hh);
                        c2b_nurbs_surface_derivs(s, up, vp, 3, 3, sp, NULL);
                        c2b_nurbs_surface_derivs(s, um, vm, 3, 3, sm, NULL);
                        for (int x = 0; x < 3; x++)
                            est[e][x] = (sp[3 * lo + x] - sm[3 * lo + x]) / (2 * hh);
                    }
                    double err = 0.0;
                    for (int x = 0; x < 3; x++) {
                        double rich = (4 * est[1][x] - est[0][x]) / 3;
                        err = fmax(err, fabs(rich - skl[3 * (a * 4 + b) + x]));
                    }
                    best = fmin(best, err);
                }
                worst = fmax(worst, best / scale);
            }
    }
    return worst;
}

static void test_cylinder_sphere(void)
{
    rng r = {0xfeedULL};
    c2b_nurbs_surface *cyl = cylinder(2.0, 3.0);
    double e = 0.0, ez = 0.0;
    for (int k = 0; k < 300; k++) {
        double u = rnd(&r), v = rnd(&r), S[30];
        c2b_nurbs_surface_eval(cyl, u, v, 3, S, NULL);
        e = fmax(e, fabs(hypot(S[0], S[1]) - 2.0));
        ez = fmax(ez, fabs(S[2] - 3.0 * v));
    }
    check_le("cylinder R = 2: max | |(x, y)| - 2 |", e, 4e-16 * 2);
    check_le("cylinder: max |z - 3 v|", ez, 1e-15 * 3);
    check_le("cylinder: finite differences of SKL, a + b <= 3 (relative)", fd_check(cyl, &r, 20), 1e-8);

    const double radii[] = {1e-6, 1.0, 1e6};
    for (int ir = 0; ir < 3; ir++) {
        double R = radii[ir];
        c2b_nurbs_surface *sph = sphere(R);
        e = 0.0;
        double en = 0.0, eh = 0.0;
        for (int k = 0; k < 300; k++) {
            double u = rnd_in(&r, 0.01, 0.99), v = rnd(&r), S[30], n[3];
            c2b_nurbs_surface_eval(sph, u, v, 2, S, NULL);
            e = fmax(e, fabs(norm3(S) - R) / R);
            /* the normal is radial */
            cross3(S + 3, S + 6, n);
            double cn[3];
            cross3(n, S, cn);
            en = fmax(en, norm3(cn) / (norm3(n) * norm3(S)));
            /* second fundamental form: L = Suu . N = -|Su|^2 / R etc. (umbilic) */
            double N[3] = {-S[0] / R, -S[1] / R, -S[2] / R};
            double E = dot3(S + 3, S + 3), F = dot3(S + 3, S + 6), G = dot3(S + 6, S + 6);
            double L = dot3(S + 9, N), M = dot3(S + 12, N), Nn = dot3(S + 15, N);
            eh = fmax(eh, fmax(fabs(L * R - E), fmax(fabs(M * R - F), fabs(Nn * R - G))) / fmax(E, G));
        }
        char what[160];
        snprintf(what, sizeof what, "sphere R = %g: max | |S| / R - 1 |", R);
        check_le(what, e, 1e-15);
        snprintf(what, sizeof what, "sphere R = %g: normal Su x Sv is radial (max sin)", R);
        check_le(what, en, 1e-13);
        snprintf(what, sizeof what, "sphere R = %g: umbilic, (L, M, N) = (E, F, G) / R", R);
        check_le(what, eh, 1e-13);
        c2b_nurbs_surface_destroy(sph);
    }
    c2b_nurbs_surface *oct = octant();
    e = 0.0;
    for (int k = 0; k < 300; k++) {
        double u = rnd(&r), v = rnd(&r), S[3];
        c2b_nurbs_surface_eval(oct, u, v, 0, S, NULL);
        e = fmax(e, fabs(norm3(S) - 1.0));
        if (S[0] < -1e-16 || S[1] < -1e-16 || S[2] < -1e-16)
            e = 1.0;
    }
    check_le("sphere octant: max | |S| - 1 | and S in the octant", e, 1e-15);
    check_le("sphere octant: finite differences of SKL (relative)", fd_check(oct, &r, 20), 1e-8);
    c2b_nurbs_surface *sph = sphere(1.0);
    check_le("sphere: finite differences of SKL (relative)", fd_check(sph, &r, 20), 1e-8);
    c2b_nurbs_surface *rs = random_surface(&r, 5, 3, 9, 7, 1, 2);
    check_le("random rational (5, 3) surface: finite differences (relative)", fd_check(rs, &r, 20),
             1e-8);

    /* layouts: the blend layout equals the table */
    double S[30], skl[4 * 4 * 3], worst = 0.0;
    for (int k = 0; k < 20; k++) {
        double u = rnd(&r), v = rnd(&r);
        c2b_nurbs_surface_eval(oct, u, v, 3, S, NULL);
        c2b_nurbs_surface_derivs(oct, u, v, 3, 3, skl, NULL);
        int idx = 0;
        for (int o = 0; o <= 3; o++)
            for (int b = 0; b <= o; b++, idx++)
                for (int x = 0; x < 3; x++)
                    worst = fmax(worst, fabs(S[3 * idx + x] - skl[3 * ((o - b) * 4 + b) + x]));
    }
    check_le("blend layout [S, Su, Sv, Suu, Suv, Svv, ...] equals the SKL table", worst, 0.0);
    c2b_nurbs_surface_destroy(cyl);
    c2b_nurbs_surface_destroy(oct);
    c2b_nurbs_surface_destroy(sph);
    c2b_nurbs_surface_destroy(rs);
}

/* ---- knot insertion and degree elevation ---------------------------------------------- */

/* Natural size of a k-th derivative: |coordinates| (p / h)^k with h the shortest
 * non-empty knot span (what a perturbation of the poles by eps changes it by, / eps). */
static double deriv_scale(const double *U, int nk, int p, int k, double coord)
{
    double h = INFINITY;
    for (int i = 0; i + 1 < nk; i++)
        if (U[i + 1] > U[i])
            h = fmin(h, U[i + 1] - U[i]);
    return coord * pow(p / h, k);
}

/* Worst relative difference of SKL (a, b <= ord) between two surfaces at 200 random
 * points, each derivative relative to the larger of its largest norm over the sample and
 * its natural size (deriv_scale() of the second surface, which has the higher degree or
 * the shorter spans). */
static double surface_diff(const c2b_nurbs_surface *a, const c2b_nurbs_surface *b, rng *r, int ord)
{
    double dom[4], scale[16] = {0}, diff[16] = {0};
    c2b_nurbs_surface_domain(a, dom);
    int w = ord + 1;
    for (int k = 0; k < 200; k++) {
        double u = k == 0 ? dom[0] : (k == 1 ? dom[1] : rnd_in(r, dom[0], dom[1]));
        double v = k == 0 ? dom[2] : (k == 1 ? dom[3] : rnd_in(r, dom[2], dom[3]));
        double sa[NDER], sb[NDER];
        if (c2b_nurbs_surface_derivs(a, u, v, ord, ord, sa, NULL) ||
            c2b_nurbs_surface_derivs(b, u, v, ord, ord, sb, NULL))
            return INFINITY;
        for (int i = 0; i < w * w; i++) {
            scale[i] = fmax(scale[i], norm3(sa + 3 * i));
            diff[i] = fmax(diff[i], dist3(sa + 3 * i, sb + 3 * i));
        }
    }
    double worst = 0.0;
    for (int i = 0; i < w * w; i++) {
        double nat = deriv_scale(c2b_nurbs_surface_knots(b, 0), c2b_nurbs_surface_nknots(b, 0),
                                 c2b_nurbs_surface_degree(b, 0), i / w, 1.0) *
                     deriv_scale(c2b_nurbs_surface_knots(b, 1), c2b_nurbs_surface_nknots(b, 1),
                                 c2b_nurbs_surface_degree(b, 1), i % w, scale[0]);
        worst = fmax(worst, diff[i] / fmax(scale[i], nat));
    }
    return worst;
}

static double curve_diff(const c2b_nurbs_curve *a, const c2b_nurbs_curve *b, rng *r, int ord)
{
    double t0, t1, scale[8] = {0}, diff[8] = {0};
    c2b_nurbs_curve_domain(a, &t0, &t1);
    for (int k = 0; k < 200; k++) {
        double t = k == 0 ? t0 : (k == 1 ? t1 : rnd_in(r, t0, t1)), ca[24], cb[24];
        if (c2b_nurbs_curve_eval(a, t, ord, ca, NULL) || c2b_nurbs_curve_eval(b, t, ord, cb, NULL))
            return INFINITY;
        for (int i = 0; i <= ord; i++) {
            scale[i] = fmax(scale[i], norm3(ca + 3 * i));
            diff[i] = fmax(diff[i], dist3(ca + 3 * i, cb + 3 * i));
        }
    }
    double worst = 0.0;
    for (int i = 0; i <= ord; i++) {
        double nat = deriv_scale(c2b_nurbs_curve_knots(b), c2b_nurbs_curve_nknots(b),
                                 c2b_nurbs_curve_degree(b), i, scale[0]);
        worst = fmax(worst, diff[i] / fmax(scale[i], nat));
    }
    return worst;
}

static void test_insert_elevate(void)
{
    rng r = {0xabcdef12345ULL};
    c2b_error err;
    char what[200];
    /* curves: random degrees, rational, repeated knots */
    for (int trial = 0; trial < 8; trial++) {
        int p = 1 + trial % 5;
        c2b_nurbs_curve *c = random_curve(&r, p, p + 5, trial % 2 == 0, p);
        c2b_nurbs_curve *d = NULL;
        c2b_nurbs_curve_copy(c, &d, NULL);
        double t0, t1;
        c2b_nurbs_curve_domain(c, &t0, &t1);
        const double *U = c2b_nurbs_curve_knots(c);
        double tk = U[p + 1]; /* an existing interior knot */
        int s = 0;
        for (int i = 0; i < c2b_nurbs_curve_nknots(c); i++)
            s += U[i] == tk;
        int ok = !c2b_nurbs_curve_insert_knot(d, rnd_in(&r, t0, t1), 1, &err);
        ok = ok && !c2b_nurbs_curve_insert_knot(d, rnd_in(&r, t0, t1), p, &err);
        ok = ok && (s >= p || !c2b_nurbs_curve_insert_knot(d, tk, p - s, &err));
        snprintf(what, sizeof what, "curve p = %d: knot insertion succeeds", p);
        check_true(what, ok);
        snprintf(what, sizeof what, "curve p = %d: knot insertion keeps C..C''' (relative)", p);
        check_le(what, curve_diff(c, d, &r, 3), 1e-13);
        c2b_nurbs_curve *e = NULL;
        c2b_nurbs_curve_copy(c, &e, NULL);
        ok = !c2b_nurbs_curve_elevate(e, 1 + trial % 3, &err);
        snprintf(what, sizeof what, "curve p = %d: elevation by %d succeeds (degree %d)", p,
                 1 + trial % 3, c2b_nurbs_curve_degree(e));
        check_true(what, ok && c2b_nurbs_curve_degree(e) == p + 1 + trial % 3);
        snprintf(what, sizeof what, "curve p = %d: degree elevation keeps C..C''' (relative)", p);
        check_le(what, curve_diff(c, e, &r, 3), 1e-13);
        c2b_nurbs_curve_destroy(c);
        c2b_nurbs_curve_destroy(d);
        c2b_nurbs_curve_destroy(e);
    }
    /* unclamped curve: elevation clamps it without changing the shape */
    {
        double U[] = {-1.0, -0.5, 0.0, 1.0, 1.5, 2.5, 3.0, 3.5, 4.2};
        double P[6 * 4];
        for (int i = 0; i < 6; i++) {
            P[4 * i] = i;
            P[4 * i + 1] = sin(i);
            P[4 * i + 2] = cos(2 * i);
            P[4 * i + 3] = 1.0 + 0.2 * i;
        }
        c2b_nurbs_curve *c = NULL, *e = NULL, *d = NULL;
        c2b_nurbs_curve_create(2, 6, U, P, 0, &c, NULL);
        c2b_nurbs_curve_copy(c, &e, NULL);
        c2b_nurbs_curve_copy(c, &d, NULL);
        check_true("unclamped curve: elevation succeeds", !c2b_nurbs_curve_elevate(e, 2, &err));
        check_le("unclamped curve: elevation keeps the shape", curve_diff(c, e, &r, 3), 1e-13);
        double t0, t1;
        c2b_nurbs_curve_domain(c, &t0, &t1);
        expect_err("unclamped curve (p = 2): inserting the end knot twice exceeds p",
                   c2b_nurbs_curve_insert_knot(d, t1, 2, &err), &err, C2B_ERR_ARG,
                   "has multiplicity 1; inserting it 2 times would exceed the degree 2");
        check_true("unclamped curve: insertion at both domain ends succeeds",
                   !c2b_nurbs_curve_insert_knot(d, t1, 1, &err) &&
                       !c2b_nurbs_curve_insert_knot(d, t0, 1, &err));
        check_le("unclamped curve: insertion at the domain ends keeps the shape",
                 curve_diff(c, d, &r, 3), 1e-13);
        c2b_nurbs_curve_destroy(c);
        c2b_nurbs_curve_destroy(d);
        c2b_nurbs_curve_destroy(e);
    }
    /* surfaces: both directions */
    for (int trial = 0; trial < 6; trial++) {
        int p = 1 + trial % 4, q = 1 + (trial + 2) % 5;
        c2b_nurbs_surface *s = random_surface(&r, p, q, p + 4, q + 3, trial % 3 != 1, 2);
        double dom[4];
        c2b_nurbs_surface_domain(s, dom);
        c2b_nurbs_surface *d = NULL, *e = NULL;
        c2b_nurbs_surface_copy(s, &d, NULL);
        c2b_nurbs_surface_copy(s, &e, NULL);
        int ok = !c2b_nurbs_surface_insert_knot(d, 0, rnd_in(&r, dom[0], dom[1]), p, &err) &&
                 !c2b_nurbs_surface_insert_knot(d, 1, rnd_in(&r, dom[2], dom[3]), 1, &err) &&
                 !c2b_nurbs_surface_insert_knot(d, 1, rnd_in(&r, dom[2], dom[3]), q, &err);
        snprintf(what, sizeof what, "surface (%d, %d): insertions in u and v succeed", p, q);
        check_true(what, ok);
        snprintf(what, sizeof what, "surface (%d, %d): insertion keeps SKL, a, b <= 2 (relative)", p, q);
        check_le(what, surface_diff(s, d, &r, 2), 1e-13);
        ok = !c2b_nurbs_surface_elevate(e, 0, 1 + trial % 2, &err) &&
             !c2b_nurbs_surface_elevate(e, 1, 2 - trial % 2, &err);
        snprintf(what, sizeof what, "surface (%d, %d): elevation to (%d, %d)", p, q,
                 c2b_nurbs_surface_degree(e, 0), c2b_nurbs_surface_degree(e, 1));
        check_true(what, ok && c2b_nurbs_surface_degree(e, 0) == p + 1 + trial % 2 &&
                             c2b_nurbs_surface_degree(e, 1) == q + 2 - trial % 2);
        snprintf(what, sizeof what, "surface (%d, %d): elevation keeps SKL, a, b <= 2 (relative)", p, q);
        check_le(what, surface_diff(s, e, &r, 2), 1e-13);
        c2b_nurbs_surface_destroy(s);
        c2b_nurbs_surface_destroy(d);
        c2b_nurbs_surface_destroy(e);
    }
    /* polynomial splines (all weights equal, here 2) stay polynomial: derivatives above
     * the degree are exactly zero before and after knot insertion */
    {
        double U[10] = {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1}, P[6 * 4];
        for (int i = 0; i < 6; i++) {
            P[4 * i] = i;
            P[4 * i + 1] = sin(3.0 * i);
            P[4 * i + 2] = 0.1 * i * i;
            P[4 * i + 3] = 2.0;
        }
        c2b_nurbs_curve *c = NULL;
        c2b_nurbs_curve_create(3, 6, U, P, 0, &c, NULL);
        double D0[15], D1[15], D2[15], W[4];
        c2b_nurbs_curve_eval(c, 0.45, 4, D0, NULL);
        c2b_nurbs_curve_insert_knot(c, 0.77, 2, NULL);
        c2b_nurbs_curve_eval(c, 0.45, 4, D1, NULL);
        c2b_nurbs_curve_eval(c, 0.9, 4, D2, NULL);
        c2b_nurbs_curve_pole(c, 6, W);
        check_true("polynomial cubic (weights 2): 4th derivative exactly 0, also after knot "
                   "insertion; weights still exactly 2",
                   norm3(D0 + 12) == 0.0 && norm3(D1 + 12) == 0.0 && norm3(D2 + 12) == 0.0 &&
                       W[3] == 2.0);
        c2b_nurbs_curve_destroy(c);
    }
    /* sphere: elevation and insertion keep it a sphere */
    {
        c2b_nurbs_surface *s = sphere(1.0);
        c2b_nurbs_surface_elevate(s, 0, 3, NULL);
        c2b_nurbs_surface_elevate(s, 1, 1, NULL);
        c2b_nurbs_surface_insert_knot(s, 0, 0.3, 2, NULL);
        c2b_nurbs_surface_insert_knot(s, 1, 0.25, 1, NULL);
        double e = 0.0;
        for (int k = 0; k < 200; k++) {
            double S[3];
            c2b_nurbs_surface_eval(s, rnd(&r), rnd(&r), 0, S, NULL);
            e = fmax(e, fabs(norm3(S) - 1.0));
        }
        check_true("sphere elevated to (5, 3) with knots inserted",
                   c2b_nurbs_surface_degree(s, 0) == 5 && c2b_nurbs_surface_degree(s, 1) == 3);
        check_le("... still max | |S| - 1 |", e, 1e-14);
        c2b_nurbs_surface_destroy(s);
    }
    /* limits */
    {
        c2b_nurbs_curve *c = random_curve(&r, 3, 8, 1, 2);
        const double *U = c2b_nurbs_curve_knots(c);
        double t0, t1;
        c2b_nurbs_curve_domain(c, &t0, &t1);
        expect_err("insertion beyond multiplicity p", c2b_nurbs_curve_insert_knot(c, 0.5 * (t0 + t1), 4, &err),
                   &err, C2B_ERR_ARG, "would exceed the degree 3");
        expect_err("insertion at a clamped end", c2b_nurbs_curve_insert_knot(c, t0, 1, &err), &err,
                   C2B_ERR_ARG, "has multiplicity 4");
        double tk = U[4];
        int s = 0;
        for (int i = 0; i < c2b_nurbs_curve_nknots(c); i++)
            s += U[i] == tk;
        expect_err("insertion of an existing knot beyond p",
                   c2b_nurbs_curve_insert_knot(c, tk, 4 - s, &err), &err, C2B_ERR_ARG,
                   "would exceed the degree");
        expect_err("insertion outside the domain", c2b_nurbs_curve_insert_knot(c, t1 + 1, 1, &err),
                   &err, C2B_ERR_ARG, "outside the domain");
        expect_err("elevation beyond degree 15", c2b_nurbs_curve_elevate(c, 13, &err), &err,
                   C2B_ERR_ARG, "exceeds 15");
        expect_err("negative elevation", c2b_nurbs_curve_elevate(c, -1, &err), &err, C2B_ERR_ARG,
                   "times must be >= 0");
        check_true("the failed calls left the curve unchanged",
                   c2b_nurbs_curve_degree(c) == 3 && c2b_nurbs_curve_npoles(c) == 8);
        c2b_nurbs_surface *sf = random_surface(&r, 2, 2, 4, 4, 1, 1);
        expect_err("surface insertion with dir 2", c2b_nurbs_surface_insert_knot(sf, 2, 0.5, 1, &err),
                   &err, C2B_ERR_ARG, "dir must be 0 (u) or 1 (v)");
        c2b_nurbs_surface_destroy(sf);
        c2b_nurbs_curve_destroy(c);
    }
}

/* ---- projection ------------------------------------------------------------------------- */

static void test_projection(void)
{
    rng r = {0x5eedULL};
    c2b_error err;
    /* a gently curved random surface: offset points along the unit normal */
    c2b_nurbs_surface *s = random_surface(&r, 3, 3, 8, 7, 1, 2);
    double dom[4];
    c2b_nurbs_surface_domain(s, dom);
    double euv = 0.0, ed = 0.0;
    int fails = 0;
    for (int k = 0; k < 40; k++) {
        double u = rnd_in(&r, dom[0] + 0.02, dom[1] - 0.02), v = rnd_in(&r, dom[2] + 0.02, dom[3] - 0.02);
        double S[9], n[3], P[3], uv[2], d;
        c2b_nurbs_surface_eval(s, u, v, 1, S, NULL);
        cross3(S + 3, S + 6, n);
        double ln = norm3(n);
        for (int x = 0; x < 3; x++)
            P[x] = S[x] + 0.01 * n[x] / ln;
        if (c2b_nurbs_surface_project(s, P, uv, &d, &err)) {
            fails++;
            continue;
        }
        euv = fmax(euv, fmax(fabs(uv[0] - u), fabs(uv[1] - v)));
        ed = fmax(ed, fabs(d - 0.01));
    }
    check_true("surface projection: 40 calls succeed", fails == 0);
    check_le("surface projection of S + 0.01 n: max |(u, v) - (u*, v*)|", euv, 1e-10);
    check_le("surface projection: max |distance - 0.01|", ed, 1e-12);

    /* sphere: every point projects radially (points inside and outside) */
    c2b_nurbs_surface *sph = sphere(2.0);
    double e = 0.0;
    for (int k = 0; k < 30; k++) {
        double u = rnd_in(&r, 0.05, 0.95), v = rnd(&r), S[3], P[3], uv[2], d, Q[3];
        c2b_nurbs_surface_eval(sph, u, v, 0, S, NULL);
        double f = k % 2 ? 1.3 : 0.6;
        for (int x = 0; x < 3; x++)
            P[x] = f * S[x];
        c2b_nurbs_surface_project(sph, P, uv, &d, NULL);
        c2b_nurbs_surface_eval(sph, uv[0], uv[1], 0, Q, NULL);
        e = fmax(e, fmax(fabs(d - fabs(f - 1) * 2.0), dist3(Q, S)));
    }
    check_le("sphere R = 2: projection of f S(u, v) is S(u, v) at distance |f - 1| R", e, 1e-12);

    /* off the boundary of a plane patch: clamped to the edge */
    {
        double U[4] = {0, 0, 1, 1}, P[16] = {0, 0, 0, 1, 0, 1, 0, 1, 1, 0, 0, 1, 1, 1, 0, 1}, uv[2], d;
        c2b_nurbs_surface *pl = NULL;
        c2b_nurbs_surface_create(1, 1, 2, 2, U, U, P, NULL, &pl, NULL);
        double X[3] = {1.5, 0.25, 0.5};
        c2b_nurbs_surface_project(pl, X, uv, &d, NULL);
        check_close("plane: projection beyond the edge u = 1: u", uv[0], 1.0, 0, 0);
        check_close("plane: ... v", uv[1], 0.25, 0, 1e-15);
        check_close("plane: ... distance", d, sqrt(0.5), 1e-15, 0);
        c2b_nurbs_surface_destroy(pl);
    }

    /* curves */
    c2b_nurbs_curve *c = random_curve(&r, 3, 9, 1, 2);
    double t0, t1, et = 0.0, edc = 0.0;
    c2b_nurbs_curve_domain(c, &t0, &t1);
    for (int k = 0; k < 40; k++) {
        double t = rnd_in(&r, t0 + 0.05, t1 - 0.05), D[6], n[3], P[3], tt, d;
        double ax[3] = {rnd(&r), rnd(&r), rnd(&r)};
        c2b_nurbs_curve_eval(c, t, 1, D, NULL);
        cross3(D + 3, ax, n);
        double ln = norm3(n);
        for (int x = 0; x < 3; x++)
            P[x] = D[x] + 0.01 * n[x] / ln;
        c2b_nurbs_curve_project(c, P, &tt, &d, NULL);
        et = fmax(et, fabs(tt - t));
        edc = fmax(edc, fabs(d - 0.01));
    }
    check_le("curve projection of C + 0.01 n: max |t - t*|", et, 1e-10);
    check_le("curve projection: max |distance - 0.01|", edc, 1e-12);
    {
        double D[6], P[3], tt, d;
        c2b_nurbs_curve_eval(c, t1, 1, D, NULL);
        double l = norm3(D + 3);
        for (int x = 0; x < 3; x++)
            P[x] = D[x] + 0.5 * D[3 + x] / l;
        c2b_nurbs_curve_project(c, P, &tt, &d, NULL);
        check_close("curve: a point beyond the end along the tangent projects to t1", tt, t1, 0, 0);
        check_close("... at distance 0.5", d, 0.5, 1e-14, 0);
    }
    /* the circle: any point off the centre projects radially */
    c2b_nurbs_curve *ci = circle(3.0);
    e = 0.0;
    for (int k = 0; k < 30; k++) {
        double a = rnd_in(&r, 0, 2 * 3.14159265358979323846), f = rnd_in(&r, 0.2, 3.0);
        double P[3] = {3 * f * cos(a), 3 * f * sin(a), k % 3 == 0 ? 0.5 : 0.0}, tt, d, Q[3];
        c2b_nurbs_curve_project(ci, P, &tt, &d, NULL);
        c2b_nurbs_curve_eval(ci, tt, 0, Q, NULL);
        double dz = P[2], rad = 3 * fabs(f - 1);
        e = fmax(e, fabs(d - sqrt(rad * rad + dz * dz)));
        e = fmax(e, fabs(atan2(Q[1], Q[0]) - atan2(P[1], P[0])) > 1e-9 &&
                            fabs(fabs(atan2(Q[1], Q[0]) - atan2(P[1], P[0])) - 2 * 3.14159265358979) > 1e-9
                        ? 1.0
                        : 0.0);
    }
    check_le("circle R = 3: projections are radial with the exact distance", e, 1e-12);

    double bad[3] = {NAN, 0, 0}, tt, uv[2], d;
    expect_err("curve projection of a NaN point", c2b_nurbs_curve_project(c, bad, &tt, &d, &err), &err,
               C2B_ERR_ARG, "not finite");
    expect_err("surface projection of a NaN point", c2b_nurbs_surface_project(s, bad, uv, &d, &err),
               &err, C2B_ERR_ARG, "not finite");
    c2b_nurbs_curve_destroy(c);
    c2b_nurbs_curve_destroy(ci);
    c2b_nurbs_surface_destroy(s);
    c2b_nurbs_surface_destroy(sph);
}

/* ---- periodic ------------------------------------------------------------------------------ */

/* Periodic flat knot vector: n periodic spacings sp[] starting at a. */
static void periodic_knots(int p, int n, double a, const double *sp, double *U)
{
    double T = 0.0;
    for (int i = 0; i < n; i++)
        T += sp[i];
    /* U[p] = a; U[p + i + 1] = U[p + i] + sp[i mod n]; extend to the left likewise */
    U[p] = a;
    for (int i = p + 1; i < n + 2 * p + 1; i++)
        U[i] = U[i - 1] + sp[(i - p - 1) % n];
    for (int i = p - 1; i >= 0; i--)
        U[i] = U[i + 1] - sp[((i - p) % n + n) % n];
    (void)T;
}

static void test_periodic(void)
{
    rng r = {0x9e3779b97f4a7c15ULL};
    c2b_error err;
    char what[160];
    int p = 3, n = 7;
    double sp[7], U[7 + 2 * 3 + 1], P[7 * 4];
    for (int i = 0; i < n; i++) {
        sp[i] = rnd_in(&r, 0.5, 1.5);
        double a = 2 * 3.14159265358979 * i / n;
        P[4 * i + 0] = cos(a) + rnd_in(&r, -0.1, 0.1);
        P[4 * i + 1] = sin(a) + rnd_in(&r, -0.1, 0.1);
        P[4 * i + 2] = rnd_in(&r, -0.3, 0.3);
        P[4 * i + 3] = rnd_in(&r, 0.5, 2.0);
    }
    periodic_knots(p, n, 0.25, sp, U);
    c2b_nurbs_curve *c = NULL, *open = NULL;
    c2b_status st = c2b_nurbs_curve_create(p, n, U, P, 1, &c, &err);
    check_true("periodic cubic curve created", st == C2B_OK);
    if (st) {
        printf("  %s\n", err.msg);
        return;
    }
    /* the same spline as an open (unclamped) curve with the n + p unwrapped poles */
    double Pw[10 * 4];
    for (int i = 0; i < n + p; i++)
        memcpy(Pw + 4 * i, P + 4 * (i % n), 4 * sizeof(double));
    c2b_nurbs_curve_create(p, n + p, U, Pw, 0, &open, NULL);
    double t0, t1;
    c2b_nurbs_curve_domain(c, &t0, &t1);
    double right[12], left[12], o1[12];
    c2b_nurbs_curve_eval(c, t0, 3, right, NULL);
    c2b_nurbs_curve_eval(open, t1, 3, left, NULL); /* left limit at the seam */
    c2b_nurbs_curve_eval(c, t1, 3, o1, NULL);      /* wraps to t0 */
    for (int k = 0; k <= 2; k++) {
        snprintf(what, sizeof what, "periodic curve: C^(%d) equal on both sides of the seam", k);
        check_le(what, dist3(right + 3 * k, left + 3 * k) / fmax(1.0, norm3(right + 3 * k)), 1e-13);
    }
    check_true("periodic cubic: C''' differs across the seam (non-uniform knots)",
               dist3(right + 9, left + 9) > 1e-6);
    check_le("periodic curve: C(t1) wraps to C(t0)", dist3(o1, right), 0.0);
    double T = t1 - t0, ew = 0.0;
    for (int k = 0; k < 100; k++) {
        double t = rnd_in(&r, t0, t1), a[12], b[12];
        c2b_nurbs_curve_eval(c, t, 3, a, NULL);
        c2b_nurbs_curve_eval(c, t + (k % 7 - 3) * T, 3, b, NULL);
        for (int i = 0; i < 4; i++)
            ew = fmax(ew, dist3(a + 3 * i, b + 3 * i) / fmax(1.0, norm3(a + 3 * i)));
    }
    check_le("periodic curve: C(t + m T) = C(t), m = -3..3, derivatives 0..3", ew, 1e-12);

    /* knot insertion in a periodic curve, also at the seam and at an existing knot */
    c2b_nurbs_curve *d = NULL;
    c2b_nurbs_curve_copy(c, &d, NULL);
    int ok = !c2b_nurbs_curve_insert_knot(d, t0 + 0.3 * T, 2, &err) &&
             !c2b_nurbs_curve_insert_knot(d, t0, 1, &err) &&
             !c2b_nurbs_curve_insert_knot(d, U[5], 2, &err) &&
             !c2b_nurbs_curve_insert_knot(d, t1 + 0.9 * T, 1, &err);
    snprintf(what, sizeof what, "periodic curve: 6 insertions succeed (%d poles now)",
             c2b_nurbs_curve_npoles(d));
    check_true(what, ok && c2b_nurbs_curve_npoles(d) == n + 6 && c2b_nurbs_curve_periodic(d));
    check_le("periodic curve: insertion keeps C..C''' (relative)", curve_diff(c, d, &r, 3), 1e-13);
    expect_err("periodic curve: insertion beyond multiplicity p", c2b_nurbs_curve_insert_knot(d, U[5], 1, &err),
               &err, C2B_ERR_ARG, "would exceed the degree");
    expect_err("periodic curve: elevation is refused", c2b_nurbs_curve_elevate(d, 1, &err), &err,
               C2B_ERR_ARG, "periodic");
    /* the new knot vector is still periodic: re-creating from it succeeds */
    {
        c2b_nurbs_curve *e = NULL;
        double Pd[4 * 16];
        for (int i = 0; i < c2b_nurbs_curve_npoles(d); i++)
            c2b_nurbs_curve_pole(d, i, Pd + 4 * i);
        st = c2b_nurbs_curve_create(p, c2b_nurbs_curve_npoles(d), c2b_nurbs_curve_knots(d), Pd, 1, &e, &err);
        check_true("periodic curve after insertion re-validates", st == C2B_OK);
        if (st)
            printf("  %s\n", err.msg);
        c2b_nurbs_curve_destroy(e);
    }
    /* projection near the seam */
    {
        double D[6], ax[3] = {0, 0, 1}, nn[3], X[3], tt, dd;
        double ts = t1 - 1e-3;
        c2b_nurbs_curve_eval(c, ts, 1, D, NULL);
        cross3(D + 3, ax, nn);
        for (int x = 0; x < 3; x++)
            X[x] = D[x] + 0.01 * nn[x] / norm3(nn);
        c2b_nurbs_curve_project(c, X, &tt, &dd, NULL);
        check_close("periodic curve: projection next to the seam recovers t", tt, ts, 0, 1e-10);
    }

    /* periodic surface: periodic cubic in u, open quadratic in v; and periodic in both */
    for (int both = 0; both < 2; both++) {
        int q = 2, nv = 5, nvw = both ? nv : nv;
        double V[5 + 2 * 2 + 1], spv[5] = {0.3, 0.5, 0.4, 0.6, 0.35};
        if (both)
            periodic_knots(q, nv, -1.0, spv, V);
        else {
            double Vo[8] = {0, 0, 0, 0.3, 0.5, 1, 1, 1};
            memcpy(V, Vo, sizeof Vo);
        }
        double SP[7 * 5 * 4];
        for (int i = 0; i < n; i++)
            for (int j = 0; j < nvw; j++) {
                double *Q = SP + 4 * (i * nv + j);
                double a = 2 * 3.14159265358979 * i / n, b = 2 * 3.14159265358979 * j / nv;
                double rr = both ? 2 + 0.7 * cos(b) : 1 + 0.2 * j;
                Q[0] = rr * cos(a) + rnd_in(&r, -0.05, 0.05);
                Q[1] = rr * sin(a) + rnd_in(&r, -0.05, 0.05);
                Q[2] = both ? 0.7 * sin(b) : j;
                Q[3] = rnd_in(&r, 0.7, 1.5);
            }
        int per[2] = {1, both};
        c2b_nurbs_surface *s = NULL;
        st = c2b_nurbs_surface_create(p, q, n, nv, U, V, SP, per, &s, &err);
        snprintf(what, sizeof what, "periodic surface (u%s) created", both ? " and v" : "");
        check_true(what, st == C2B_OK);
        if (st) {
            printf("  %s\n", err.msg);
            continue;
        }
        double dom[4];
        c2b_nurbs_surface_domain(s, dom);
        double worst = 0.0;
        for (int k = 0; k < 20; k++) {
            double v = rnd_in(&r, dom[2], dom[3]), a[NDER], b[NDER], h = 1e-7;
            /* both sides of the seam u = u0: compare one-sided Taylor extrapolations */
            c2b_nurbs_surface_derivs(s, dom[0] + h, v, 3, 2, a, NULL);
            c2b_nurbs_surface_derivs(s, dom[1] - h, v, 3, 2, b, NULL);
            for (int i = 0; i < 3; i++)   /* a = 0..2 */
                for (int j = 0; j <= 2; j++) {
                    int idx = i * 3 + j, up = (i + 1) * 3 + j;
                    for (int x = 0; x < 3; x++) {
                        double ra = a[3 * idx + x] - h * a[3 * up + x];
                        double rb = b[3 * idx + x] + h * b[3 * up + x];
                        worst = fmax(worst, fabs(ra - rb) / fmax(1.0, fabs(a[3 * idx + x])));
                    }
                }
        }
        snprintf(what, sizeof what, "periodic surface%s: S_u^a S_v^b, a <= 2, continuous across u seam", both ? " (both)" : "");
        check_le(what, worst, 1e-9);
        ew = 0.0;
        for (int k = 0; k < 50; k++) {
            double u = rnd_in(&r, dom[0], dom[1]), v = rnd_in(&r, dom[2], dom[3]), a[30], b[30];
            double lu = dom[1] - dom[0], lv = dom[3] - dom[2];
            c2b_nurbs_surface_eval(s, u, v, 3, a, NULL);
            c2b_nurbs_surface_eval(s, u - 2 * lu, both ? v + 3 * lv : v, 3, b, NULL);
            for (int i = 0; i < 10; i++)
                ew = fmax(ew, dist3(a + 3 * i, b + 3 * i) / fmax(1.0, norm3(a + 3 * i)));
        }
        snprintf(what, sizeof what, "periodic surface%s: parameters wrap", both ? " (both)" : "");
        check_le(what, ew, 1e-12);
        if (!both) {
            double vv = dom[3] + 0.1, out[3];
            expect_err("periodic-in-u surface: v outside its open domain",
                       c2b_nurbs_surface_eval(s, 0.0, vv, 0, out, &err), &err, C2B_ERR_ARG,
                       "parameter v = ");
        }
        c2b_nurbs_surface *e = NULL;
        c2b_nurbs_surface_copy(s, &e, NULL);
        ok = !c2b_nurbs_surface_insert_knot(e, 0, dom[0] + 0.77 * (dom[1] - dom[0]), 2, &err) &&
             !c2b_nurbs_surface_insert_knot(e, 1, dom[2] + 0.41 * (dom[3] - dom[2]), 1, &err);
        if (!both)
            ok = ok && !c2b_nurbs_surface_elevate(e, 1, 2, &err);
        snprintf(what, sizeof what, "periodic surface%s: insertion%s succeed", both ? " (both)" : "",
                 both ? "s" : "s and v elevation");
        check_true(what, ok);
        snprintf(what, sizeof what, "periodic surface%s: ... shape unchanged", both ? " (both)" : "");
        check_le(what, surface_diff(s, e, &r, 2), 1e-13);
        expect_err("periodic surface: elevation in u is refused", c2b_nurbs_surface_elevate(e, 0, 1, &err),
                   &err, C2B_ERR_ARG, "periodic");
        /* projection across the seam */
        double S[9], nn[3], X[3], uv[2], dd, us = dom[0] + 1e-4, vs = dom[2] + 0.5 * (dom[3] - dom[2]);
        c2b_nurbs_surface_eval(s, us, vs, 1, S, NULL);
        cross3(S + 3, S + 6, nn);
        for (int x = 0; x < 3; x++)
            X[x] = S[x] + 0.01 * nn[x] / norm3(nn);
        c2b_nurbs_surface_project(s, X, uv, &dd, NULL);
        snprintf(what, sizeof what, "periodic surface%s: projection next to the seam: u", both ? " (both)" : "");
        check_close(what, uv[0], us, 0, 1e-10);
        check_close("... distance", dd, 0.01, 0, 1e-12);
        c2b_nurbs_surface_destroy(s);
        c2b_nurbs_surface_destroy(e);
    }
    c2b_nurbs_curve_destroy(c);
    c2b_nurbs_curve_destroy(d);
    c2b_nurbs_curve_destroy(open);
}

/* ---- bad input ------------------------------------------------------------------------------ */

static void test_bad_input(void)
{
    c2b_error err;
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_curve *c = NULL;
    double ku[11] = {0, 0, 0, 0, 0.2, 0.5, 0.4, 0.7, 1, 1, 1};
    double kv[9] = {0, 0, 0, 0.5, 0.6, 0.7, 1, 1, 1};
    double ok_u[11] = {0, 0, 0, 0, 0.2, 0.4, 0.5, 1, 1, 1, 1};
    double P[7 * 6 * 4];
    for (int i = 0; i < 7 * 6; i++) {
        P[4 * i] = i;
        P[4 * i + 1] = i % 3;
        P[4 * i + 2] = 0;
        P[4 * i + 3] = 1;
    }
    expect_err("decreasing knots_u", c2b_nurbs_surface_create(3, 2, 7, 6, ku, kv, P, NULL, &s, &err),
               &err, C2B_ERR_SPEC, "knots_u: decreasing at index 6 (0.4 after 0.5)");
    check_true("failed create leaves *out NULL", s == NULL);
    P[4 * (2 * 6 + 3) + 3] = 0.0;
    expect_err("zero weight", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "poles[2][3]: weight must be positive (got 0)");
    P[4 * (2 * 6 + 3) + 3] = -1.5;
    expect_err("negative weight", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, &s, &err),
               &err, C2B_ERR_SPEC, "poles[2][3]: weight must be positive (got -1.5)");
    P[4 * (2 * 6 + 3) + 3] = 1.0;
    P[4 * (2 * 6 + 3) + 1] = NAN;
    expect_err("NaN pole", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "poles[2][3]: not finite");
    P[4 * (2 * 6 + 3) + 1] = INFINITY;
    expect_err("infinite pole", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "poles[2][3]: not finite");
    P[4 * (2 * 6 + 3) + 1] = 1e300;
    P[4 * (2 * 6 + 3) + 3] = 1e10;
    expect_err("pole overflowing when weighted",
               c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, &s, &err), &err, C2B_ERR_SPEC,
               "poles[2][3]: not finite after weighting");
    P[4 * (2 * 6 + 3) + 1] = 0.0;
    P[4 * (2 * 6 + 3) + 3] = 1.0;
    expect_err("degree 0", c2b_nurbs_surface_create(0, 2, 7, 6, ok_u, kv, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "degree must be 1..15");
    expect_err("degree 16", c2b_nurbs_surface_create(3, 16, 7, 6, ok_u, kv, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "degree must be 1..15 (got 16 in v)");
    expect_err("too few poles", c2b_nurbs_surface_create(4, 2, 3, 6, ok_u, kv, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "degree 4 in u needs at least 5 poles, got 3");
    expect_err("too many poles", c2b_nurbs_surface_create(3, 2, 7, 200000, ok_u, kv, P, NULL, &s, &err),
               &err, C2B_ERR_LIMIT, "exceed the limit of 100000");
    double kz[9] = {0, 0, 0, 1, 1, 1, 1, 1, 1};
    double kz2[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1};
    expect_err("zero-length domain", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kz2, P, NULL, &s, &err),
               &err, C2B_ERR_SPEC, "knots_v: the domain [1, 1] has zero length");
    expect_err("multiplicity above p + 1", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kz, P, NULL, &s, &err),
               &err, C2B_ERR_SPEC, "knots_v: value 1 at index 3 has multiplicity 6, more than p + 1 = 3");
    double km[9] = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
    expect_err("interior multiplicity above p", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, km, P, NULL, &s, &err),
               &err, C2B_ERR_SPEC, "multiplicity 3, more than p (interior knot) = 2");
    double kbig[9] = {-1e308, -1e308, -1e308, 0.5, 0.6, 0.7, 1e308, 1e308, 1e308};
    expect_err("knot range overflowing", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kbig, P, NULL, &s, &err),
               &err, C2B_ERR_SPEC, "knots_v: the knot range [-1e+308, 1e+308] is too long");
    double kn[9] = {0, 0, 0, 0.5, NAN, 0.7, 1, 1, 1};
    expect_err("NaN knot", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kn, P, NULL, &s, &err), &err,
               C2B_ERR_SPEC, "knots_v[4]: not finite");
    int per[2] = {0, 1};
    double kp[6 + 4 + 1] = {-0.4, -0.2, 0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.61};
    expect_err("periodic spacing", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kp, P, per, &s, &err), &err,
               C2B_ERR_SPEC, "knots_v: not periodic: knots_v[10] - knots_v[4] = 1.21, expected the period 1.2");
    expect_err("NULL knots", c2b_nurbs_surface_create(3, 2, 7, 6, NULL, kv, P, NULL, &s, &err), &err,
               C2B_ERR_ARG, "knots_u");
    expect_err("NULL out", c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, NULL, &err), &err,
               C2B_ERR_ARG, "NULL");

    /* curves */
    double U[9] = {0, 0, 0, 0, 0.5, 0.25, 1, 1, 1};
    expect_err("curve: decreasing knots", c2b_nurbs_curve_create(3, 5, U, P, 0, &c, &err), &err,
               C2B_ERR_SPEC, "knots: decreasing at index 5 (0.25 after 0.5)");
    double U2[9] = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    P[4 * 3 + 3] = 0;
    expect_err("curve: zero weight", c2b_nurbs_curve_create(3, 5, U2, P, 0, &c, &err), &err, C2B_ERR_SPEC,
               "poles[3]: weight must be positive (got 0)");
    P[4 * 3 + 3] = 1;
    expect_err("curve: too few poles", c2b_nurbs_curve_create(4, 3, U2, P, 0, &c, &err), &err,
               C2B_ERR_SPEC, "degree 4 needs at least 5 poles, got 3");
    expect_err("curve: at path", c2b_nurbs_curve_create_at(3, 5, U, P, 0, "curves[2]", &c, &err), &err,
               C2B_ERR_SPEC, "curves[2].knots: decreasing at index 5");

    /* evaluation outside the domain and bad orders */
    c2b_nurbs_curve_create(3, 5, U2, P, 0, &c, NULL);
    double out[NDER];
    expect_err("curve: t outside the domain", c2b_nurbs_curve_eval(c, 1.5, 1, out, &err), &err,
               C2B_ERR_ARG, "parameter t = 1.5 is outside the domain [0, 1]");
    check_true("curve: t within 1e-12 of the domain end is clamped",
               c2b_nurbs_curve_eval(c, 1 + 5e-13, 1, out, NULL) == C2B_OK &&
                   c2b_nurbs_curve_eval(c, -5e-13, 1, out, NULL) == C2B_OK);
    expect_err("curve: NaN parameter", c2b_nurbs_curve_eval(c, NAN, 0, out, &err), &err, C2B_ERR_ARG,
               "not finite");
    expect_err("curve: order 7", c2b_nurbs_curve_eval(c, 0.5, 7, out, &err), &err, C2B_ERR_ARG,
               "derivative order 7");
    c2b_nurbs_surface_create(3, 2, 7, 6, ok_u, kv, P, NULL, &s, NULL);
    expect_err("surface: v outside the domain", c2b_nurbs_surface_derivs(s, 0.5, -0.25, 1, 1, out, &err),
               &err, C2B_ERR_ARG, "parameter v = -0.25 is outside the domain [0, 1]");
    expect_err("surface: order (7, 0)", c2b_nurbs_surface_derivs(s, 0.5, 0.5, 7, 0, out, &err), &err,
               C2B_ERR_ARG, "derivative orders (7, 0)");
    /* NULL-safety */
    c2b_nurbs_surface_destroy(NULL);
    c2b_nurbs_curve_destroy(NULL);
    double dom[4], pole[4];
    c2b_nurbs_surface_domain(NULL, dom);
    c2b_nurbs_surface_pole(s, 99, 0, pole);
    check_true("NULL and out-of-range accessors do not crash (NaN results)",
               isnan(dom[0]) && isnan(pole[0]) && c2b_nurbs_surface_degree(NULL, 0) == 0 &&
                   c2b_nurbs_surface_knots(s, 2) == NULL);
    expect_err("eval with NULL surface", c2b_nurbs_surface_eval(NULL, 0, 0, 0, out, &err), &err,
               C2B_ERR_ARG, "NULL");
    /* evaluation at the end of the domain uses the last non-empty span */
    double e1[3], e2[3], Pend[4];
    c2b_nurbs_curve_eval(c, 1.0, 0, e1, NULL);
    c2b_nurbs_curve_pole(c, 4, Pend);
    check_le("clamped curve: C(t1) is the last pole", dist3(e1, Pend), 0.0);
    c2b_nurbs_curve_eval(c, 0.0, 0, e2, NULL);
    c2b_nurbs_curve_pole(c, 0, Pend);
    check_le("clamped curve: C(t0) is the first pole", dist3(e2, Pend), 0.0);
    c2b_nurbs_curve_destroy(c);
    c2b_nurbs_surface_destroy(s);
}

/* ---- degenerate inputs ---------------------------------------------------------------- */

static void test_degenerate(void)
{
    rng r = {0x77ULL};
    c2b_error err;
    /* all poles at one point: projection returns that point's distance */
    double U[8] = {0, 0, 0, 0, 1, 1, 1, 1}, P[16 * 4];
    for (int i = 0; i < 16; i++) {
        P[4 * i] = 1.0;
        P[4 * i + 1] = 2.0;
        P[4 * i + 2] = 3.0;
        P[4 * i + 3] = 1.0 + 0.1 * i;
    }
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_surface_create(3, 3, 4, 4, U, U, P, NULL, &s, NULL);
    double X[3] = {1.0, 2.0, 5.0}, uv[2], d;
    c2b_status st = c2b_nurbs_surface_project(s, X, uv, &d, &err);
    check_true("surface collapsed to a point: projection succeeds", st == C2B_OK);
    check_close("... distance", d, 2.0, 1e-14, 0);
    c2b_nurbs_surface_destroy(s);
    c2b_nurbs_curve *c = NULL;
    c2b_nurbs_curve_create(3, 4, U, P, 0, &c, NULL);
    double t;
    st = c2b_nurbs_curve_project(c, X, &t, &d, &err);
    check_true("curve collapsed to a point: projection succeeds", st == C2B_OK);
    check_close("... distance", d, 2.0, 1e-14, 0);
    c2b_nurbs_curve_destroy(c);

    /* the poles of the sphere: degenerate normal */
    c2b_nurbs_surface *sph = sphere(1.5);
    double N[3] = {0, 0, 2.0}, S[3];
    st = c2b_nurbs_surface_project(sph, N, uv, &d, &err);
    c2b_nurbs_surface_eval(sph, uv[0], uv[1], 0, S, NULL);
    check_true("sphere: projection of a point above the pole succeeds", st == C2B_OK);
    check_close("... distance", d, 0.5, 1e-12, 0);
    c2b_nurbs_surface_destroy(sph);

    /* degree 15, derivatives of order 6 in both directions */
    {
        double K[32], Q[16 * 16 * 4];
        for (int i = 0; i < 16; i++) {
            K[i] = 0.0;
            K[16 + i] = 1.0;
        }
        for (int i = 0; i < 256; i++) {
            Q[4 * i] = i / 16;
            Q[4 * i + 1] = i % 16;
            Q[4 * i + 2] = rnd(&r);
            Q[4 * i + 3] = rnd_in(&r, 0.5, 2);
        }
        c2b_nurbs_surface *h = NULL;
        st = c2b_nurbs_surface_create(15, 15, 16, 16, K, K, Q, NULL, &h, &err);
        double skl[NDER];
        int ok = st == C2B_OK;
        for (int k = 0; ok && k < 20; k++) {
            ok = c2b_nurbs_surface_derivs(h, rnd(&r), rnd(&r), 6, 6, skl, &err) == C2B_OK;
            for (int i = 0; ok && i < 49 * 3; i++)
                ok = isfinite(skl[i]);
        }
        check_true("degree (15, 15): derivatives up to (6, 6) are finite", ok);
        expect_err("degree (15, 15): elevation refused", c2b_nurbs_surface_elevate(h, 0, 1, &err), &err,
                   C2B_ERR_ARG, "exceeds 15");
        c2b_nurbs_surface_destroy(h);
    }

    /* a large surface: projection keeps its grid bounded (300 x 300 poles, bicubic) */
    {
        int n = 300;
        double *K = malloc((size_t)(n + 4) * sizeof(double));
        double *Q = malloc((size_t)n * (size_t)n * 4 * sizeof(double));
        for (int i = 0; i < n + 4; i++)
            K[i] = i < 4 ? 0.0 : (i >= n ? 1.0 : (double)(i - 3) / (n - 3));
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                double *q = Q + 4 * ((size_t)i * (size_t)n + (size_t)j);
                q[0] = i;
                q[1] = j;
                q[2] = sin(0.1 * i) * cos(0.07 * j);
                q[3] = 1.0;
            }
        c2b_nurbs_surface *big = NULL;
        st = c2b_nurbs_surface_create(3, 3, n, n, K, K, Q, NULL, &big, &err);
        double Sb[9], nn[3], Xb[3];
        c2b_nurbs_surface_eval(big, 0.4321, 0.6789, 1, Sb, NULL);
        cross3(Sb + 3, Sb + 6, nn);
        for (int x = 0; x < 3; x++)
            Xb[x] = Sb[x] + 0.01 * nn[x] / norm3(nn);
        st = c2b_nurbs_surface_project(big, Xb, uv, &d, &err);
        check_true("300 x 300 surface: projection succeeds", st == C2B_OK);
        check_close("... u", uv[0], 0.4321, 0, 1e-10);
        check_close("... v", uv[1], 0.6789, 0, 1e-10);
        c2b_nurbs_surface_destroy(big);
        free(K);
        free(Q);
    }
}

/* ---- JSON ------------------------------------------------------------------------------------- */

static c2b_status parse_surface(const char *text, const char *field, c2b_nurbs_surface **s,
                                c2b_error *err)
{
    cJSON *j = cJSON_Parse(text);
    if (!j) {
        printf("FAIL (test bug) malformed test JSON: %s\n", text);
        t_failed++;
        return C2B_ERR_IO;
    }
    c2b_status st = c2b_nurbs_surface_from_json(j, field, s, err);
    cJSON_Delete(j);
    return st;
}

static int same_surface(const c2b_nurbs_surface *a, const c2b_nurbs_surface *b)
{
    for (int d = 0; d < 2; d++) {
        if (c2b_nurbs_surface_degree(a, d) != c2b_nurbs_surface_degree(b, d) ||
            c2b_nurbs_surface_npoles(a, d) != c2b_nurbs_surface_npoles(b, d) ||
            c2b_nurbs_surface_periodic(a, d) != c2b_nurbs_surface_periodic(b, d) ||
            c2b_nurbs_surface_nknots(a, d) != c2b_nurbs_surface_nknots(b, d))
            return 0;
        if (memcmp(c2b_nurbs_surface_knots(a, d), c2b_nurbs_surface_knots(b, d),
                   sizeof(double) * (size_t)c2b_nurbs_surface_nknots(a, d)))
            return 0;
    }
    for (int i = 0; i < c2b_nurbs_surface_npoles(a, 0); i++)
        for (int j = 0; j < c2b_nurbs_surface_npoles(a, 1); j++) {
            double pa[4], pb[4];
            c2b_nurbs_surface_pole(a, i, j, pa);
            c2b_nurbs_surface_pole(b, i, j, pb);
            if (memcmp(pa, pb, sizeof pa))
                return 0;
        }
    return 1;
}

static void test_json(void)
{
    rng r = {0x1f2e3d4cULL};
    c2b_error err;
    c2b_nurbs_surface *s = NULL;
    const char *F = "primaries[0].nurbs";
    const char *good =
        "{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
        " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,0.5],[2,1,1,2]],"
        " [[3,0,0,1],[3,1,0,1]]], \"periodic\": [false, false]}";
    c2b_status st = parse_surface(good, F, &s, &err);
    check_true("JSON: a valid surface reads", st == C2B_OK && s && c2b_nurbs_surface_npoles(s, 0) == 4);
    if (st)
        printf("  %s\n", err.msg);
    c2b_nurbs_surface_destroy(s);
    s = NULL;

    struct {
        const char *text, *frag;
        c2b_status code;
    } bad[] = {
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.6, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]], [[4,0,0,1],[4,1,0,1]]]}",
         "primaries[0].nurbs.knots_u: decreasing at index 4 (0.5 after 0.6)", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]]}",
         "primaries[0].nurbs.poles[2]: expected 2 rows of [x, y, z, w] (as in poles[0]), got 1", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]]}",
         "primaries[0].nurbs.poles[2][1]: expected [x, y, z, w] (4 numbers)", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,0],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]]}",
         "primaries[0].nurbs.poles[2][0]: weight must be positive (got 0)", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]], \"weights\": [1]}",
         "primaries[0].nurbs: unknown key 'weights'", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]]}",
         "primaries[0].nurbs.knots_u: 6 values given, 7 needed (n + p + 1 with n = 4 poles, p = 2)",
         C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]], \"periodic\": [true, false]}",
         "primaries[0].nurbs.knots_u: 7 values given, 9 needed (n + 2p + 1 (periodic) with n = 4 poles, p = 2)",
         C2B_ERR_SPEC},
        {"{\"degree\": [4, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]]]}",
         "primaries[0].nurbs: degree 4 in u needs at least 5 poles, got 3", C2B_ERR_SPEC},
        {"{\"degree\": [2, 0], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]]}",
         "primaries[0].nurbs: degree must be 1..15 (got 0 in v)", C2B_ERR_SPEC},
        {"{\"degree\": [2.5, 1], \"knots_u\": [0], \"knots_v\": [0], \"poles\": [[[0,0,0,1]]]}",
         "primaries[0].nurbs.degree: expected [p, q] with integers 1..15", C2B_ERR_SPEC},
        {"{\"degree\": 2, \"knots_u\": [0], \"knots_v\": [0], \"poles\": [[[0,0,0,1]]]}",
         "primaries[0].nurbs.degree: expected [p, q]", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_v\": [0, 0, 1, 1], \"poles\": [[[0,0,0,1]]]}",
         "primaries[0].nurbs: missing key 'knots_u'", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, \"a\", 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]]}",
         "primaries[0].nurbs.knots_u[3]: expected a number", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]], [[1,0,0,1],[1,1,0,1]], [[2,0,1,1],[2,1,1,1]],"
         " [[3,0,0,1],[3,1,0,1]]], \"periodic\": [1, 0]}",
         "primaries[0].nurbs.periodic: expected [bool, bool]", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": [[[0,0,0,1],[0,1,0,1]]]}",
         "primaries[0].nurbs: duplicate key 'degree'", C2B_ERR_SPEC},
        {"[1, 2]", "primaries[0].nurbs: expected an object", C2B_ERR_SPEC},
        {"{\"degree\": [2, 1], \"knots_u\": [0, 0, 0, 0.5, 1, 1, 1], \"knots_v\": [0, 0, 1, 1],"
         " \"poles\": []}",
         "primaries[0].nurbs.poles: expected rows", C2B_ERR_SPEC},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char what[64];
        snprintf(what, sizeof what, "JSON bad surface %zu", i);
        st = parse_surface(bad[i].text, F, &s, &err);
        expect_err(what, st, &err, bad[i].code, bad[i].frag);
        check_true("... no surface returned", s == NULL);
    }
    st = c2b_nurbs_surface_from_json(NULL, F, &s, &err);
    expect_err("JSON: missing object", st, &err, C2B_ERR_SPEC, "primaries[0].nurbs: missing");

    /* curves */
    cJSON *jc = cJSON_Parse("{\"degree\": 2, \"knots\": [0, 0, 0, 1, 1], \"poles\": [[0,0,0,1],[1,1,0,1]],"
                            " \"periodic\": false}");
    c2b_nurbs_curve *c = NULL;
    expect_err("JSON curve: knot count", c2b_nurbs_curve_from_json(jc, "curves[1]", &c, &err), &err,
               C2B_ERR_SPEC, "curves[1]: degree 2 needs at least 3 poles, got 2");
    cJSON_Delete(jc);
    jc = cJSON_Parse("{\"degree\": 1, \"knots\": [0, 0, 1], \"poles\": [[0,0,0,1],[1,1,0,1]]}");
    expect_err("JSON curve: knot count", c2b_nurbs_curve_from_json(jc, "curves[1]", &c, &err), &err,
               C2B_ERR_SPEC, "curves[1].knots: 3 values given, 4 needed (n + p + 1 with n = 2 poles, p = 1)");
    cJSON_Delete(jc);
    jc = cJSON_Parse("{\"degree\": 1, \"knots\": [0, 0, 1, 1], \"poles\": [[0,0,0,1],[1,1,0]]}");
    expect_err("JSON curve: pole", c2b_nurbs_curve_from_json(jc, "curves[1]", &c, &err), &err,
               C2B_ERR_SPEC, "curves[1].poles[1]: expected [x, y, z, w] (4 numbers)");
    cJSON_Delete(jc);
    jc = cJSON_Parse("[1, 2]");
    expect_err("JSON curve: not an object", c2b_nurbs_curve_from_json(jc, "curves[1]", &c, &err),
               &err, C2B_ERR_SPEC,
               "curves[1]: expected an object {\"degree\": p, \"knots\": [...], \"poles\": "
               "[[x, y, z, w], ...]}");
    cJSON_Delete(jc);
    expect_err("JSON curve: missing", c2b_nurbs_curve_from_json(NULL, "curves[1]", &c, &err), &err,
               C2B_ERR_SPEC, "curves[1]: missing");
    jc = cJSON_Parse("{\"degree\": 1, \"poles\": [[0,0,0,1],[1,1,0,1]]}");
    expect_err("JSON curve: missing knots", c2b_nurbs_curve_from_json(jc, "curves[1]", &c, &err),
               &err, C2B_ERR_SPEC, "curves[1]: missing key 'knots'");
    cJSON_Delete(jc);
    jc = cJSON_Parse("{\"degree\": 1, \"knots\": [0, 0, 1, 1], \"poles\": [[0,0,0,1],[1,1,0,1]],"
                     " \"knot\": 2}");
    expect_err("JSON curve: unknown key", c2b_nurbs_curve_from_json(jc, "curves[1]", &c, &err),
               &err, C2B_ERR_SPEC,
               "curves[1]: unknown key 'knot' (allowed: degree, knots, poles, periodic)");
    cJSON_Delete(jc);

    /* round trips: random full-precision values, a periodic surface, a surface made by
     * knot insertion, through memory and through printed text */
    for (int trial = 0; trial < 4; trial++) {
        c2b_nurbs_surface *a = NULL;
        if (trial < 2) {
            a = random_surface(&r, 3, 2, 6, 5, 1, 2);
            if (trial == 1) {
                double dom[4];
                c2b_nurbs_surface_domain(a, dom);
                c2b_nurbs_surface_insert_knot(a, 0, rnd_in(&r, dom[0], dom[1]), 2, NULL);
                c2b_nurbs_surface_elevate(a, 1, 1, NULL);
            }
        } else {
            double U[4 + 2 * 2 + 1], sp[4] = {0.1, 0.7 / 3, 0.3, 1.0 / 7}, V[6] = {0, 0, 0, 1, 1, 1};
            periodic_knots(2, 4, 0.1, sp, U);
            double P[4 * 3 * 4];
            for (int i = 0; i < 12; i++) {
                P[4 * i] = rnd_in(&r, -1e3, 1e3);
                P[4 * i + 1] = trial == 3 ? -0.0 : rnd_in(&r, -1e-9, 1e-9);
                P[4 * i + 2] = rnd(&r) / 3;
                P[4 * i + 3] = rnd_in(&r, 0.5, 2);
            }
            int per[2] = {1, 0};
            c2b_nurbs_surface_create(2, 2, 4, 3, U, V, P, per, &a, NULL);
        }
        cJSON *j = c2b_nurbs_surface_to_json(a);
        c2b_nurbs_surface *b = NULL, *b2 = NULL;
        st = c2b_nurbs_surface_from_json(j, "x", &b, &err);
        size_t need = c2b_nurbs_json_print(j, trial % 2, NULL, 0);
        char *text = malloc(need + 1);
        c2b_nurbs_json_print(j, trial % 2, text, need + 1);
        cJSON *j2 = cJSON_Parse(text);
        c2b_status st2 = c2b_nurbs_surface_from_json(j2, "x", &b2, &err);
        char what[96];
        snprintf(what, sizeof what, "JSON round trip %d: in memory, bit for bit", trial);
        check_true(what, st == C2B_OK && same_surface(a, b));
        snprintf(what, sizeof what, "JSON round trip %d: through c2b_nurbs_json_print text, bit for bit",
                 trial);
        check_true(what, st2 == C2B_OK && same_surface(a, b2));
        if (trial == 3) {
            double pole[4];
            c2b_nurbs_surface_pole(b2, 1, 1, pole);
            check_true("JSON: -0 is stored as +0", pole[1] == 0.0 && !signbit(pole[1]));
        }
        double S1[30], S2[30];
        c2b_nurbs_surface_eval(a, 0.3, 0.4, 3, S1, NULL);
        c2b_nurbs_surface_eval(b2, 0.3, 0.4, 3, S2, NULL);
        check_true("... and evaluates identically", memcmp(S1, S2, sizeof S1) == 0);
        free(text);
        cJSON_Delete(j);
        cJSON_Delete(j2);
        c2b_nurbs_surface_destroy(a);
        c2b_nurbs_surface_destroy(b);
        c2b_nurbs_surface_destroy(b2);
    }
    {
        c2b_nurbs_curve *a = random_curve(&r, 4, 9, 1, 3), *b = NULL;
        c2b_nurbs_curve_insert_knot(a, 2.1, 3, NULL);
        cJSON *j = c2b_nurbs_curve_to_json(a);
        char text[8192];
        size_t need = c2b_nurbs_json_print(j, 0, text, sizeof text);
        cJSON *j2 = need < sizeof text ? cJSON_Parse(text) : NULL;
        st = c2b_nurbs_curve_from_json(j2, "c", &b, &err);
        int same = st == C2B_OK && c2b_nurbs_curve_npoles(a) == c2b_nurbs_curve_npoles(b) &&
                   c2b_nurbs_curve_nknots(a) == c2b_nurbs_curve_nknots(b) &&
                   !memcmp(c2b_nurbs_curve_knots(a), c2b_nurbs_curve_knots(b),
                           sizeof(double) * (size_t)c2b_nurbs_curve_nknots(a));
        for (int i = 0; same && i < c2b_nurbs_curve_npoles(a); i++) {
            double pa[4], pb[4];
            c2b_nurbs_curve_pole(a, i, pa);
            c2b_nurbs_curve_pole(b, i, pb);
            same = !memcmp(pa, pb, sizeof pa);
        }
        check_true("JSON curve round trip through text, bit for bit", same);
        cJSON_Delete(j);
        cJSON_Delete(j2);
        c2b_nurbs_curve_destroy(a);
        c2b_nurbs_curve_destroy(b);
    }
}

/* ---- high orders ------------------------------------------------------------------------- */

/* A polynomial (w = 1) Bezier surface of degrees (6, 6) reproduces u^6 v^6 exactly after
 * being written in the Bernstein basis: d^6/du^6 = 720 v^6 etc. Poles of x = u^a v^b:
 * B-coefficients C(i, a) / C(6, a) * C(j, b) / C(6, b). */
static void test_high_order(void)
{
    double U[14] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1}, P[7 * 7 * 4];
    double bin[7][7];
    for (int n = 0; n <= 6; n++) {
        bin[n][0] = bin[n][n] = 1;
        for (int k = 1; k < n; k++)
            bin[n][k] = bin[n - 1][k - 1] + bin[n - 1][k];
    }
    for (int i = 0; i <= 6; i++)
        for (int j = 0; j <= 6; j++) {
            double *Q = P + 4 * (i * 7 + j);
            Q[0] = (i >= 6 ? 1.0 : 0.0) * (j >= 6 ? 1.0 : 0.0);            /* u^6 v^6 */
            Q[1] = (i >= 3 ? bin[i][3] / bin[6][3] : 0) * (j >= 2 ? bin[j][2] / bin[6][2] : 0); /* u^3 v^2 */
            Q[2] = i / 6.0;                                                    /* u */
            Q[3] = 1.0;
        }
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_surface_create(6, 6, 7, 7, U, U, P, NULL, &s, NULL);
    double skl[NDER], worst = 0.0;
    double f[7][7];
    for (int k = 0; k < 20; k++) {
        double u = k / 19.0, v = 1 - k / 23.0;
        c2b_nurbs_surface_derivs(s, u, v, 6, 6, skl, NULL);
        for (int a = 0; a <= 6; a++)
            for (int b = 0; b <= 6; b++) {
                double fa6 = 1, fb6 = 1, fa3 = 1, fb2 = 1;
                for (int i = 0; i < a; i++) {
                    fa6 *= 6 - i;
                    fa3 *= 3 - i;
                }
                for (int i = 0; i < b; i++) {
                    fb6 *= 6 - i;
                    fb2 *= 2 - i;
                }
                f[a][b] = fa6 * pow(u, 6 - a) * fb6 * pow(v, 6 - b);
                double y = (a <= 3 && b <= 2) ? fa3 * pow(u, 3 - a) * fb2 * pow(v, 2 - b) : 0.0;
                double z = (b == 0) ? (a == 0 ? u : (a == 1 ? 1.0 : 0.0)) : 0.0;
                /* rounding model: sum_i |B_i^(a)| <= 2^a 6! / (6 - a)! per direction */
                double model = 1e-16 * pow(2, a + b) * fa6 * fb6;
                const double *D = skl + 3 * (a * 7 + b);
                worst = fmax(worst, fabs(D[0] - f[a][b]) / model);
                worst = fmax(worst, fabs(D[1] - y) / model);
                worst = fmax(worst, fabs(D[2] - z) / model);
            }
    }
    check_le("degree (6, 6) polynomial: all SKL up to (6, 6) exact, error / (eps 2^(a+b) 6!/(6-a)! 6!/(6-b)!)",
             worst, 10.0);
    c2b_nurbs_surface_destroy(s);
}

int main(void)
{
    test_partition_of_unity();
    test_circle();
    test_cylinder_sphere();
    test_insert_elevate();
    test_projection();
    test_periodic();
    test_bad_input();
    test_degenerate();
    test_json();
    test_high_order();
    return test_summary("test_nurbs");
}
