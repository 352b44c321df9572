/*
 * Curvature module tests. Every derivative block is written out by hand from an analytic
 * parametrisation (sphere, cylinder, torus, plane, z = uv, monkey saddle, cone) and the
 * results are compared with the closed-form curvatures of those surfaces, over model
 * scales from 1e-6 to 1e6 (and 1e+-70 for the exact power-of-two rescaling). Errors are
 * measured relative to the curvature scale kappa = max(|k1|, |k2|) of the exact answer.
 */
#include <math.h>
#include <string.h>

#include "c2b_constants.h"
#include "c2b_curv.h"
#include "test_util.h"

/* Tolerances of the exact checks, relative to the curvature scale (a few hundred ulp).
 * The shear u = s + 40 t leaves S_s and S_t about 0.5 degrees apart; rounding the input
 * S_tt = 1600 Suu + ... alone moves the curvatures by ~ eps / sin^2(angle) ~ 3e-12, so the
 * sheared checks get the conditioning-limited TOL_SHEAR (measured: 1e-15 for shear 0.7,
 * 1e-14 for -3, 3e-12 for 40). */
#define TOL 1e-13
#define TOL_SHEAR 1e-11

static void set3(double *d, int entry, double x, double y, double z)
{
    d[entry * 3] = x;
    d[entry * 3 + 1] = y;
    d[entry * 3 + 2] = z;
}

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm(const double *a)
{
    return sqrt(dot(a, a));
}

/* sine of the angle between the lines spanned by a and b */
static double line_err(const double *a, const double *b)
{
    double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    return norm(c) / (norm(a) * norm(b));
}

static void track(double *mx, double e)
{
    if (!(e <= *mx))
        *mx = e; /* NaN propagates into the maximum */
}

/* ---- analytic surfaces and their hand-written partial derivatives ---------------- */

/* Sphere x = R cos u cos v, y = R sin u cos v, z = R sin v (normal outward). */
static void sphere(double R, double u, double v, double *d)
{
    double cu = cos(u), su = sin(u), cv = cos(v), sv = sin(v);
    set3(d, 0, R * cu * cv, R * su * cv, R * sv);
    set3(d, 1, -R * su * cv, R * cu * cv, 0);
    set3(d, 2, -R * cu * sv, -R * su * sv, R * cv);
    set3(d, 3, -R * cu * cv, -R * su * cv, 0);
    set3(d, 4, R * su * sv, -R * cu * sv, 0);
    set3(d, 5, -R * cu * cv, -R * su * cv, -R * sv);
}

/* The pole v = pi/2 of the sphere with cos v = 0 and sin v = 1 exactly: Su = 0. */
static void sphere_pole_exact(double R, double u, double *d)
{
    double cu = cos(u), su = sin(u);
    set3(d, 0, 0, 0, R);
    set3(d, 1, 0, 0, 0);
    set3(d, 2, -R * cu, -R * su, 0);
    set3(d, 3, 0, 0, 0);
    set3(d, 4, R * su, -R * cu, 0);
    set3(d, 5, 0, 0, -R);
}

/* Exchange the roles of u and v: the normal flips. */
static void swap_uv(double *d)
{
    double t[3];
    memcpy(t, d + 3, sizeof t);
    memcpy(d + 3, d + 6, sizeof t);
    memcpy(d + 6, t, sizeof t);
    memcpy(t, d + 9, sizeof t);
    memcpy(d + 9, d + 15, sizeof t);
    memcpy(d + 15, t, sizeof t);
}

/* Reparametrise by u = s + alpha t, v = t (chain rule); the geometry is unchanged,
 * F becomes non-zero and the orientation is kept. */
static void shear(double *d, double alpha)
{
    for (int k = 0; k < 3; k++) {
        double su = d[3 + k], sv = d[6 + k], suu = d[9 + k], suv = d[12 + k], svv = d[15 + k];
        d[6 + k] = alpha * su + sv;
        d[12 + k] = alpha * suu + suv;
        d[15 + k] = alpha * alpha * suu + 2 * alpha * suv + svv;
    }
}

