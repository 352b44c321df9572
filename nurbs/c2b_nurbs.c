/*
 * NURBS curves and surfaces (see c2b_nurbs.h).
 *
 * Storage. The canonical state of an object is its degree, its knot vector and its
 * Cartesian poles [x, y, z, w] exactly as given (so that a copy through the public
 * accessors reproduces it bit for bit). The homogeneous poles [x w, y w, z w, w] used by
 * every algorithm are derived from them. Periodic directions keep the unwrapped form:
 * n + p poles (the first p repeated at the end), so evaluation needs no index wrapping.
 *
 * References: L. Piegl, W. Tiller, The NURBS Book, 2nd ed., Springer 1997:
 * A2.1 (span search), A2.2 (basis functions, as the Cox-de Boor triangle of all degrees),
 * A3.3/A3.4 and A3.7/A3.8 (derivatives through derivative control points: exact zeros and
 * small derivatives stay accurate), A4.2/A4.4 (rational derivatives, eq. 4.8 and 4.20),
 * A5.1 (knot insertion, Boehm), section 6.1 (point inversion). Degree elevation uses Prautzsch's
 * identity instead of A5.9 (see nb_elevate_one()).
 */
#include "c2b_nurbs.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXP C2B_NURBS_MAX_DEGREE
#define MAXD C2B_NURBS_MAX_DERIV

/** Parameters within this fraction of the domain length outside a non-periodic domain
 *  are clamped; farther ones are an error. */
#define NB_DOMAIN_TOL 1e-12
/** Relative tolerance of the periodic knot spacing condition. */
#define NB_PERIOD_TOL 1e-12
/** Projection: grid samples per knot span and direction, the largest grid, the number of
 *  grid candidates refined by Newton, and the Newton iteration limit. */
#define NB_PROJ_PER_SPAN 8
#define NB_PROJ_MAX_GRID 1000000L
#define NB_PROJ_CANDIDATES 4
#define NB_PROJ_MAX_ITER 100
/** Newton stops when a step is below this fraction of the domain length. */
#define NB_PROJ_STEP_TOL 1e-15
/** Newton steps below this fraction of the domain length are taken without line search
 *  (the squared distance no longer resolves them). */
#define NB_PROJ_LOCAL 1e-6

/* ---- internal representation ------------------------------------------------------- */

/* One parametric direction. */
typedef struct nb_dir {
    int p;        /* degree */
    int n;        /* distinct poles */
    int periodic; /* 0 or 1 */
    int nk;       /* knots: n + p + 1, or n + 2p + 1 when periodic */
    int nw;       /* stored (unwrapped) poles: n, or n + p when periodic */
    double *U;    /* knot vector, nk values */
} nb_dir;

struct c2b_nurbs_curve {
    nb_dir d;
    double *cart; /* nw x [x, y, z, w] */
    double *pw;   /* nw x [x w, y w, z w, w] */
    int rational; /* 0 when all weights are equal: evaluated as a polynomial spline */
};

struct c2b_nurbs_surface {
    nb_dir d[2];
    double *cart; /* nw_u x nw_v x [x, y, z, w], row-major */
    double *pw;   /* same, homogeneous */
    int rational; /* as for curves */
};

/* 1 unless all weights of the Cartesian poles are equal. With equal weights the spline is
 * polynomial and is evaluated without the quotient rule, so that derivatives of order
 * above the degree are exactly zero instead of rounding noise of sum N^(k) = 0. */
static int nb_is_rational(const double *cart, size_t count)
{
    for (size_t i = 1; i < count; i++)
        if (cart[4 * i + 3] != cart[3])
            return 1;
    return 0;
}

/* ---- messages ------------------------------------------------------------------------ */

/* Shortest decimal form of x that reads back exactly. */
static const char *nb_num(double x, char *buf, size_t len)
{
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(buf, len, "%.*g", prec, x);
        if (strtod(buf, NULL) == x || x != x)
            break;
    }
    return buf;
}

