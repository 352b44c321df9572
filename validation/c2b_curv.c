/*
 * Analytic differential geometry at a surface point. See c2b_curv.h for the layout,
 * the sign conventions and the method.
 */
#include "c2b_curv.h"
#include "c2b_vec3.h"

#include <math.h>
#include <stdint.h>

static const char *const ENTRY_NAME[6] = {"S", "Su", "Sv", "Suu", "Suv", "Svv"};
static const char XYZ[3] = {'x', 'y', 'z'};



/* Index of the first non-finite entry of v[0..n-1], or -1. */
static int first_nonfinite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return i;
    return -1;
}

static c2b_status nonfinite_input(int i, double value, c2b_error *err)
{
    return c2b_error_set(err, C2B_ERR_NUMERIC, "non-finite input: d[%d] (%s.%c) = %g", i,
                         ENTRY_NAME[i / 3], XYZ[i % 3], value);
}

/* tol_rel <= 0 or NaN selects the default; values >= 1 would reject every point. */
static c2b_status resolve_tol(double tol_rel, double *tol, c2b_error *err)
{
    if (!(tol_rel > 0)) {
        *tol = C2B_CURV_TOL_REL_DEFAULT;
        return C2B_OK;
    }
    if (!(tol_rel < 1))
        return c2b_error_set(err, C2B_ERR_ARG, "tol_rel = %g must be < 1 (or <= 0 for the default %g)",
                             tol_rel, C2B_CURV_TOL_REL_DEFAULT);
    *tol = tol_rel;
    return C2B_OK;
}