/* Cylinder x = R cos u, y = R sin u, z = v (normal outward). */
static void cylinder(double R, double u, double v, double *d)
{
    double cu = cos(u), su = sin(u);
    set3(d, 0, R * cu, R * su, v);
    set3(d, 1, -R * su, R * cu, 0);
    set3(d, 2, 0, 0, 1);
    set3(d, 3, -R * cu, -R * su, 0);
    set3(d, 4, 0, 0, 0);
    set3(d, 5, 0, 0, 0);
}

/* Torus x = (R + r cos v) cos u, y = (R + r cos v) sin u, z = r sin v (normal outward). */
static void torus(double R, double r, double u, double v, double *d)
{
    double cu = cos(u), su = sin(u), cv = cos(v), sv = sin(v), rho = R + r * cv;
    set3(d, 0, rho * cu, rho * su, r * sv);
    set3(d, 1, -rho * su, rho * cu, 0);
    set3(d, 2, -r * sv * cu, -r * sv * su, r * cv);
    set3(d, 3, -rho * cu, -rho * su, 0);
    set3(d, 4, r * sv * su, -r * sv * cu, 0);
    set3(d, 5, -r * cv * cu, -r * cv * su, -r * sv);
}

/* Monge patch S = (u, v, f(u, v)) from f's derivatives. */
static void monge(double u, double v, double f, double fu, double fv, double fuu, double fuv,
                  double fvv, double *d)
{
    set3(d, 0, u, v, f);
    set3(d, 1, 1, 0, fu);
    set3(d, 2, 0, 1, fv);
    set3(d, 3, 0, 0, fuu);
    set3(d, 4, 0, 0, fuv);
    set3(d, 5, 0, 0, fvv);
}

/* Hyperbolic paraboloid z = u v. */
static void saddle(double u, double v, double *d)
{
    monge(u, v, u * v, v, u, 0, 1, 0, d);
}

/* Monkey saddle z = u^3 - 3 u v^2. */
static void monkey(double u, double v, double *d)
{
    monge(u, v, u * u * u - 3 * u * v * v, 3 * u * u - 3 * v * v, -6 * u * v, 6 * u, -6 * v, -6 * u, d);
}

/* Exact K and H of a Monge patch (normal (-fu, -fv, 1) / sqrt(W), W = 1 + fu^2 + fv^2). */
static void monge_exact(double fu, double fv, double fuu, double fuv, double fvv, double *K, double *H)
{
    double W = 1 + fu * fu + fv * fv;
    *K = (fuu * fvv - fuv * fuv) / (W * W);
    *H = ((1 + fu * fu) * fvv - 2 * fu * fv * fuv + (1 + fv * fv) * fuu) / (2 * W * sqrt(W));
}

/* Cone x = u cos v, y = u sin v, z = u; apex at u = 0. */
static void cone(double u, double v, double *d)
{
    double cv = cos(v), sv = sin(v);
    set3(d, 0, u * cv, u * sv, u);
    set3(d, 1, cv, sv, 1);
    set3(d, 2, -u * sv, u * cv, 0);
    set3(d, 3, 0, 0, 0);
    set3(d, 4, -sv, cv, 0);
    set3(d, 5, -u * cv, -u * sv, 0);
}

/* ---- generic checks ---------------------------------------------------------------- */

/* Frame errors: |dir|-1, dir.n, dir1.dir2, (dir1 x dir2).n - 1, |n| - 1, n.Su, n.Sv. */
static double frame_err(const c2b_curv_point *p, const double *d)
{
    double c[3] = {p->dir1[1] * p->dir2[2] - p->dir1[2] * p->dir2[1],
                   p->dir1[2] * p->dir2[0] - p->dir1[0] * p->dir2[2],
                   p->dir1[0] * p->dir2[1] - p->dir1[1] * p->dir2[0]};
    double e = 0;
    track(&e, fabs(norm(p->dir1) - 1));
    track(&e, fabs(norm(p->dir2) - 1));
    track(&e, fabs(norm(p->normal) - 1));
    track(&e, fabs(dot(p->dir1, p->normal)));
    track(&e, fabs(dot(p->dir2, p->normal)));
    track(&e, fabs(dot(p->dir1, p->dir2)));
    track(&e, fabs(dot(c, p->normal) - 1));
    track(&e, fabs(dot(p->normal, d + 3)) / norm(d + 3));
    track(&e, fabs(dot(p->normal, d + 6)) / norm(d + 6));
    return e;
}