/* Set err to "<path>.<sub>: <message>" (either part may be empty or NULL). */
static c2b_status nb_fail(c2b_error *err, c2b_status code, const char *path, const char *sub,
                          const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

static c2b_status nb_fail(c2b_error *err, c2b_status code, const char *path, const char *sub,
                          const char *fmt, ...)
{
    if (!err)
        return code;
    char body[C2B_ERROR_MSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(body, sizeof body, fmt, ap);
    va_end(ap);
    int hp = path && *path, hs = sub && *sub;
    c2b_error_set(err, code, "%s", body);
    if (hp || hs)
        c2b_error_prefix(err, "%s%s%s: ", hp ? path : "", hp && hs ? "." : "", hs ? sub : "");
    return code;
}

/* ---- knot vector helpers ----------------------------------------------------------- */

static double nb_dom0(const nb_dir *d) { return d->U[d->p]; }
static double nb_dom1(const nb_dir *d) { return d->U[d->nw]; }

/* Knot span (A2.1): the index k in [p, nw - 1] with U[k] <= t < U[k + 1]; at the end of
 * the domain the last non-empty span. t must lie in the domain. */
static int nb_span(const nb_dir *d, double t)
{
    const double *U = d->U;
    int lo = d->p, hi = d->nw;
    if (t >= U[hi]) {
        int k = hi - 1;
        while (k > d->p && U[k] == U[k + 1])
            k--;
        return k;
    }
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (t < U[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

/* Map t into the domain: wrap when periodic, clamp within the tolerance otherwise.
 * name is the parameter's name for messages ("t", "u", "v"). */
static c2b_status nb_map(const nb_dir *d, double t, double *out, const char *name, c2b_error *err)
{
    double a = nb_dom0(d), b = nb_dom1(d), len = b - a;
    char s0[32], s1[32], s2[32];
    if (!isfinite(t))
        return c2b_error_set(err, C2B_ERR_ARG, "parameter %s = %s is not finite", name,
                             nb_num(t, s0, sizeof s0));
    if (d->periodic) {
        if (t >= a && t < b) {
            *out = t;
            return C2B_OK;
        }
        double x = fmod(t - a, len);
        if (x < 0)
            x += len;
        double r = a + x;
        if (!(r >= a && r < b))
            r = a;
        *out = r;
        return C2B_OK;
    }
    double tol = NB_DOMAIN_TOL * len;
    if (t < a - tol || t > b + tol)
        return c2b_error_set(err, C2B_ERR_ARG, "parameter %s = %s is outside the domain [%s, %s]",
                             name, nb_num(t, s0, sizeof s0), nb_num(a, s1, sizeof s1),
                             nb_num(b, s2, sizeof s2));
    *out = t < a ? a : (t > b ? b : t);
    return C2B_OK;
}

/* Map without error reporting (internal callers with in-domain or wrapped values). */
static double nb_map_quiet(const nb_dir *d, double t)
{
    double r = t;
    if (nb_map(d, t, &r, "t", NULL) != C2B_OK) {
        double a = nb_dom0(d), b = nb_dom1(d);
        r = t < a ? a : b;
    }
    return r;
}

/* ---- basis functions ------------------------------------------------------------------ */

/*
 * The Cox-de Boor triangle on a non-empty span (The NURBS Book eq. 2.5, A2.2):
 * tri[d][j] = N_{span - d + j, d}(t) for every degree d = 0..p, j = 0..d.
 * On a non-empty span no denominator that is used vanishes.
 */
static void nb_triangle(const double *U, int p, int span, double t, double tri[][MAXP + 1])
{
    tri[0][0] = 1.0;
    for (int d = 1; d <= p; d++) {
        for (int j = 0; j <= d; j++) {
            int i = span - d + j;
            double v = 0.0;
            if (j >= 1)
                v += (t - U[i]) / (U[i + d] - U[i]) * tri[d - 1][j - 1];
            if (j < d)
                v += (U[i + d + 1] - t) / (U[i + d + 1] - U[i + 1]) * tri[d - 1][j];
            tri[d][j] = v;
        }
    }
}

/*
 * Derivative control points of one span, in place (The NURBS Book eq. 3.8, A3.3):
 * given the level-(m-1) points P[0..p-m+1] of the span (level 0: the poles
 * span-p..span), make level m:
 *   P^(m)_j = (p - m + 1) (P^(m-1)_{j+1} - P^(m-1)_j) / (U_{i+p+1} - U_{i+m}),  i = span - p + j,
 * so that d^m/dt^m = sum_j N_{span-p+m+j, p-m} P^(m)_j (A3.4). Differencing the poles
 * before summing keeps small derivatives (of order near or above the "true" degree, e.g.
 * after degree elevation) as accurate as the differences of the poles, where summing
 * basis-function derivatives times poles leaves rounding of the size of the poles.
 * P holds (p + 1) points of D doubles each, with stride `stride`.
 */
static void nb_diff_level(const double *U, int p, int span, int m, double *P, size_t stride, int D)
{
    for (int j = 0; j <= p - m; j++) {
        int i = span - p + j;
        double f = (p - m + 1) / (U[i + p + 1] - U[i + m]);
        double *a = P + (size_t)j * stride;
        const double *b = P + (size_t)(j + 1) * stride;
        for (int x = 0; x < D; x++)
            a[x] = f * (b[x] - a[x]);
    }
}

/* Binomial coefficients bin[n][k] for n <= nmax (exact in double for nmax <= 30). */
static void nb_binomials(int nmax, double bin[][MAXP + MAXD + 2])
{
    for (int n = 0; n <= nmax; n++) {
        bin[n][0] = bin[n][n] = 1.0;
        for (int k = 1; k < n; k++)
            bin[n][k] = bin[n - 1][k - 1] + bin[n - 1][k];
    }
}

/* ---- evaluation cores (parameters already mapped into the domain) --------------------- */

/* Curve: out[k * 3 + xyz] = C^(k)(t), k = 0..nd. Derivatives of the homogeneous curve by
 * derivative control points (A3.3/A3.4), then the quotient rule (A4.2, eq. 4.8); a
 * polynomial curve (equal weights) is evaluated on its Cartesian poles directly. */
static void nb_curve_eval_raw(const c2b_nurbs_curve *c, double t, int nd, double *out)
{
    const nb_dir *d = &c->d;
    int p = d->p, span = nb_span(d, t);
    double tri[MAXP + 1][MAXP + 1], A[MAXD + 1][4], Q[MAXP + 1][4];
    nb_triangle(d->U, p, span, t, tri);
    const double *poles = c->rational ? c->pw : c->cart;
    memcpy(Q, poles + 4 * (size_t)(span - p), 4 * (size_t)(p + 1) * sizeof(double));
    for (int k = 0; k <= nd; k++) {
        for (int x = 0; x < 4; x++)
            A[k][x] = 0.0;
        if (k > p)
            continue;
        if (k > 0)
            nb_diff_level(d->U, p, span, k, &Q[0][0], 4, 4);
        for (int j = 0; j <= p - k; j++)
            for (int x = 0; x < 4; x++)
                A[k][x] += tri[p - k][j] * Q[j][x];
    }
    if (!c->rational) {
        for (int k = 0; k <= nd; k++)
            for (int x = 0; x < 3; x++)
                out[k * 3 + x] = A[k][x];
        return;
    }
    double bin[MAXD + 1][MAXP + MAXD + 2];
    nb_binomials(nd, bin);
    double w0 = A[0][3];
    for (int k = 0; k <= nd; k++)
        for (int x = 0; x < 3; x++) {
            double v = A[k][x];
            for (int i = 1; i <= k; i++)
                v -= bin[k][i] * A[i][3] * out[(k - i) * 3 + x];
            out[k * 3 + x] = v / w0;
        }
}

/*
 * Surface: skl[(a * (dv + 1) + b) * 3 + xyz] = d^(a+b) S / du^a dv^b for a <= du, b <= dv
 * and a + b <= tot (other entries untouched). Homogeneous derivatives by derivative
 * control points of the span's (p+1) x (q+1) poles (A3.7/A3.8: a-fold differences in u,
 * then b-fold in v, of the poles themselves, summed with the degree (p - a, q - b)
 * functions), then the rational recurrence (A4.4, eq. 4.20) unless polynomial.
 */
static void nb_surface_eval_raw(const c2b_nurbs_surface *s, double u, double v, int du, int dv,
                                int tot, double *skl)
{
    const nb_dir *a = &s->d[0], *b = &s->d[1];
    int p = a->p, q = b->p, nwv = b->nw;
    int su = nb_span(a, u), sv = nb_span(b, v);
    double tu[MAXP + 1][MAXP + 1], tv[MAXP + 1][MAXP + 1];
    nb_triangle(a->U, p, su, u, tu);
    nb_triangle(b->U, q, sv, v, tv);
    const double *poles = s->rational ? s->pw : s->cart;

    const size_t RS = (MAXP + 1) * 4; /* row stride of W and V */
    double W[MAXP + 1][MAXP + 1][4];      /* W[r][c]: level-k u-differences */
    double V[MAXP + 1][MAXP + 1][4];      /* V[r][c]: level-l v-differences of W */
    for (int r = 0; r <= p; r++)
        memcpy(W[r], poles + 4 * ((size_t)(su - p + r) * (size_t)nwv + (size_t)(sv - q)),
               4 * (size_t)(q + 1) * sizeof(double));

    double A[MAXD + 1][MAXD + 1][4];
    for (int k = 0; k <= du; k++) {
        int lmax = tot - k < dv ? tot - k : dv;
        if (lmax < 0)
            break;
        for (int l = 0; l <= lmax; l++)
            for (int x = 0; x < 4; x++)
                A[k][l][x] = 0.0;
        if (k > p)
            continue;
        if (k > 0) /* u-differences of all q + 1 columns at once */
            nb_diff_level(a->U, p, su, k, &W[0][0][0], RS, 4 * (q + 1));
        for (int r = 0; r <= p - k; r++)
            memcpy(V[r], W[r], 4 * (size_t)(q + 1) * sizeof(double));
        for (int l = 0; l <= lmax && l <= q; l++) {
            if (l > 0) /* v-differences of every row */
                for (int r = 0; r <= p - k; r++)
                    nb_diff_level(b->U, q, sv, l, &V[r][0][0], 4, 4);
            for (int r = 0; r <= p - k; r++) {
                double row[4] = {0.0, 0.0, 0.0, 0.0};
                for (int c = 0; c <= q - l; c++)
                    for (int x = 0; x < 4; x++)
                        row[x] += tv[q - l][c] * V[r][c][x];
                for (int x = 0; x < 4; x++)
                    A[k][l][x] += tu[p - k][r] * row[x];
            }
        }
    }

    int ld = dv + 1;
    if (!s->rational) {
        for (int k = 0; k <= du; k++) {
            int lmax = tot - k < dv ? tot - k : dv;
            for (int l = 0; l <= lmax; l++)
                for (int x = 0; x < 3; x++)
                    skl[(k * ld + l) * 3 + x] = A[k][l][x];
        }
        return;
    }
    double bin[MAXD + 1][MAXP + MAXD + 2];
    nb_binomials(du > dv ? du : dv, bin);
    double w0 = A[0][0][3];
    for (int k = 0; k <= du; k++) {
        int lmax = tot - k < dv ? tot - k : dv;
        for (int l = 0; l <= lmax; l++) {
            for (int x = 0; x < 3; x++) {
                double val = A[k][l][x];
                for (int j = 1; j <= l; j++)
                    val -= bin[l][j] * A[0][j][3] * skl[(k * ld + l - j) * 3 + x];
                for (int i = 1; i <= k; i++) {
                    val -= bin[k][i] * A[i][0][3] * skl[((k - i) * ld + l) * 3 + x];
                    double v2 = 0.0;
                    for (int j = 1; j <= l; j++)
                        v2 += bin[l][j] * A[i][j][3] * skl[((k - i) * ld + l - j) * 3 + x];
                    val -= bin[k][i] * v2;
                }
                skl[(k * ld + l) * 3 + x] = val / w0;
            }
        }
    }
}

/* ---- validation ------------------------------------------------------------------------ */

/* Validate the degree, pole count and knot vector of one direction.
 * kname: "knots", "knots_u" or "knots_v"; dirw: "", " in u" or " in v". */
static c2b_status nb_check_dir(int p, int n, const double *U, int periodic, const char *path,
                               const char *kname, const char *dirw, c2b_error *err)
{
    char s0[32], s1[32], sub[64];
    if (p < 1 || p > MAXP)
        return nb_fail(err, C2B_ERR_SPEC, path, NULL, "degree must be 1..%d (got %d%s)", MAXP, p,
                       dirw);
    if (n > C2B_NURBS_MAX_POLES)
        return nb_fail(err, C2B_ERR_LIMIT, path, NULL, "%d poles%s exceed the limit of %d", n, dirw,
                       C2B_NURBS_MAX_POLES);
    if (n < p + 1)
        return nb_fail(err, C2B_ERR_SPEC, path, NULL, "degree %d%s needs at least %d poles, got %d",
                       p, dirw, p + 1, n);
    if (!U)
        return nb_fail(err, C2B_ERR_ARG, path, kname, "NULL knot vector");
    int nk = periodic ? n + 2 * p + 1 : n + p + 1;
    int nw = periodic ? n + p : n;
    for (int i = 0; i < nk; i++)
        if (!isfinite(U[i])) {
            snprintf(sub, sizeof sub, "%s[%d]", kname, i);
            return nb_fail(err, C2B_ERR_SPEC, path, sub, "not finite");
        }
    for (int i = 1; i < nk; i++)
        if (U[i] < U[i - 1])
            return nb_fail(err, C2B_ERR_SPEC, path, kname, "decreasing at index %d (%s after %s)", i,
                           nb_num(U[i], s0, sizeof s0), nb_num(U[i - 1], s1, sizeof s1));
    double a = U[p], b = U[nw];
    if (!(b > a))
        return nb_fail(err, C2B_ERR_SPEC, path, kname, "the domain [%s, %s] has zero length",
                       nb_num(a, s0, sizeof s0), nb_num(b, s1, sizeof s1));
    if (!isfinite(U[nk - 1] - U[0]))
        return nb_fail(err, C2B_ERR_SPEC, path, kname, "the knot range [%s, %s] is too long "
                       "(its length overflows)", nb_num(U[0], s0, sizeof s0),
                       nb_num(U[nk - 1], s1, sizeof s1));
    for (int i = 0; i < nk;) {
        int j = i;
        while (j + 1 < nk && U[j + 1] == U[i])
            j++;
        int mult = j - i + 1;
        int inside = periodic || (U[i] > a && U[i] < b);
        int maxm = inside ? p : p + 1;
        if (mult > maxm)
            return nb_fail(err, C2B_ERR_SPEC, path, kname,
                           "value %s at index %d has multiplicity %d, more than %s = %d",
                           nb_num(U[i], s0, sizeof s0), i, mult,
                           inside ? (periodic ? "p (periodic)" : "p (interior knot)") : "p + 1",
                           maxm);
        i = j + 1;
    }
    if (periodic) {
        double T = b - a;
        for (int i = 0; i + n < nk; i++) {
            double dd = U[i + n] - U[i];
            if (!(fabs(dd - T) <= NB_PERIOD_TOL * T))
                return nb_fail(err, C2B_ERR_SPEC, path, kname,
                               "not periodic: %s[%d] - %s[%d] = %s, expected the period %s "
                               "(n = %d poles, p = %d)",
                               kname, i + n, kname, i, nb_num(dd, s0, sizeof s0),
                               nb_num(T, s1, sizeof s1), n, p);
        }
    }
    return C2B_OK;
}

/* Validate one pole [x, y, z, w]; name is "poles[i]" or "poles[i][j]". */
static c2b_status nb_check_pole(const double *P, const char *path, const char *name, c2b_error *err)
{
    char s0[32];
    for (int x = 0; x < 4; x++)
        if (!isfinite(P[x]))
            return nb_fail(err, C2B_ERR_SPEC, path, name, "not finite");
    if (!(P[3] > 0))
        return nb_fail(err, C2B_ERR_SPEC, path, name, "weight must be positive (got %s)",
                       nb_num(P[3], s0, sizeof s0));
    for (int x = 0; x < 3; x++)
        if (!isfinite(P[x] * P[3]))
            return nb_fail(err, C2B_ERR_SPEC, path, name, "not finite after weighting (x w overflows)");
    return C2B_OK;
}

/* Homogeneous form of Cartesian poles. */
static void nb_homog(const double *cart, double *pw, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        double w = cart[4 * i + 3];
        pw[4 * i + 0] = cart[4 * i + 0] * w;
        pw[4 * i + 1] = cart[4 * i + 1] * w;
        pw[4 * i + 2] = cart[4 * i + 2] * w;
        pw[4 * i + 3] = w;
    }
}

/* Cartesian form of homogeneous poles computed by an algorithm, then the homogeneous
 * form again from it, so that the canonical (Cartesian) state determines everything.
 * wfix > 0: the spline was polynomial with all weights wfix; keep them exactly so (the
 * convex combinations of equal weights may round by one unit in the last place). */
static void nb_from_homog(double *pw, double *cart, size_t count, double wfix)
{
    for (size_t i = 0; i < count; i++) {
        double w = pw[4 * i + 3];
        cart[4 * i + 0] = pw[4 * i + 0] / w + 0.0;
        cart[4 * i + 1] = pw[4 * i + 1] / w + 0.0;
        cart[4 * i + 2] = pw[4 * i + 2] / w + 0.0;
        cart[4 * i + 3] = wfix > 0 ? wfix : w;
    }
    nb_homog(cart, pw, count);
}

static void nb_dir_init(nb_dir *d, int p, int n, int periodic)
{
    d->p = p;
    d->n = n;
    d->periodic = periodic ? 1 : 0;
    d->nk = periodic ? n + 2 * p + 1 : n + p + 1;
    d->nw = periodic ? n + p : n;
    d->U = NULL;
}

/* Copy knots (normalising -0 to +0 so that text round trips are exact). */
static double *nb_knots_dup(const double *U, int nk)
{
    double *r = malloc((size_t)nk * sizeof *r);
    if (r)
        for (int i = 0; i < nk; i++)
            r[i] = U[i] + 0.0;
    return r;
}

/* ---- curves ------------------------------------------------------------------------------ */

c2b_status c2b_nurbs_curve_create_at(int p, int n, const double *knots, const double *poles,
                                     int periodic, const char *path, c2b_nurbs_curve **out,
                                     c2b_error *err)
{
    if (!out)
        return nb_fail(err, C2B_ERR_ARG, path, NULL, "NULL output pointer");
    *out = NULL;
    c2b_status st = nb_check_dir(p, n, knots, periodic, path, "knots", "", err);
    if (st)
        return st;
    if (!poles)
        return nb_fail(err, C2B_ERR_ARG, path, "poles", "NULL pole array");
    char name[48];
    for (int i = 0; i < n; i++) {
        snprintf(name, sizeof name, "poles[%d]", i);
        if ((st = nb_check_pole(poles + 4 * (size_t)i, path, name, err)))
            return st;
    }
    c2b_nurbs_curve *c = calloc(1, sizeof *c);
    if (!c)
        return nb_fail(err, C2B_ERR_NOMEM, path, NULL, "out of memory creating a curve");
    nb_dir_init(&c->d, p, n, periodic);
    c->d.U = nb_knots_dup(knots, c->d.nk);
    c->cart = malloc(4 * (size_t)c->d.nw * sizeof(double));
    c->pw = malloc(4 * (size_t)c->d.nw * sizeof(double));
    if (!c->d.U || !c->cart || !c->pw) {
        c2b_nurbs_curve_destroy(c);
        return nb_fail(err, C2B_ERR_NOMEM, path, NULL, "out of memory creating a curve");
    }
    for (int i = 0; i < c->d.nw; i++)
        for (int x = 0; x < 4; x++)
            c->cart[4 * i + x] = poles[4 * (i % n) + x] + 0.0;
    nb_homog(c->cart, c->pw, (size_t)c->d.nw);
    c->rational = nb_is_rational(c->cart, (size_t)c->d.nw);
    *out = c;
    return C2B_OK;
}

c2b_status c2b_nurbs_curve_create(int p, int n, const double *knots, const double *poles,
                                  int periodic, c2b_nurbs_curve **out, c2b_error *err)
{
    return c2b_nurbs_curve_create_at(p, n, knots, poles, periodic, NULL, out, err);
}

void c2b_nurbs_curve_destroy(c2b_nurbs_curve *c)
{
    if (!c)
        return;
    free(c->d.U);
    free(c->cart);
    free(c->pw);
    free(c);
}

c2b_status c2b_nurbs_curve_copy(const c2b_nurbs_curve *c, c2b_nurbs_curve **out, c2b_error *err)
{
    if (!c || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_curve_copy: NULL argument");
    *out = NULL;
    c2b_nurbs_curve *r = calloc(1, sizeof *r);
    if (!r)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory copying a curve");
    r->d = c->d;
    r->rational = c->rational;
    r->d.U = malloc((size_t)c->d.nk * sizeof(double));
    r->cart = malloc(4 * (size_t)c->d.nw * sizeof(double));
    r->pw = malloc(4 * (size_t)c->d.nw * sizeof(double));
    if (!r->d.U || !r->cart || !r->pw) {
        c2b_nurbs_curve_destroy(r);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory copying a curve");
    }
    memcpy(r->d.U, c->d.U, (size_t)c->d.nk * sizeof(double));
    memcpy(r->cart, c->cart, 4 * (size_t)c->d.nw * sizeof(double));
    memcpy(r->pw, c->pw, 4 * (size_t)c->d.nw * sizeof(double));
    *out = r;
    return C2B_OK;
}

void c2b_nurbs_curve_domain(const c2b_nurbs_curve *c, double *t0, double *t1)
{
    if (t0)
        *t0 = c ? nb_dom0(&c->d) : NAN;
    if (t1)
        *t1 = c ? nb_dom1(&c->d) : NAN;
}

int c2b_nurbs_curve_degree(const c2b_nurbs_curve *c) { return c ? c->d.p : 0; }
int c2b_nurbs_curve_npoles(const c2b_nurbs_curve *c) { return c ? c->d.n : 0; }
int c2b_nurbs_curve_periodic(const c2b_nurbs_curve *c) { return c ? c->d.periodic : 0; }
int c2b_nurbs_curve_nknots(const c2b_nurbs_curve *c) { return c ? c->d.nk : 0; }
const double *c2b_nurbs_curve_knots(const c2b_nurbs_curve *c) { return c ? c->d.U : NULL; }

void c2b_nurbs_curve_pole(const c2b_nurbs_curve *c, int i, double *out)
{
    if (!out)
        return;
    if (!c || i < 0 || i >= c->d.n) {
        for (int x = 0; x < 4; x++)
            out[x] = NAN;
        return;
    }
    memcpy(out, c->cart + 4 * (size_t)i, 4 * sizeof(double));
}

c2b_status c2b_nurbs_curve_eval(const c2b_nurbs_curve *c, double t, int order, double *out,
                                c2b_error *err)
{
    if (!c || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_curve_eval: NULL argument");
    if (order < 0 || order > MAXD)
        return c2b_error_set(err, C2B_ERR_ARG, "derivative order %d is outside 0..%d", order, MAXD);
    double tt;
    c2b_status st = nb_map(&c->d, t, &tt, "t", err);
    if (st)
        return st;
    nb_curve_eval_raw(c, tt, order, out);
    return C2B_OK;
}

/* ---- knot insertion (A5.1) on items of D doubles ------------------------------------ */

/* Distinct pole j of a (possibly periodic) direction, items of D doubles. */
static const double *nb_item(const double *P, size_t D, int n, int j)
{
    int m = j % n;
    if (m < 0)
        m += n;
    return P + (size_t)m * D;
}

/* Knot of the infinite periodic extension of a stored periodic knot vector. */
static double nb_knot_ext(const nb_dir *d, int j)
{
    double T = nb_dom1(d) - nb_dom0(d);
    int shift = 0;
    while (j < 0) {
        j += d->n;
        shift--;
    }
    while (j >= d->nk) {
        j -= d->n;
        shift++;
    }
    return d->U[j] + shift * T;
}

/*
 * Insert knot t (already in the domain) once into direction d whose n distinct poles
 * are items of D doubles in *P (homogeneous coordinates). Boehm's algorithm (A5.1 with
 * r = 1): with U[k] <= t <= U[k + 1],
 *   Q_i = P_i (i <= k - p),  Q_i = a_i P_i + (1 - a_i) P_{i-1},  a_i = (t - U_i) / (U_{i+p} - U_i)
 *   (k - p < i <= k),  Q_i = P_{i-1} (i > k).
 * Periodic directions insert t + m T for every m: one new pole and knot per period.
 * The caller guarantees that the multiplicity of t stays <= p + 1 (non-periodic) or <= p.
 */
static c2b_status nb_insert_once(nb_dir *d, double **P, size_t D, double t)
{
    const double *U = d->U;
    int p = d->p, n = d->n;
    int k = d->p;
    while (k + 1 <= d->nw - 1 && U[k + 1] <= t)
        k++;
    double *Q = malloc((size_t)(n + 1) * D * sizeof(double));
    double *V = malloc((size_t)(d->nk + 1) * sizeof(double));
    if (!Q || !V) {
        free(Q);
        free(V);
        return C2B_ERR_NOMEM;
    }
    const double *Pv = *P;
    if (!d->periodic) {
        for (int i = 0; i <= k - p; i++)
            memcpy(Q + (size_t)i * D, Pv + (size_t)i * D, D * sizeof(double));
        for (int i = k - p + 1; i <= k; i++) {
            double a = (t - U[i]) / (U[i + p] - U[i]);
            const double *A = Pv + (size_t)i * D, *B = Pv + (size_t)(i - 1) * D;
            double *R = Q + (size_t)i * D;
            for (size_t x = 0; x < D; x++)
                R[x] = a * A[x] + (1.0 - a) * B[x];
        }
        for (int i = k + 1; i <= n; i++)
            memcpy(Q + (size_t)i * D, Pv + (size_t)(i - 1) * D, D * sizeof(double));
        for (int i = 0; i <= k; i++)
            V[i] = U[i];
        V[k + 1] = t;
        for (int i = k + 2; i <= d->nk; i++)
            V[i] = U[i - 1];
    } else {
        /* New poles Q_i, i = k-p+1 .. k-p+n+1 (one period of the new sequence). */
        double T = nb_dom1(d) - nb_dom0(d);
        int first = k - p + 1;
        for (int i = first; i <= first + n; i++) {
            int jn = ((i % (n + 1)) + (n + 1)) % (n + 1);
            double *R = Q + (size_t)jn * D;
            if (i <= k) {
                double a = (t - U[i]) / (U[i + p] - U[i]);
                const double *A = nb_item(Pv, D, n, i), *B = nb_item(Pv, D, n, i - 1);
                for (size_t x = 0; x < D; x++)
                    R[x] = a * A[x] + (1.0 - a) * B[x];
            } else {
                memcpy(R, nb_item(Pv, D, n, i - 1), D * sizeof(double));
            }
        }
        /* New knots: t inserted after index k, t - T after k - n, t + T after k + n. */
        for (int j = 0; j <= d->nk; j++) {
            double v;
            if (j < k - n)
                v = nb_knot_ext(d, j + 1) ; /* before the previous period's insertion */
            else if (j == k - n)
                v = t - T;
            else if (j <= k)
                v = nb_knot_ext(d, j);
            else if (j == k + 1)
                v = t;
            else if (j <= k + n + 1)
                v = nb_knot_ext(d, j - 1);
            else if (j == k + n + 2)
                v = t + T;
            else
                v = nb_knot_ext(d, j - 2);
            V[j] = v;
        }
        /* j < k - n is only reached for k > n, where index j + 1 <= p is stored. */
    }
    free(d->U);
    free(*P);
    d->U = V;
    *P = Q;
    d->n = n + 1;
    d->nk += 1;
    d->nw += 1;
    return C2B_OK;
}

/* Multiplicity of value t in the stored knot vector. */
static int nb_mult(const nb_dir *d, double t)
{
    int s = 0;
    for (int i = 0; i < d->nk; i++)
        if (d->U[i] == t)
            s++;
    return s;
}

/* ---- degree elevation on items of D doubles ------------------------------------------ */

/* Make a non-periodic direction clamped (knots[0..p] = domain start, the last p + 1 =
 * domain end) by inserting the domain ends up to multiplicity p + 1 and dropping the
 * poles whose basis functions vanish on the domain. */
static c2b_status nb_clamp(nb_dir *d, double **P, size_t D)
{
    c2b_status st;
    double a = nb_dom0(d);
    if (d->U[0] != a) {
        while (nb_mult(d, a) < d->p + 1)
            if ((st = nb_insert_once(d, P, D, a)))
                return st;
        int c = 0;
        while (d->U[c] != a)
            c++;
        /* drop poles 0..c-1 and knots 0..c-1 */
        memmove(*P, *P + (size_t)c * D, (size_t)(d->n - c) * D * sizeof(double));
        memmove(d->U, d->U + c, (size_t)(d->nk - c) * sizeof(double));
        d->n -= c;
        d->nw -= c;
        d->nk -= c;
    }
    double b = nb_dom1(d);
    if (d->U[d->nk - 1] != b) {
        while (nb_mult(d, b) < d->p + 1)
            if ((st = nb_insert_once(d, P, D, b)))
                return st;
        int j0 = 0;
        while (d->U[j0] != b)
            j0++;
        /* keep poles 0..j0-1 and knots 0..j0+p */
        d->n = j0;
        d->nw = j0;
        d->nk = j0 + d->p + 1;
    }
    return C2B_OK;
}

/* Largest local knot vector in the elevation: all copies of the knot values in the
 * support of one basis function, each multiplicity raised by one. */
#define NB_LOCAL (4 * MAXP + 8)

/*
 * Insert t once into the local knot vector L (len m + d + 1) of a degree-d spline with m
 * coefficients c (a single B-spline, extended by zero coefficients on both sides):
 * Boehm's rule c'_i = a_i c_i + (1 - a_i) c_{i-1}, a_i = (t - L_i) / (L_{i+d} - L_i)
 * clamped to [0, 1], which covers every position of t in [L_0, L_{m+d}].
 * Every new coefficient is a convex combination of old ones.
 */
static void nb_local_insert(double *L, int *m, double *c, int d, double t)
{
    int mm = *m;
    double cn[NB_LOCAL];
    for (int i = 0; i <= mm; i++) {
        double a;
        if (t >= L[i + d])
            a = 1.0;
        else if (t <= L[i])
            a = 0.0;
        else
            a = (t - L[i]) / (L[i + d] - L[i]);
        double ci = i < mm ? c[i] : 0.0, cp = i > 0 ? c[i - 1] : 0.0;
        cn[i] = a * ci + (1.0 - a) * cp;
    }
    int pos = mm + d + 1;
    while (pos > 0 && L[pos - 1] > t) {
        L[pos] = L[pos - 1];
        pos--;
    }
    L[pos] = t;
    for (int i = 0; i <= mm; i++)
        c[i] = cn[i];
    *m = mm + 1;
}

/*
 * Raise the degree of a clamped direction by one. Prautzsch's identity (H. Prautzsch,
 * Degree elevation of B-spline curves, CAGD 1 (1984) 193-198):
 *   N_{i,p} = 1/(p+1) sum_{j=i}^{i+p+1} N(. | U_i..U_{i+p+1} with U_j doubled),
 * each term a degree p + 1 B-spline whose knots are a sub-multiset of U* (U with every
 * multiplicity raised by one). Inserting the missing knots of U* (Boehm) expresses each
 * term in the basis of U*. All weights are non-negative, so every new pole is a convex
 * combination of the old ones and the result is as accurate as the poles.
 * (The NURBS Book's A5.9, which removes knots after Bezier elevation, extrapolates where
 * adjacent knot spans differ much in length: 3e-13 relative error at a span ratio of 70.)
 */
static c2b_status nb_elevate_one(nb_dir *d, double **Pp, size_t D)
{
    const double *U = d->U;
    int p = d->p, n = d->n, nk = d->nk;
    int ndist = 1;
    for (int i = 1; i < nk; i++)
        if (U[i] != U[i - 1])
            ndist++;
    int nks = nk + ndist, ns = nks - (p + 2);
    double *Us = malloc((size_t)nks * sizeof(double));
    double *Q = calloc((size_t)ns * D, sizeof(double));
    if (!Us || !Q) {
        free(Us);
        free(Q);
        return C2B_ERR_NOMEM;
    }
    for (int i = 0, k = 0; i < nk; i++) {
        Us[k++] = U[i];
        if (i + 1 == nk || U[i + 1] != U[i])
            Us[k++] = U[i];
    }
    const double *P = *Pp;
    for (int i = 0; i < n; i++) {
        double a = U[i], b = U[i + p + 1];
        int s = 0, e = nks - 1;
        while (Us[s] < a)
            s++;
        while (Us[e] > b)
            e--;
        int len = e - s + 1, mfin = len - (p + 2);
        if (len > NB_LOCAL - 2) { /* cannot happen: multiplicities are at most p + 1 */
            free(Us);
            free(Q);
            return C2B_ERR_NUMERIC;
        }
        double w[NB_LOCAL] = {0};
        for (int j = i; j <= i + p + 1; j++) {
            /* tau = U[i..i+p+1] with U[j] doubled */
            double L[NB_LOCAL], c[NB_LOCAL];
            int m = 1, nt = 0;
            for (int k = i; k <= i + p + 1; k++) {
                L[nt++] = U[k];
                if (k == j)
                    L[nt++] = U[k];
            }
            c[0] = 1.0;
            /* insert the knots of Us[s..e] that tau lacks (multiset difference) */
            double tau[NB_LOCAL];
            memcpy(tau, L, (size_t)nt * sizeof(double));
            for (int k = s, q = 0; k <= e; k++) {
                if (q < nt && tau[q] == Us[k])
                    q++;
                else
                    nb_local_insert(L, &m, c, p + 1, Us[k]);
            }
            if (m != mfin) { /* cannot happen: tau is a sub-multiset of Us[s..e] */
                free(Us);
                free(Q);
                return C2B_ERR_NUMERIC;
            }
            for (int l = 0; l < m; l++)
                w[l] += c[l];
        }
        const double *Pi = P + (size_t)i * D;
        for (int l = 0; l < mfin; l++) {
            double f = w[l] / (p + 1);
            if (f == 0.0)
                continue;
            double *R = Q + (size_t)(s + l) * D;
            for (size_t x = 0; x < D; x++)
                R[x] += f * Pi[x];
        }
    }
    free(d->U);
    free(*Pp);
    d->U = Us;
    *Pp = Q;
    d->p = p + 1;
    d->n = ns;
    d->nw = ns;
    d->nk = nks;
    return C2B_OK;
}

/* Raise the degree of a clamped direction by t, one degree at a time. */
static c2b_status nb_elevate_clamped(nb_dir *d, double **Pp, size_t D, int t)
{
    for (int r = 0; r < t; r++) {
        c2b_status st = nb_elevate_one(d, Pp, D);
        if (st)
            return st;
    }
    return C2B_OK;
}

/* Common argument checks of insert/elevate. */
static c2b_status nb_check_insert(const nb_dir *d, double t, int times, double *tt, const char *name,
                                  c2b_error *err)
{
    char s0[32];
    if (times < 0)
        return c2b_error_set(err, C2B_ERR_ARG, "knot insertion: times must be >= 0, got %d", times);
    c2b_status st = nb_map(d, t, tt, name, err);
    if (st)
        return st;
    int s = nb_mult(d, *tt);
    if (s + times > d->p)
        return c2b_error_set(err, C2B_ERR_ARG,
                             "knot insertion: %s = %s has multiplicity %d; inserting it %d times "
                             "would exceed the degree %d",
                             name, nb_num(*tt, s0, sizeof s0), s, times, d->p);
    if ((long)d->n + times > C2B_NURBS_MAX_POLES)
        return c2b_error_set(err, C2B_ERR_LIMIT, "knot insertion: more than %d poles",
                             C2B_NURBS_MAX_POLES);
    return C2B_OK;
}

static c2b_status nb_check_elevate(const nb_dir *d, int times, const char *what, c2b_error *err)
{
    if (times < 0)
        return c2b_error_set(err, C2B_ERR_ARG, "degree elevation: times must be >= 0, got %d", times);
    if (d->periodic && times > 0)
        return c2b_error_set(err, C2B_ERR_ARG,
                             "degree elevation of a periodic %s is not supported", what);
    if (d->p + times > MAXP)
        return c2b_error_set(err, C2B_ERR_ARG, "degree elevation: degree %d + %d exceeds %d", d->p,
                             times, MAXP);
    /* pole count after elevation: at most n (after clamping) + times * spans */
    long spans = 0;
    for (int i = d->p; i < d->nw; i++)
        if (d->U[i] < d->U[i + 1])
            spans++;
    if ((long)d->n + (long)times * (spans + 1) > C2B_NURBS_MAX_POLES)
        return c2b_error_set(err, C2B_ERR_LIMIT, "degree elevation: more than %d poles",
                             C2B_NURBS_MAX_POLES);
    return C2B_OK;
}

/* Distinct homogeneous poles of a curve (copy). */
static double *nb_curve_items(const c2b_nurbs_curve *c)
{
    double *P = malloc(4 * (size_t)c->d.n * sizeof(double));
    if (P)
        memcpy(P, c->pw, 4 * (size_t)c->d.n * sizeof(double));
    return P;
}

/* Install new distinct homogeneous poles P (n items of 4) and direction d in curve c. */
static c2b_status nb_curve_install(c2b_nurbs_curve *c, nb_dir *d, double *P)
{
    size_t nw = (size_t)d->nw;
    double *pw = malloc(4 * nw * sizeof(double));
    double *cart = malloc(4 * nw * sizeof(double));
    if (!pw || !cart) {
        free(pw);
        free(cart);
        return C2B_ERR_NOMEM;
    }
    for (size_t i = 0; i < nw; i++)
        memcpy(pw + 4 * i, P + 4 * (i % (size_t)d->n), 4 * sizeof(double));
    nb_from_homog(pw, cart, nw, c->rational ? 0.0 : c->cart[3]);
    free(c->pw);
    free(c->cart);
    free(c->d.U);
    c->pw = pw;
    c->cart = cart;
    c->d = *d;
    c->rational = nb_is_rational(cart, nw);
    return C2B_OK;
}

/* Distinct homogeneous poles of direction dir as items: item i (i < n_dir) holds the
 * stored (unwrapped) poles of the other direction, D = 4 * nw_other. */
static double *nb_surface_items(const c2b_nurbs_surface *s, int dir, size_t *D)
{
    size_t nwu = (size_t)s->d[0].nw, nwv = (size_t)s->d[1].nw;
    size_t n = (size_t)s->d[dir].n;
    size_t other = dir == 0 ? nwv : nwu;
    *D = 4 * other;
    double *P = malloc(n * *D * sizeof(double));
    if (!P)
        return NULL;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < other; j++) {
            size_t src = dir == 0 ? i * nwv + j : j * nwv + i;
            memcpy(P + i * *D + 4 * j, s->pw + 4 * src, 4 * sizeof(double));
        }
    return P;
}

static c2b_status nb_surface_install(c2b_nurbs_surface *s, int dir, nb_dir *d, double *P, size_t D)
{
    size_t nwd = (size_t)d->nw, other = D / 4;
    size_t cnt = 4 * nwd * other;
    double *pw = malloc(cnt * sizeof(double));
    double *cart = malloc(cnt * sizeof(double));
    if (!pw || !cart) {
        free(pw);
        free(cart);
        return C2B_ERR_NOMEM;
    }
    for (size_t i = 0; i < nwd; i++)
        for (size_t j = 0; j < other; j++) {
            size_t dst = dir == 0 ? i * other + j : j * nwd + i;
            memcpy(pw + 4 * dst, P + (i % (size_t)d->n) * D + 4 * j, 4 * sizeof(double));
        }
    nb_from_homog(pw, cart, cnt / 4, s->rational ? 0.0 : s->cart[3]);
    free(s->pw);
    free(s->cart);
    free(s->d[dir].U);
    s->pw = pw;
    s->cart = cart;
    s->d[dir] = *d;
    s->rational = nb_is_rational(cart, cnt / 4);
    return C2B_OK;
}

/* The object a knot insertion or degree elevation changes: a curve (c), or direction dir
 * of a surface (s). */
typedef struct nb_owner {
    c2b_nurbs_curve *c;
    c2b_nurbs_surface *s;
    int dir;
} nb_owner;

/* `times` insertions of knot t into o's direction or, when `elevate`, `times` degree
 * elevations of it (after clamping), made on copies of its knots and distinct poles and
 * installed in o only when all succeed: on failure o is unchanged. Arguments checked. */
static c2b_status nb_edit(nb_owner o, int elevate, double t, int times, c2b_error *err)
{
    const nb_dir *src = o.c ? &o.c->d : &o.s->d[o.dir];
    size_t D = 4;
    double *P = o.c ? nb_curve_items(o.c) : nb_surface_items(o.s, o.dir, &D);
    nb_dir d = *src;
    d.U = nb_knots_dup(src->U, src->nk);
    c2b_status st = !d.U || !P ? C2B_ERR_NOMEM : C2B_OK;
    if (!st && elevate && !(st = nb_clamp(&d, &P, D)))
        st = nb_elevate_clamped(&d, &P, D, times);
    for (int r = 0; !st && !elevate && r < times; r++)
        st = nb_insert_once(&d, &P, D, t);
    if (!st)
        st = o.c ? nb_curve_install(o.c, &d, P) : nb_surface_install(o.s, o.dir, &d, P, D);
    free(P);
    if (!st)
        return C2B_OK;
    free(d.U);
    if (!elevate)
        return c2b_error_set(err, st, "knot insertion: out of memory");
    return c2b_error_set(err, st, st == C2B_ERR_NOMEM ? "degree elevation: out of memory"
                                                       : "degree elevation: internal inconsistency");
}

c2b_status c2b_nurbs_curve_insert_knot(c2b_nurbs_curve *c, double t, int times, c2b_error *err)
{
    if (!c)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_curve_insert_knot: NULL curve");
    double tt;
    c2b_status st = nb_check_insert(&c->d, t, times, &tt, "t", err);
    if (st || times == 0)
        return st;
    return nb_edit((nb_owner){c, NULL, 0}, 0, tt, times, err);
}

c2b_status c2b_nurbs_curve_elevate(c2b_nurbs_curve *c, int times, c2b_error *err)
{
    if (!c)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_curve_elevate: NULL curve");
    c2b_status st = nb_check_elevate(&c->d, times, "curve", err);
    if (st || times == 0)
        return st;
    return nb_edit((nb_owner){c, NULL, 0}, 1, 0.0, times, err);
}

/* ---- projection -------------------------------------------------------------------------- */

static double nb_dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double nb_dist2(const double *S, const double *P)
{
    double r[3] = {S[0] - P[0], S[1] - P[1], S[2] - P[2]};
    return nb_dot3(r, r);
}

/* Keep the best `nc` (value, parameter) candidates in ascending order. */
static void nb_keep(double *best, double (*par)[2], int nc, double f, double u, double v)
{
    if (!(f < best[nc - 1]))
        return;
    int i = nc - 1;
    while (i > 0 && f < best[i - 1]) {
        best[i] = best[i - 1];
        par[i][0] = par[i - 1][0];
        par[i][1] = par[i - 1][1];
        i--;
    }
    best[i] = f;
    par[i][0] = u;
    par[i][1] = v;
}

/* Next sample parameter list of a direction: `per` samples per non-empty span in the
 * domain (plus the domain end when not periodic). Returns the count; writes into buf when
 * non-NULL. */
static long nb_samples(const nb_dir *d, int per, double *buf)
{
    long cnt = 0;
    for (int i = d->p; i < d->nw; i++) {
        double a = d->U[i], b = d->U[i + 1];
        if (!(b > a))
            continue;
        for (int j = 0; j < per; j++) {
            if (buf)
                buf[cnt] = a + (b - a) * j / per;
            cnt++;
        }
    }
    if (!d->periodic) {
        if (buf)
            buf[cnt] = nb_dom1(d);
        cnt++;
    }
    return cnt;
}

/* Apply a parameter move: wrap (periodic) or clamp (open). */
static double nb_move(const nb_dir *d, double t)
{
    return nb_map_quiet(d, t);
}

/* What a projection is onto: a curve (n = 1, c) or a surface (n = 2, s), with its n
 * parametric directions d. */
typedef struct nb_target {
    int n;
    const nb_dir *d;
    const c2b_nurbs_curve *c;
    const c2b_nurbs_surface *s;
} nb_target;

/* The target's point at parameters x (in its domain) in S[0] and, when `second`, its
 * first derivatives in S[1 + k] and its second derivatives in S[1 + n + k + l], k <= l:
 * C, C', C'' for a curve; S, Su, Sv, Suu, Suv, Svv for a surface. */
static void nb_target_eval(const nb_target *g, const double *x, int second, double S[6][3])
{
    int nd = second ? 2 : 0;
    if (g->c) {
        nb_curve_eval_raw(g->c, x[0], nd, &S[0][0]);
        return;
    }
    static const int at[6] = {0, 3, 1, 6, 4, 2}; /* skl index / 3 of S, Su, Sv, Suu, Suv, Svv */
    double skl[3 * 3 * 3];
    nb_surface_eval_raw(g->s, x[0], x[1], nd, nd, nd, skl);
    for (int i = 0; i < (second ? 6 : 1); i++)
        memcpy(S[i], skl + 3 * at[i], 3 * sizeof(double));
}

/* Newton on f(x) = |S(x) - P|^2 / 2 from x with the full Hessian
 *   H_kl = S_k.S_l + r.S_kl,  r = S - P,
 * a Gauss-Newton fallback (J_kl = S_k.S_l) where H is not positive definite, bound
 * handling by holding a parameter at a non-periodic bound whose gradient points outward,
 * a move along the better-conditioned direction alone where the 2 x 2 system is
 * singular, and a halving line search for steps beyond NB_PROJ_LOCAL. Returns the final
 * x and squared distance. */
static void nb_newton(const nb_target *g, const double *P, double *xp, double *fp)
{
    int n = g->n;
    const nb_dir *d = g->d;
    double len[2] = {1.0, 1.0}, x[2] = {0.0, 0.0}, S[6][3], Sn[6][3];
    for (int k = 0; k < n; k++) {
        len[k] = nb_dom1(&d[k]) - nb_dom0(&d[k]);
        x[k] = xp[k];
    }
    nb_target_eval(g, x, 1, S);
    double f = nb_dist2(S[0], P);
    for (int it = 0; it < NB_PROJ_MAX_ITER; it++) {
        double r[3] = {S[0][0] - P[0], S[0][1] - P[1], S[0][2] - P[2]};
        double gr[2] = {0.0, 0.0}, J[2][2] = {{0.0}}, H[2][2] = {{0.0}};
        int freev[2] = {0, 0};
        for (int k = 0; k < n; k++) {
            gr[k] = nb_dot3(r, S[1 + k]);
            for (int l = 0; l < n; l++) {
                J[k][l] = nb_dot3(S[1 + k], S[1 + l]);
                H[k][l] = J[k][l] + nb_dot3(r, S[1 + n + k + l]);
            }
            freev[k] = d[k].periodic || !((x[k] <= nb_dom0(&d[k]) && gr[k] > 0) ||
                                          (x[k] >= nb_dom1(&d[k]) && gr[k] < 0));
        }
        double step[2] = {0.0, 0.0};
        if (freev[0] && freev[1]) {
            double det = H[0][0] * H[1][1] - H[0][1] * H[1][0];
            const double(*M)[2] = H;
            if (!(H[0][0] > 0 && det > 0)) {
                M = J;
                det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            }
            if (det > 1e-300 && det > 1e-14 * M[0][0] * M[1][1]) {
                step[0] = -(M[1][1] * gr[0] - M[0][1] * gr[1]) / det;
                step[1] = -(M[0][0] * gr[1] - M[1][0] * gr[0]) / det;
            } else {
                int k = J[0][0] >= J[1][1] ? 0 : 1;
                freev[1 - k] = 0;
            }
        }
        if (freev[0] != freev[1]) {
            int k = freev[0] ? 0 : 1;
            double h = H[k][k] > 0 ? H[k][k] : J[k][k];
            if (h > 0)
                step[k] = -gr[k] / h;
        }
        if (step[0] == 0 && step[1] == 0)
            break;
        int local = 1;
        for (int k = 0; k < n; k++) {
            if (fabs(step[k]) > 0.5 * len[k])
                step[k] = step[k] > 0 ? 0.5 * len[k] : -0.5 * len[k];
            local = local && fabs(step[k]) <= NB_PROJ_LOCAL * len[k];
        }
        double xn[2] = {x[0], x[1]}, fn = f;
        int accepted = 0;
        double lam = 1.0;
        for (int ls = 0; ls < 60 && !accepted; ls++, lam *= 0.5) {
            for (int k = 0; k < n; k++)
                xn[k] = nb_move(&d[k], x[k] + lam * step[k]);
            nb_target_eval(g, xn, 1, Sn);
            fn = nb_dist2(Sn[0], P);
            accepted = local || fn < f; /* a local step is taken as it is */
        }
        if (!accepted)
            break;
        int small = 1;
        for (int k = 0; k < n; k++) {
            double moved = fabs(xn[k] - x[k]);
            if (d[k].periodic && moved > 0.5 * len[k])
                moved = len[k] - moved;
            if (moved > NB_PROJ_STEP_TOL * len[k])
                small = 0;
        }
        memcpy(x, xn, sizeof x);
        f = fn;
        memcpy(S, Sn, sizeof S);
        if (small)
            break;
    }
    for (int k = 0; k < n; k++)
        xp[k] = x[k];
    *fp = f;
}

/* The closest point of the target to `point`: its parameters in x[0 .. n-1] and the
 * distance (dist may be NULL). The candidates are the NB_PROJ_CANDIDATES nearest of a grid
 * of NB_PROJ_PER_SPAN samples per knot span and direction (fewer per span, then a stride
 * over them, when the grid would exceed NB_PROJ_MAX_GRID points), each refined by
 * nb_newton. */
static c2b_status nb_project(const nb_target *g, const double *point, double *x, double *dist,
                             c2b_error *err)
{
    char s0[32], s1[32], s2[32];
    if (!isfinite(point[0]) || !isfinite(point[1]) || !isfinite(point[2]))
        return c2b_error_set(err, C2B_ERR_ARG, "projection: point (%s, %s, %s) is not finite",
                             nb_num(point[0], s0, sizeof s0), nb_num(point[1], s1, sizeof s1),
                             nb_num(point[2], s2, sizeof s2));
    int n = g->n;
    const nb_dir *d = g->d;
    int per[2] = {NB_PROJ_PER_SPAN, n == 2 ? NB_PROJ_PER_SPAN : 1};
    long cnt[2] = {1, 1}, stride[2] = {1, 1};
    for (int k = 0; k < n; k++)
        cnt[k] = nb_samples(&d[k], per[k], NULL);
    while (cnt[0] * cnt[1] > NB_PROJ_MAX_GRID && (per[0] > 1 || per[1] > 1)) {
        int k = (per[0] > 1 && (cnt[0] >= cnt[1] || per[1] == 1)) ? 0 : 1;
        cnt[k] = nb_samples(&d[k], --per[k], NULL);
    }
    /* with one sample per span and still too many, stride over the samples */
    for (int k = 0; k < n; k++)
        while ((cnt[0] / stride[0] + 1) * (cnt[1] / stride[1] + 1) > NB_PROJ_MAX_GRID &&
               cnt[k] / stride[k] > 1000)
            stride[k] *= 2;
    double *su = malloc((size_t)(cnt[0] + cnt[1]) * sizeof(double));
    if (!su)
        return c2b_error_set(err, C2B_ERR_NOMEM, "projection: out of memory");
    double *sv = su + cnt[0];
    sv[0] = 0.0;
    for (int k = 0; k < n; k++)
        nb_samples(&d[k], per[k], k ? sv : su);
    double best[NB_PROJ_CANDIDATES], par[NB_PROJ_CANDIDATES][2];
    for (int i = 0; i < NB_PROJ_CANDIDATES; i++) {
        best[i] = INFINITY;
        par[i][0] = nb_dom0(&d[0]);
        par[i][1] = n == 2 ? nb_dom0(&d[1]) : 0.0;
    }
    double S[6][3];
    for (long i = 0; i < cnt[0]; i += stride[0])
        for (long j = 0; j < cnt[1]; j += stride[1]) {
            double at[2] = {su[i], sv[j]};
            nb_target_eval(g, at, 0, S);
            nb_keep(best, par, NB_PROJ_CANDIDATES, nb_dist2(S[0], point), at[0], at[1]);
        }
    free(su);
    double bx[2] = {par[0][0], par[0][1]}, bf = INFINITY;
    for (int i = 0; i < NB_PROJ_CANDIDATES && isfinite(best[i]); i++) {
        double xi[2] = {par[i][0], par[i][1]}, f;
        nb_newton(g, point, xi, &f);
        if (f < bf) {
            bf = f;
            memcpy(bx, xi, sizeof bx);
        }
    }
    for (int k = 0; k < n; k++)
        x[k] = bx[k];
    if (dist)
        *dist = sqrt(bf);
    return isfinite(bf) ? C2B_OK
                        : c2b_error_set(err, C2B_ERR_NUMERIC, "projection: no finite distance");
}

c2b_status c2b_nurbs_curve_project(const c2b_nurbs_curve *c, const double *point, double *t,
                                   double *dist, c2b_error *err)
{
    if (!c || !point || !t)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_curve_project: NULL argument");
    nb_target g = {1, &c->d, c, NULL};
    return nb_project(&g, point, t, dist, err);
}

c2b_status c2b_nurbs_surface_project(const c2b_nurbs_surface *s, const double *point,
                                     double *uv, double *dist, c2b_error *err)
{
    if (!s || !point || !uv)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_surface_project: NULL argument");
    nb_target g = {2, s->d, NULL, s};
    return nb_project(&g, point, uv, dist, err);
}

/* ---- surfaces ----------------------------------------------------------------------------- */

c2b_status c2b_nurbs_surface_create_at(int p, int q, int nu, int nv, const double *knots_u,
                                       const double *knots_v, const double *poles,
                                       const int *periodic, const char *path,
                                       c2b_nurbs_surface **out, c2b_error *err)
{
    if (!out)
        return nb_fail(err, C2B_ERR_ARG, path, NULL, "NULL output pointer");
    *out = NULL;
    int per[2] = {periodic ? !!periodic[0] : 0, periodic ? !!periodic[1] : 0};
    c2b_status st = nb_check_dir(p, nu, knots_u, per[0], path, "knots_u", " in u", err);
    if (st)
        return st;
    if ((st = nb_check_dir(q, nv, knots_v, per[1], path, "knots_v", " in v", err)))
        return st;
    if (!poles)
        return nb_fail(err, C2B_ERR_ARG, path, "poles", "NULL pole array");
    char name[64];
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            snprintf(name, sizeof name, "poles[%d][%d]", i, j);
            if ((st = nb_check_pole(poles + 4 * ((size_t)i * (size_t)nv + (size_t)j), path, name, err)))
                return st;
        }
    c2b_nurbs_surface *s = calloc(1, sizeof *s);
    if (!s)
        return nb_fail(err, C2B_ERR_NOMEM, path, NULL, "out of memory creating a surface");
    nb_dir_init(&s->d[0], p, nu, per[0]);
    nb_dir_init(&s->d[1], q, nv, per[1]);
    size_t nwu = (size_t)s->d[0].nw, nwv = (size_t)s->d[1].nw;
    s->d[0].U = nb_knots_dup(knots_u, s->d[0].nk);
    s->d[1].U = nb_knots_dup(knots_v, s->d[1].nk);
    s->cart = malloc(4 * nwu * nwv * sizeof(double));
    s->pw = malloc(4 * nwu * nwv * sizeof(double));
    if (!s->d[0].U || !s->d[1].U || !s->cart || !s->pw) {
        c2b_nurbs_surface_destroy(s);
        return nb_fail(err, C2B_ERR_NOMEM, path, NULL, "out of memory creating a surface");
    }
    for (size_t i = 0; i < nwu; i++)
        for (size_t j = 0; j < nwv; j++) {
            const double *src = poles + 4 * ((i % (size_t)nu) * (size_t)nv + j % (size_t)nv);
            for (int x = 0; x < 4; x++)
                s->cart[4 * (i * nwv + j) + (size_t)x] = src[x] + 0.0;
        }
    nb_homog(s->cart, s->pw, nwu * nwv);
    s->rational = nb_is_rational(s->cart, nwu * nwv);
    *out = s;
    return C2B_OK;
}

c2b_status c2b_nurbs_surface_create(int p, int q, int nu, int nv, const double *knots_u,
                                    const double *knots_v, const double *poles,
                                    const int *periodic, c2b_nurbs_surface **out,
                                    c2b_error *err)
{
    return c2b_nurbs_surface_create_at(p, q, nu, nv, knots_u, knots_v, poles, periodic, NULL, out,
                                       err);
}

void c2b_nurbs_surface_destroy(c2b_nurbs_surface *s)
{
    if (!s)
        return;
    free(s->d[0].U);
    free(s->d[1].U);
    free(s->cart);
    free(s->pw);
    free(s);
}

c2b_status c2b_nurbs_surface_copy(const c2b_nurbs_surface *s, c2b_nurbs_surface **out,
                                  c2b_error *err)
{
    if (!s || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_surface_copy: NULL argument");
    *out = NULL;
    c2b_nurbs_surface *r = calloc(1, sizeof *r);
    if (!r)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory copying a surface");
    size_t cnt = 4 * (size_t)s->d[0].nw * (size_t)s->d[1].nw;
    r->d[0] = s->d[0];
    r->d[1] = s->d[1];
    r->rational = s->rational;
    r->d[0].U = nb_knots_dup(s->d[0].U, s->d[0].nk);
    r->d[1].U = nb_knots_dup(s->d[1].U, s->d[1].nk);
    r->cart = malloc(cnt * sizeof(double));
    r->pw = malloc(cnt * sizeof(double));
    if (!r->d[0].U || !r->d[1].U || !r->cart || !r->pw) {
        c2b_nurbs_surface_destroy(r);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory copying a surface");
    }
    memcpy(r->cart, s->cart, cnt * sizeof(double));
    memcpy(r->pw, s->pw, cnt * sizeof(double));
    *out = r;
    return C2B_OK;
}

void c2b_nurbs_surface_domain(const c2b_nurbs_surface *s, double *dom)
{
    if (!dom)
        return;
    for (int k = 0; k < 2; k++) {
        dom[2 * k] = s ? nb_dom0(&s->d[k]) : NAN;
        dom[2 * k + 1] = s ? nb_dom1(&s->d[k]) : NAN;
    }
}

static int nb_dir_ok(const c2b_nurbs_surface *s, int dir) { return s && (dir == 0 || dir == 1); }

int c2b_nurbs_surface_degree(const c2b_nurbs_surface *s, int dir)
{
    return nb_dir_ok(s, dir) ? s->d[dir].p : 0;
}
int c2b_nurbs_surface_npoles(const c2b_nurbs_surface *s, int dir)
{
    return nb_dir_ok(s, dir) ? s->d[dir].n : 0;
}
int c2b_nurbs_surface_periodic(const c2b_nurbs_surface *s, int dir)
{
    return nb_dir_ok(s, dir) ? s->d[dir].periodic : 0;
}
int c2b_nurbs_surface_nknots(const c2b_nurbs_surface *s, int dir)
{
    return nb_dir_ok(s, dir) ? s->d[dir].nk : 0;
}
const double *c2b_nurbs_surface_knots(const c2b_nurbs_surface *s, int dir)
{
    return nb_dir_ok(s, dir) ? s->d[dir].U : NULL;
}

void c2b_nurbs_surface_pole(const c2b_nurbs_surface *s, int i, int j, double *out)
{
    if (!out)
        return;
    if (!s || i < 0 || j < 0 || i >= s->d[0].n || j >= s->d[1].n) {
        for (int x = 0; x < 4; x++)
            out[x] = NAN;
        return;
    }
    memcpy(out, s->cart + 4 * ((size_t)i * (size_t)s->d[1].nw + (size_t)j), 4 * sizeof(double));
}

c2b_status c2b_nurbs_surface_derivs(const c2b_nurbs_surface *s, double u, double v, int du,
                                    int dv, double *skl, c2b_error *err)
{
    if (!s || !skl)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_surface_derivs: NULL argument");
    if (du < 0 || du > MAXD || dv < 0 || dv > MAXD)
        return c2b_error_set(err, C2B_ERR_ARG, "derivative orders (%d, %d) are outside 0..%d", du,
                             dv, MAXD);
    double uu, vv;
    c2b_status st = nb_map(&s->d[0], u, &uu, "u", err);
    if (st || (st = nb_map(&s->d[1], v, &vv, "v", err)))
        return st;
    nb_surface_eval_raw(s, uu, vv, du, dv, du + dv, skl);
    return C2B_OK;
}

c2b_status c2b_nurbs_surface_eval(const c2b_nurbs_surface *s, double u, double v, int order,
                                  double *out, c2b_error *err)
{
    if (!s || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_surface_eval: NULL argument");
    if (order < 0 || order > MAXD)
        return c2b_error_set(err, C2B_ERR_ARG, "derivative order %d is outside 0..%d", order, MAXD);
    double uu, vv;
    c2b_status st = nb_map(&s->d[0], u, &uu, "u", err);
    if (st || (st = nb_map(&s->d[1], v, &vv, "v", err)))
        return st;
    double skl[(MAXD + 1) * (MAXD + 1) * 3];
    nb_surface_eval_raw(s, uu, vv, order, order, order, skl);
    int idx = 0;
    for (int k = 0; k <= order; k++)
        for (int b = 0; b <= k; b++, idx++)
            for (int x = 0; x < 3; x++)
                out[idx * 3 + x] = skl[((k - b) * (order + 1) + b) * 3 + x];
    return C2B_OK;
}

c2b_status c2b_nurbs_surface_insert_knot(c2b_nurbs_surface *s, int dir, double t, int times,
                                         c2b_error *err)
{
    if (!s || (dir != 0 && dir != 1))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_surface_insert_knot: %s",
                             s ? "dir must be 0 (u) or 1 (v)" : "NULL surface");
    double tt;
    c2b_status st = nb_check_insert(&s->d[dir], t, times, &tt, dir ? "v" : "u", err);
    if (st || times == 0)
        return st;
    return nb_edit((nb_owner){NULL, s, dir}, 0, tt, times, err);
}

c2b_status c2b_nurbs_surface_elevate(c2b_nurbs_surface *s, int dir, int times, c2b_error *err)
{
    if (!s || (dir != 0 && dir != 1))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_nurbs_surface_elevate: %s",
                             s ? "dir must be 0 (u) or 1 (v)" : "NULL surface");
    c2b_status st = nb_check_elevate(&s->d[dir], times, dir ? "direction (v)" : "direction (u)", err);
    if (st || times == 0)
        return st;
    return nb_edit((nb_owner){NULL, s, dir}, 1, 0.0, times, err);
}