static c2b_status eval_point(const double *d, double tol, c2b_curv_point *out, c2b_error *err)
{
    int bad = first_nonfinite(d, C2B_CURV_BLOCK);
    if (bad >= 0)
        return nonfinite_input(bad, d[bad], err);

    /* Scale by an exact power of two so that max |Su|, |Sv| components lie in [0.5, 1):
     * a uniform scaling of the surface by lambda = 2^-e maps E -> lambda^2 E,
     * L -> lambda L, k -> k / lambda, and is undone exactly at the end. */
    double m = 0;
    for (int i = 3; i < 9; i++)
        m = fmax(m, fabs(d[i]));
    if (m == 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "degenerate point: Su and Sv both vanish (E = G = 0)");
    int e;
    (void)frexp(m, &e);
    double su[3], sv[3], suu[3], suv[3], svv[3];
    for (int k = 0; k < 3; k++) {
        su[k] = ldexp(d[3 + k], -e);
        sv[k] = ldexp(d[6 + k], -e);
        suu[k] = ldexp(d[9 + k], -e);
        suv[k] = ldexp(d[12 + k], -e);
        svv[k] = ldexp(d[15 + k], -e);
    }

    double E = c2b_vec3_dot(su, su), F = c2b_vec3_dot(su, sv), G = c2b_vec3_dot(sv, sv);
    double c[3];
    c2b_vec3_cross(su, sv, c);
    double det = c2b_vec3_dot(c, c); /* = EG - F^2 (Lagrange), without cancellation */
    double det_unscaled = ldexp(det, 4 * e);
    if (E == 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "degenerate point: Su vanishes (E = %g)",
                             ldexp(E, 2 * e));
    if (G == 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "degenerate point: Sv vanishes (G = %g)",
                             ldexp(G, 2 * e));
    if (E <= tol * G)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "degenerate point: Su vanishes relative to Sv (E/G = %.3g <= tol_rel %.3g)",
                             E / G, tol);
    if (G <= tol * E)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "degenerate point: Sv vanishes relative to Su (G/E = %.3g <= tol_rel %.3g)",
                             G / E, tol);
    double rel = det / E / G; /* sin^2 of the angle between Su and Sv */
    if (!(rel > tol))
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "degenerate point: Su x Sv vanishes (EG-F^2 = %.3g, relative %.3g <= tol_rel %.3g)",
                             det_unscaled, rel, tol);

    c2b_curv_point r;
    double sq = sqrt(det);
    for (int k = 0; k < 3; k++)
        r.normal[k] = c[k] / sq;
    double L = c2b_vec3_dot(suu, r.normal), M = c2b_vec3_dot(suv, r.normal), N = c2b_vec3_dot(svv, r.normal);
    double K = (L * N - M * M) / det;
    double H = (E * N - 2 * F * M + G * L) / (2 * det);

    /* Orthonormal frame e1 = Su/|Su|, e2 = n x e1. With I = R^T R,
     * R = [[sqrt(E), F/sqrt(E)], [0, sqrt(det)/sqrt(E)]], the shape operator in the frame
     * is S = R^-T II R^-1 (symmetric). R^-1 = [[r11, r12], [0, r22]]. */
    double sE = sqrt(E);
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++)
        e1[k] = su[k] / sE;
    c2b_vec3_cross(r.normal, e1, e2);
    double r11 = 1 / sE, r12 = -F / (sE * sq), r22 = sE / sq;
    double s11 = L * r11 * r11;
    double s12 = r11 * (L * r12 + M * r22);
    double s22 = (L * r12 + 2 * M * r22) * r12 + N * r22 * r22;
    double half = 0.5 * (s11 - s22);
    double rad = hypot(half, s12); /* sqrt(H^2 - K) as a sum of squares */

    double x, y;
    if (2 * rad <= C2B_CURV_UMBILIC_REL * (fabs(H) + rad)) {
        x = 1; /* umbilic or flat point: every direction is principal */
        y = 0;
    } else if (half >= 0) {
        x = half + rad; /* (k1 - s22, s12): no cancellation, norm >= rad */
        y = s12;
    } else {
        x = s12; /* (s12, k1 - s11) */
        y = rad - half;
    }
    double len = hypot(x, y);
    x /= len;
    y /= len;
    for (int k = 0; k < 3; k++)
        r.dir1[k] = x * e1[k] + y * e2[k];
    c2b_vec3_cross(r.normal, r.dir1, r.dir2);

    r.E = ldexp(E, 2 * e);
    r.F = ldexp(F, 2 * e);
    r.G = ldexp(G, 2 * e);
    r.L = ldexp(L, e);
    r.M = ldexp(M, e);
    r.N = ldexp(N, e);
    r.K = ldexp(K, -2 * e);
    r.H = ldexp(H, -e);
    r.k1 = ldexp(H + rad, -e);
    r.k2 = ldexp(H - rad, -e);
    r.metric_det = det_unscaled;

    const double *fields[] = {&r.E, &r.F, &r.G, &r.L, &r.M, &r.N, &r.K, &r.H, &r.k1, &r.k2, &r.metric_det};
    static const char *const names[] = {"E", "F", "G", "L", "M", "N", "K", "H", "k1", "k2", "EG-F^2"};
    for (size_t i = 0; i < sizeof fields / sizeof *fields; i++)
        if (!isfinite(*fields[i]))
            return c2b_error_set(err, C2B_ERR_NUMERIC,
                                 "non-finite result: %s = %g (second derivatives too large for the "
                                 "first, or the result exceeds the double range)",
                                 names[i], *fields[i]);
    *out = r;
    return C2B_OK;
}