/* Invariant errors against exact (K, H, k1, k2), relative to kappa. */
static double invariant_err(const c2b_curv_point *p, double K, double H, double k1, double k2)
{
    double kap = fmax(fabs(k1), fabs(k2));
    double e = 0;
    track(&e, fabs(p->K - K) / (kap * kap));
    track(&e, fabs(p->H - H) / kap);
    track(&e, fabs(p->k1 - k1) / kap);
    track(&e, fabs(p->k2 - k2) / kap);
    track(&e, p->k1 >= p->k2 ? 0 : INFINITY);
    return e;
}

/* Euler's theorem and the 3-D variant in several parameter directions. */
static double euler_err(const double *d, const c2b_curv_point *p)
{
    double kap = fmax(fabs(p->k1), fabs(p->k2));
    double e = 0;
    for (int i = 0; i < 7; i++) {
        double phi = 0.45 * i + 0.1, a = cos(phi), b = sin(phi);
        double t[3], tn[3];
        for (int k = 0; k < 3; k++)
            t[k] = a * d[3 + k] + b * d[6 + k];
        double c = dot(t, p->dir1) / norm(t), s = dot(t, p->dir2) / norm(t);
        double want = p->k1 * c * c + p->k2 * s * s;
        track(&e, fabs(c2b_curv_normal_curvature(p, a, b) - want) / kap);
        /* the same direction, scaled and tilted out of the tangent plane */
        for (int k = 0; k < 3; k++)
            tn[k] = 3.0 * t[k] / norm(t) + 5.0 * p->normal[k];
        double kn = NAN;
        c2b_status st = c2b_curv_normal_curvature_3d(d, p, tn, &kn, NULL);
        track(&e, st == C2B_OK ? fabs(kn - want) / kap : INFINITY);
    }
    return e;
}

static int eval_ok(const char *what, const double *d, c2b_curv_point *p)
{
    c2b_error err;
    c2b_error_clear(&err);
    c2b_status st = c2b_curv_eval(d, 0, p, &err);
    if (st != C2B_OK) {
        printf("     %s: %s\n", what, err.msg);
        return check_true(what, 0);
    }
    return 1;
}

/* ---- surfaces ------------------------------------------------------------------------ */

static const double SCALES[] = {1e-6, 1.0, 1e6};
#define NSCALES (int)(sizeof SCALES / sizeof *SCALES)

static void test_sphere(void)
{
    static const double US[] = {0.3, 2.1, -1.2, 4.0};
    static const double VS[] = {-1.1, 0.0, 0.4, 1.3, 1.5};
    double extra[] = {1e-70, 1e70};
    for (int s = 0; s < NSCALES + 2; s++) {
        double R = s < NSCALES ? SCALES[s] : extra[s - NSCALES];
        double inv = 0, frm = 0, nrm = 0, umb = 0, ffe = 0, eul = 0, flip = 0;
        for (size_t i = 0; i < sizeof US / sizeof *US; i++)
            for (size_t j = 0; j < sizeof VS / sizeof *VS; j++) {
                double d[18];
                c2b_curv_point p;
                sphere(R, US[i], VS[j], d);
                if (!eval_ok("sphere", d, &p))
                    continue;
                track(&inv, invariant_err(&p, 1 / (R * R), -1 / R, -1 / R, -1 / R));
                track(&frm, frame_err(&p, d));
                /* outward normal = S / R */
                for (int k = 0; k < 3; k++)
                    track(&nrm, fabs(p.normal[k] - d[k] / R));
                /* umbilic: dir1 = Su / |Su| */
                track(&umb, line_err(p.dir1, d + 3) + fabs(dot(p.dir1, d + 3) / norm(d + 3) - 1));
                double cv = cos(VS[j]);
                track(&ffe, fabs(p.E - R * R * cv * cv) / (R * R) + fabs(p.F) / (R * R) +
                                fabs(p.G - R * R) / (R * R) +
                                fabs(p.metric_det - pow(R, 4) * cv * cv) / pow(R, 4));
                track(&eul, euler_err(d, &p));
                /* swapped parametrisation: inward normal, H = +1/R, K unchanged */
                swap_uv(d);
                if (!eval_ok("sphere swapped", d, &p))
                    continue;
                track(&flip, invariant_err(&p, 1 / (R * R), 1 / R, 1 / R, 1 / R));
                for (int k = 0; k < 3; k++)
                    track(&flip, fabs(p.normal[k] + d[k] / R));
            }
        char w[128];
        snprintf(w, sizeof w, "sphere R=%g: K, H, k1, k2 (outward, H=-1/R) rel err", R);
        check_le(w, inv, TOL);
        snprintf(w, sizeof w, "sphere R=%g: swapped u,v gives H=+1/R, inward normal", R);
        check_le(w, flip, TOL);
        snprintf(w, sizeof w, "sphere R=%g: normal = S/R", R);
        check_le(w, nrm, TOL);
        snprintf(w, sizeof w, "sphere R=%g: directions orthonormal, tangent, right-handed", R);
        check_le(w, frm, TOL);
        snprintf(w, sizeof w, "sphere R=%g: umbilic dir1 = Su/|Su|", R);
        check_le(w, umb, TOL);
        snprintf(w, sizeof w, "sphere R=%g: E, F, G, EG-F^2 rel err", R);
        check_le(w, ffe, TOL);
        snprintf(w, sizeof w, "sphere R=%g: normal curvature = -1/R in every direction", R);
        check_le(w, eul, TOL);
    }
}

static void test_cylinder(void)
{
    static const double US[] = {0.0, 0.8, 2.5, -2.0};
    for (int s = 0; s < NSCALES; s++) {
        double R = SCALES[s], inv = 0, dir = 0, frm = 0, eul = 0;
        for (size_t i = 0; i < sizeof US / sizeof *US; i++) {
            double d[18], axis[3] = {0, 0, 1}, circ[3] = {-sin(US[i]), cos(US[i]), 0};
            c2b_curv_point p;
            cylinder(R, US[i], 0.3 * R, d);
            if (!eval_ok("cylinder", d, &p))
                continue;
            /* outward normal: k along the circle is -1/R, along the axis 0 */
            track(&inv, invariant_err(&p, 0, -0.5 / R, 0, -1 / R));
            track(&dir, line_err(p.dir1, axis));
            track(&dir, line_err(p.dir2, circ));
            track(&frm, frame_err(&p, d));
            track(&eul, euler_err(d, &p));
        }
        char w[128];
        snprintf(w, sizeof w, "cylinder R=%g: K=0, H=-1/(2R), (k1,k2)=(0,-1/R) rel err", R);
        check_le(w, inv, TOL);
        snprintf(w, sizeof w, "cylinder R=%g: dir1 along the axis, dir2 along the circle", R);
        check_le(w, dir, TOL);
        snprintf(w, sizeof w, "cylinder R=%g: frame", R);
        check_le(w, frm, TOL);
        snprintf(w, sizeof w, "cylinder R=%g: Euler's formula", R);
        check_le(w, eul, TOL);
    }
}