c2b_status c2b_curv_eval(const double *d, double tol_rel, c2b_curv_point *out, c2b_error *err)
{
    if (!d || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_curv_eval: %s is NULL", !d ? "d" : "out");
    double tol = C2B_CURV_TOL_REL_DEFAULT;
    c2b_status st = resolve_tol(tol_rel, &tol, err);
    if (st)
        return st;
    return eval_point(d, tol, out, err);
}

double c2b_curv_normal_curvature(const c2b_curv_point *p, double a, double b)
{
    if (!p || !isfinite(a) || !isfinite(b))
        return NAN;
    double s = fmax(fabs(a), fabs(b));
    if (s == 0)
        return NAN;
    a /= s;
    b /= s;
    double num = (p->L * a + 2 * p->M * b) * a + p->N * b * b;
    double den = (p->E * a + 2 * p->F * b) * a + p->G * b * b;
    return num / den;
}

c2b_status c2b_curv_normal_curvature_3d(const double *d, const c2b_curv_point *p, const double *t,
                                        double *kn, c2b_error *err)
{
    if (!d || !p || !t || !kn)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_curv_normal_curvature_3d: %s is NULL",
                             !d ? "d" : !p ? "p" : !t ? "t" : "kn");
    int bad = first_nonfinite(d + 3, 6);
    if (bad >= 0)
        return nonfinite_input(bad + 3, d[bad + 3], err);
    bad = first_nonfinite(t, 3);
    if (bad >= 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "non-finite direction: t[%d] = %g", bad, t[bad]);

    /* Scale t to max component 1 so |t|^2 cannot overflow. */
    double s = fmax(fmax(fabs(t[0]), fabs(t[1])), fabs(t[2]));
    if (s == 0)
        return c2b_error_set(err, C2B_ERR_ARG, "direction t is the zero vector");
    double u[3] = {t[0] / s, t[1] / s, t[2] / s};
    double tn = c2b_vec3_dot(u, p->normal);
    double tt[3];
    for (int k = 0; k < 3; k++)
        tt[k] = u[k] - tn * p->normal[k];
    double tlen = sqrt(c2b_vec3_dot(tt, tt)), ulen = sqrt(c2b_vec3_dot(u, u));
    if (!(tlen > C2B_CURV_TANGENT_REL * ulen))
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "direction t is (nearly) normal to the surface: tangential part %.3g of "
                             "|t| <= %.3g",
                             tlen / ulen, C2B_CURV_TANGENT_REL);

    /* Solve a Su + b Sv = tt in the frame e1 = Su/|Su|, e2 = n x e1 (Sv.e2 > 0 for a
     * regular point), avoiding the normal equations' squared condition number. */
    /* (a, b) only matters up to a common factor, so Su and Sv may be scaled by a power
     * of two that keeps their squares in range. */
    double m = 0;
    for (int i = 3; i < 9; i++)
        m = fmax(m, fabs(d[i]));
    int e;
    (void)frexp(m, &e);
    double Su[3], Sv[3];
    for (int k = 0; k < 3; k++) {
        Su[k] = ldexp(d[3 + k], -e);
        Sv[k] = ldexp(d[6 + k], -e);
    }
    double nSu = sqrt(c2b_vec3_dot(Su, Su));
    if (!(nSu > 0))
        return c2b_error_set(err, C2B_ERR_NUMERIC, "degenerate point: Su vanishes");
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++)
        e1[k] = Su[k] / nSu;
    c2b_vec3_cross(p->normal, e1, e2);
    double v2 = c2b_vec3_dot(Sv, e2);
    if (!(fabs(v2) > 0))
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "degenerate point: Su and Sv do not span the tangent plane of p");
    double b = c2b_vec3_dot(tt, e2) / v2;
    double a = (c2b_vec3_dot(tt, e1) - b * c2b_vec3_dot(Sv, e1)) / nSu;
    double k = c2b_curv_normal_curvature(p, a, b);
    if (!isfinite(k))
        return c2b_error_set(err, C2B_ERR_NUMERIC, "non-finite normal curvature %g", k);
    *kn = k;
    return C2B_OK;
}

c2b_status c2b_curv_eval_many(size_t n, const double *d, size_t stride, double tol_rel,
                              c2b_curv_point *out, unsigned char *flags, size_t *ndegenerate,
                              c2b_error *err)
{
    if (n > 0 && (!d || !out))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_curv_eval_many: %s is NULL", !d ? "d" : "out");
    if (stride < C2B_CURV_BLOCK)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_curv_eval_many: stride %zu < %d", stride,
                             C2B_CURV_BLOCK);
    if (n > 0 && (n - 1) > (SIZE_MAX - C2B_CURV_BLOCK) / stride)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_curv_eval_many: n = %zu blocks of stride %zu overflow",
                             n, stride);
    double tol = C2B_CURV_TOL_REL_DEFAULT;
    c2b_status st = resolve_tol(tol_rel, &tol, err);
    if (st)
        return st;

    size_t nbad = 0;
    for (size_t i = 0; i < n; i++) {
        st = eval_point(d + i * stride, tol, &out[i], NULL);
        if (st) {
            c2b_curv_point *q = &out[i];
            for (int k = 0; k < 3; k++)
                q->normal[k] = q->dir1[k] = q->dir2[k] = NAN;
            q->E = q->F = q->G = q->L = q->M = q->N = NAN;
            q->K = q->H = q->k1 = q->k2 = q->metric_det = NAN;
            nbad++;
        }
        if (flags)
            flags[i] = st ? 1 : 0;
    }
    if (ndegenerate)
        *ndegenerate = nbad;
    return C2B_OK;
}