static void test_torus(void)
{
    static const double RR[][2] = {{3, 1}, {1, 0.25}, {2, 1.5}};
    static const double US[] = {0.0, 0.7, 2.5};
    static const double VS[] = {0.0, 0.9, C2B_PI / 2, 2.2, C2B_PI, 4.0, 5.5};
    static const double ALPHA[] = {0.7, -3.0, 40.0};
    for (int s = 0; s < NSCALES; s++) {
        double inv = 0, dir = 0, frm = 0, eul = 0, sh_inv = 0, sh_dir = 0, sh_eul = 0;
        for (size_t g = 0; g < sizeof RR / sizeof *RR; g++) {
            double R = RR[g][0] * SCALES[s], r = RR[g][1] * SCALES[s];
            for (size_t i = 0; i < sizeof US / sizeof *US; i++)
                for (size_t j = 0; j < sizeof VS / sizeof *VS; j++) {
                    double v = VS[j], cv = cos(v), rho = R + r * cv, d[18], d0[18];
                    c2b_curv_point p;
                    torus(R, r, US[i], v, d);
                    memcpy(d0, d, sizeof d);
                    if (!eval_ok("torus", d, &p))
                        continue;
                    /* outward normal: k = -cos v/rho along the parallel (Su), -1/r along
                     * the meridian (Sv); -cos v/rho > -1/r always */
                    double K = cv / (r * rho), k1 = -cv / rho, k2 = -1 / r;
                    track(&inv, invariant_err(&p, K, 0.5 * (k1 + k2), k1, k2));
                    track(&dir, line_err(p.dir1, d + 3));
                    track(&dir, line_err(p.dir2, d + 6));
                    track(&frm, frame_err(&p, d));
                    track(&eul, euler_err(d, &p));
                    for (size_t a = 0; a < sizeof ALPHA / sizeof *ALPHA; a++) {
                        memcpy(d, d0, sizeof d);
                        shear(d, ALPHA[a]);
                        if (!eval_ok("sheared torus", d, &p))
                            continue;
                        track(&sh_inv, invariant_err(&p, K, 0.5 * (k1 + k2), k1, k2));
                        track(&sh_dir, line_err(p.dir1, d0 + 3));
                        track(&sh_dir, line_err(p.dir2, d0 + 6));
                        track(&sh_dir, frame_err(&p, d));
                        track(&sh_eul, euler_err(d, &p));
                    }
                }
        }
        char w[160];
        snprintf(w, sizeof w, "torus x%g: K = cos v/(r(R + r cos v)), k = {-cos v/rho, -1/r} rel err",
                 SCALES[s]);
        check_le(w, inv, TOL);
        snprintf(w, sizeof w, "torus x%g: dir1 along Su (parallel), dir2 along Sv (meridian)", SCALES[s]);
        check_le(w, dir, TOL);
        snprintf(w, sizeof w, "torus x%g: frame", SCALES[s]);
        check_le(w, frm, TOL);
        snprintf(w, sizeof w, "torus x%g: Euler's formula, 2-D and 3-D", SCALES[s]);
        check_le(w, eul, TOL);
        snprintf(w, sizeof w, "sheared torus (F != 0) x%g: invariants", SCALES[s]);
        check_le(w, sh_inv, TOL_SHEAR);
        snprintf(w, sizeof w, "sheared torus x%g: same principal directions, frame", SCALES[s]);
        check_le(w, sh_dir, TOL_SHEAR);
        snprintf(w, sizeof w, "sheared torus x%g: Euler's formula", SCALES[s]);
        check_le(w, sh_eul, TOL_SHEAR);
    }
}

static void test_plane(void)
{
    double A[3] = {1, 0.5, -0.2}, B[3] = {0.3, 2, 1};
    for (int s = 0; s < NSCALES; s++) {
        double L = SCALES[s], d[18] = {0}, n[3];
        set3(d, 0, L, 2 * L, 3 * L);
        set3(d, 1, L * A[0], L * A[1], L * A[2]);
        set3(d, 2, L * B[0], L * B[1], L * B[2]);
        n[0] = A[1] * B[2] - A[2] * B[1];
        n[1] = A[2] * B[0] - A[0] * B[2];
        n[2] = A[0] * B[1] - A[1] * B[0];
        c2b_curv_point p;
        if (!eval_ok("plane", d, &p))
            continue;
        char w[128];
        snprintf(w, sizeof w, "plane x%g: K = H = k1 = k2 = 0 exactly", L);
        check_true(w, p.K == 0 && p.H == 0 && p.k1 == 0 && p.k2 == 0 && p.L == 0 && p.M == 0 && p.N == 0);
        snprintf(w, sizeof w, "plane x%g: normal along A x B", L);
        check_le(w, line_err(p.normal, n) + fabs(dot(p.normal, n) / norm(n) - 1), TOL);
        snprintf(w, sizeof w, "plane x%g: flat point, dir1 = Su/|Su|, frame", L);
        check_le(w, line_err(p.dir1, A) + fabs(dot(p.dir1, A) / norm(A) - 1) + frame_err(&p, d), TOL);
        snprintf(w, sizeof w, "plane x%g: normal curvature 0", L);
        check_true(w, c2b_curv_normal_curvature(&p, 0.3, -2) == 0);
    }
}

static void test_saddles(void)
{
    double d[18];
    c2b_curv_point p;
    /* z = uv at the origin: K = -1, H = 0, k = +-1 along (1, +-1, 0)/sqrt 2 */
    saddle(0, 0, d);
    if (eval_ok("z=uv origin", d, &p)) {
        double dp[3] = {1, 1, 0}, dm[3] = {1, -1, 0};
        check_close("z=uv origin: K", p.K, -1, 0, 1e-15);
        check_close("z=uv origin: H", p.H, 0, 0, 1e-15);
        check_close("z=uv origin: k1", p.k1, 1, 0, 1e-15);
        check_close("z=uv origin: k2", p.k2, -1, 0, 1e-15);
        check_le("z=uv origin: dir1 along (1,1,0), dir2 along (1,-1,0)",
                 line_err(p.dir1, dp) + line_err(p.dir2, dm), 1e-15);
        check_le("z=uv origin: frame", frame_err(&p, d), 1e-15);
        check_close("z=uv origin: normal curvature along u is 0", c2b_curv_normal_curvature(&p, 1, 0), 0, 0,
                    1e-15);
        check_close("z=uv origin: normal curvature along (1,1) is 1", c2b_curv_normal_curvature(&p, 2, 2), 1,
                    1e-15, 0);
    }
    /* off the origin (F = uv != 0) against the Monge formulas */
    static const double P[][2] = {{0.5, -0.3}, {1.2, 2.0}, {-3, 0.1}, {1e-3, 2e-3}};
    double inv = 0, frm = 0, eul = 0, minv = 0, mfrm = 0, meul = 0;
    for (size_t i = 0; i < sizeof P / sizeof *P; i++) {
        double u = P[i][0], v = P[i][1], K, H;
        saddle(u, v, d);
        monge_exact(v, u, 0, 1, 0, &K, &H);
        if (eval_ok("z=uv", d, &p)) {
            double rt = sqrt(H * H - K);
            track(&inv, invariant_err(&p, K, H, H + rt, H - rt));
            track(&frm, frame_err(&p, d));
            track(&eul, euler_err(d, &p));
        }
        monkey(u, v, d);
        monge_exact(3 * u * u - 3 * v * v, -6 * u * v, 6 * u, -6 * v, -6 * u, &K, &H);
        if (eval_ok("monkey saddle", d, &p)) {
            double rt = sqrt(fmax(H * H - K, 0));
            track(&minv, invariant_err(&p, K, H, H + rt, H - rt));
            track(&mfrm, frame_err(&p, d));
            track(&meul, euler_err(d, &p));
        }
    }
    check_le("z=uv off origin: K, H, k1, k2 vs Monge formulas", inv, TOL);
    check_le("z=uv off origin: frame", frm, TOL);
    check_le("z=uv off origin: Euler's formula", eul, TOL);
    check_le("monkey saddle off origin: K, H, k1, k2 vs Monge formulas", minv, TOL);
    check_le("monkey saddle off origin: frame", mfrm, TOL);
    check_le("monkey saddle off origin: Euler's formula", meul, TOL);
    /* monkey saddle origin: flat umbilic */
    monkey(0, 0, d);
    if (eval_ok("monkey origin", d, &p)) {
        double ex[3] = {1, 0, 0};
        check_true("monkey saddle origin: K = H = k1 = k2 = 0", p.K == 0 && p.H == 0 && p.k1 == 0 && p.k2 == 0);
        check_le("monkey saddle origin: dir1 = Su/|Su| = (1,0,0)", line_err(p.dir1, ex) + frame_err(&p, d),
                 1e-15);
    }
}

/* ---- failures ------------------------------------------------------------------------ */

static int has(const c2b_error *e, const char *s)
{
    return strstr(e->msg, s) != NULL;
}

static void expect_numeric(const char *what, const double *d, double tol_rel, const char *fragment)
{
    c2b_curv_point p;
    c2b_error err;
    c2b_error_clear(&err);
    p.K = 42;
    c2b_status st = c2b_curv_eval(d, tol_rel, &p, &err);
    printf("     %s -> %s: %s\n", what, c2b_status_name(st), err.msg);
    char w[200];
    snprintf(w, sizeof w, "%s: C2B_ERR_NUMERIC, message has '%s', output untouched", what, fragment);
    check_true(w, st == C2B_ERR_NUMERIC && err.code == C2B_ERR_NUMERIC && has(&err, fragment) && p.K == 42);
}

static void test_degenerate(void)
{
    double d[18];
    cone(0, 0.7, d);
    expect_numeric("cone apex", d, 0, "Sv vanishes");
    sphere_pole_exact(1, 0.4, d);
    expect_numeric("sphere pole (exact cos v = 0)", d, 0, "Su vanishes");
    sphere(2, 0.4, C2B_PI / 2, d);
    expect_numeric("sphere pole (v = pi/2 in floating point)", d, 0, "Su vanishes relative to Sv");
    swap_uv(d);
    expect_numeric("sphere pole, swapped", d, 0, "Sv vanishes relative to Su");

    /* parallel and nearly parallel tangents */
    memset(d, 0, sizeof d);
    set3(d, 1, 1, 2, 3);
    set3(d, 2, 2, 4, 6);
    set3(d, 3, 0, 0, 1);
    expect_numeric("parallel Su, Sv", d, 0, "Su x Sv vanishes (EG-F^2 = 0");
    set3(d, 1, 1, 0, 0);
    set3(d, 2, 1, 1e-10, 0);
    expect_numeric("nearly parallel Su, Sv (sin^2 = 1e-20)", d, 0, "relative 1e-20");
    {
        c2b_curv_point p;
        c2b_status st = c2b_curv_eval(d, 1e-30, &p, NULL);
        check_true("nearly parallel Su, Sv accepted with tol_rel = 1e-30", st == C2B_OK && isfinite(p.K));
        expect_numeric("nearly parallel, tol_rel = 1e-19", d, 1e-19, "tol_rel 1e-19");
    }

    /* non-finite input and overflowing results */
    sphere(1, 0.3, 0.2, d);
    d[10] = NAN;
    expect_numeric("NaN in Suu.y", d, 0, "non-finite input: d[10] (Suu.y)");
    sphere(1, 0.3, 0.2, d);
    d[0] = INFINITY;
    expect_numeric("inf in S.x", d, 0, "d[0] (S.x)");
    sphere(1, 0.3, 0.2, d);
    for (int i = 3; i < 9; i++)
        d[i] *= 1e-200;
    for (int i = 9; i < 18; i++)
        d[i] *= 1e200;
    expect_numeric("curvature beyond the double range", d, 0, "non-finite result");
    sphere(1e200, 0.3, 0.2, d);
    expect_numeric("metric EG-F^2 = 1e800 beyond the double range", d, 0, "non-finite result: E");

    /* argument errors */
    c2b_curv_point p;
    c2b_error err;
    sphere(1, 0.3, 0.2, d);
    check_true("NULL d -> C2B_ERR_ARG", c2b_curv_eval(NULL, 0, &p, &err) == C2B_ERR_ARG && has(&err, "d is NULL"));
    check_true("NULL out -> C2B_ERR_ARG", c2b_curv_eval(d, 0, NULL, &err) == C2B_ERR_ARG);
    check_true("tol_rel = 2 -> C2B_ERR_ARG", c2b_curv_eval(d, 2, &p, &err) == C2B_ERR_ARG && has(&err, "tol_rel"));
    check_true("NULL err accepted", c2b_curv_eval(NULL, 0, &p, NULL) == C2B_ERR_ARG);
    check_true("tol_rel = NaN selects the default", c2b_curv_eval(d, NAN, &p, NULL) == C2B_OK);

    /* normal curvature failure modes */
    if (eval_ok("sphere", d, &p)) {
        double kn = 42, t0[3] = {0, 0, 0}, tnan[3] = {1, NAN, 0};
        double tnear[3] = {p.normal[0] + 1e-10 * p.dir1[0], p.normal[1] + 1e-10 * p.dir1[1],
                           p.normal[2] + 1e-10 * p.dir1[2]};
        c2b_status st = c2b_curv_normal_curvature_3d(d, &p, p.normal, &kn, &err);
        printf("     normal direction -> %s\n", err.msg);
        check_true("normal_curvature_3d(t = n) -> C2B_ERR_NUMERIC 'normal', kn untouched",
                   st == C2B_ERR_NUMERIC && has(&err, "normal") && kn == 42);
        st = c2b_curv_normal_curvature_3d(d, &p, tnear, &kn, &err);
        check_true("normal_curvature_3d(t 1e-10 off n) -> C2B_ERR_NUMERIC", st == C2B_ERR_NUMERIC && kn == 42);
        st = c2b_curv_normal_curvature_3d(d, &p, t0, &kn, &err);
        check_true("normal_curvature_3d(t = 0) -> C2B_ERR_ARG", st == C2B_ERR_ARG && has(&err, "zero"));
        st = c2b_curv_normal_curvature_3d(d, &p, tnan, &kn, &err);
        check_true("normal_curvature_3d(t NaN) -> C2B_ERR_NUMERIC", st == C2B_ERR_NUMERIC && has(&err, "t[1]"));
        st = c2b_curv_normal_curvature_3d(d, &p, NULL, &kn, &err);
        check_true("normal_curvature_3d(NULL t) -> C2B_ERR_ARG", st == C2B_ERR_ARG);
        check_true("normal_curvature(0, 0) is NaN (documented)", isnan(c2b_curv_normal_curvature(&p, 0, 0)));
        check_close("normal_curvature(1e300, 1e300) does not overflow", c2b_curv_normal_curvature(&p, 1e300, 1e300),
                    -1, 1e-14, 0);
    }
}

static void test_batch(void)
{
    enum { NP = 6, STRIDE = 21 };
    double buf[NP * STRIDE];
    for (size_t i = 0; i < sizeof buf / sizeof *buf; i++)
        buf[i] = -7; /* padding between blocks must be ignored */
    sphere(2, 0.3, 0.2, buf + 0 * STRIDE);
    torus(3, 1, 0.5, 1.0, buf + 1 * STRIDE);
    cone(0, 1.0, buf + 2 * STRIDE);
    sphere(1, 0.1, 0.1, buf + 3 * STRIDE);
    buf[3 * STRIDE + 5] = NAN;
    sphere_pole_exact(1, 0.2, buf + 4 * STRIDE);
    saddle(0.4, 0.1, buf + 5 * STRIDE);
    static const unsigned char want_flags[NP] = {0, 0, 1, 1, 1, 0};

    c2b_curv_point out[NP];
    unsigned char flags[NP];
    size_t nd = 99;
    c2b_error err;
    c2b_status st = c2b_curv_eval_many(NP, buf, STRIDE, 0, out, flags, &nd, &err);
    check_true("batch: returns C2B_OK despite degenerate points", st == C2B_OK);
    check_true("batch: 3 degenerate points counted", nd == 3);
    check_true("batch: flags = {0,0,1,1,1,0}", memcmp(flags, want_flags, NP) == 0);
    int same = 1, nan_ok = 1;
    for (int i = 0; i < NP; i++) {
        c2b_curv_point q;
        if (!want_flags[i]) {
            same &= c2b_curv_eval(buf + i * STRIDE, 0, &q, NULL) == C2B_OK && memcmp(&q, &out[i], sizeof q) == 0;
        } else {
            nan_ok &= isnan(out[i].K) && isnan(out[i].k1) && isnan(out[i].normal[0]) && isnan(out[i].dir2[2]);
        }
    }
    check_true("batch: valid points equal single-point results bit for bit", same);
    check_true("batch: degenerate points are NaN-filled", nan_ok);

    st = c2b_curv_eval_many(NP, buf, STRIDE, 0, out, NULL, NULL, &err);
    check_true("batch: flags and ndegenerate may be NULL", st == C2B_OK);
    st = c2b_curv_eval_many(NP, buf, 17, 0, out, flags, &nd, &err);
    check_true("batch: stride 17 -> C2B_ERR_ARG", st == C2B_ERR_ARG && has(&err, "stride"));
    st = c2b_curv_eval_many(NP, NULL, STRIDE, 0, out, flags, &nd, &err);
    check_true("batch: NULL d -> C2B_ERR_ARG", st == C2B_ERR_ARG);
    st = c2b_curv_eval_many((size_t)-1 / 8, buf, 64, 0, out, flags, &nd, &err);
    check_true("batch: n * stride overflow -> C2B_ERR_ARG", st == C2B_ERR_ARG && has(&err, "overflow"));
    st = c2b_curv_eval_many(NP, buf, STRIDE, 5, out, flags, &nd, &err);
    check_true("batch: tol_rel = 5 -> C2B_ERR_ARG", st == C2B_ERR_ARG);
    nd = 99;
    st = c2b_curv_eval_many(0, NULL, STRIDE, 0, NULL, NULL, &nd, &err);
    check_true("batch: n = 0 is OK and counts 0", st == C2B_OK && nd == 0);
}

int main(void)
{
    test_sphere();
    test_cylinder();
    test_torus();
    test_plane();
    test_saddles();
    test_degenerate();
    test_batch();
    return test_summary("test_curv");
}
