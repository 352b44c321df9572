#include "c2b_vseries.h"

#include <fftw3.h>
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_constants.h"
#include "c2b_lsq.h"
#include "c2b_poly.h"

/* Structure checks use 33 points with an irrational-looking spacing, so that no
 * low-frequency mode can hide in their zeros. */
#define NCHECK 33
#define CHECK_OFFSET 0.0123
#define CHECK_STEP 0.0302

const char *c2b_vmethod_name(c2b_vmethod m)
{
    static const char *const names[] = {"zero", "polynomial", "mode", "fft", "dst"};
    return (unsigned)m < 5 ? names[m] : "?";
}

const char *c2b_vkind_name(c2b_vkind k)
{
    static const char *const names[] = {"pow", "cos", "sin", "expp", "expm"};
    return (unsigned)k < 5 ? names[k] : "?";
}

double c2b_vfunc_beta(const c2b_vfunc *f)
{
    switch (f->kind) {
    case C2B_VF_POW: return 0.0;
    case C2B_VF_COS:
    case C2B_VF_SIN: return -f->omega * f->omega;
    case C2B_VF_EXPP:
    case C2B_VF_EXPM: return f->omega * f->omega;
    }
    return 0.0;
}

double c2b_vfunc_value(const c2b_vfunc *f, double s, double L)
{
    switch (f->kind) {
    case C2B_VF_POW: {
        double p = 1.0;
        for (int j = 0; j < f->power; j++)
            p *= s;
        return p;
    }
    case C2B_VF_COS: return cos(f->omega * s);
    case C2B_VF_SIN: return sin(f->omega * s);
    case C2B_VF_EXPP: return exp(f->omega * (s - L));
    case C2B_VF_EXPM: return exp(-f->omega * s);
    }
    return 0.0;
}

void c2b_vfunc_eval(const c2b_vfunc *f, double s, double L, int maxd, double *out)
{
    for (int q = 0; q <= maxd; q++) {
        c2b_vfunc g;
        double k = c2b_vfunc_derivative(f, q, &g);
        out[q] = k == 0.0 ? 0.0 : k * c2b_vfunc_value(&g, s, L);
    }
}

int c2b_vfunc_same(const c2b_vfunc *a, const c2b_vfunc *b)
{
    if (a->kind != b->kind)
        return 0;
    if (a->kind == C2B_VF_POW)
        return a->power == b->power;
    return fabs(a->omega - b->omega) <= 1e-13 * fmax(a->omega, b->omega);
}

double c2b_vfunc_derivative(const c2b_vfunc *f, int q, c2b_vfunc *g)
{
    *g = *f;
    double w = f->omega, factor = 1.0;
    switch (f->kind) {
    case C2B_VF_POW:
        if (q > f->power)
            return 0.0;
        for (int j = 0; j < q; j++)
            factor *= (double)(f->power - j);
        g->power = f->power - q;
        return factor;
    case C2B_VF_COS:
    case C2B_VF_SIN:
        /* cos -> -w sin -> -w^2 cos -> w^3 sin; sin -> w cos -> -w^2 sin -> -w^3 cos */
        for (int j = 0; j < q; j++)
            factor *= w;
        if (q % 2)
            g->kind = f->kind == C2B_VF_COS ? C2B_VF_SIN : C2B_VF_COS;
        if ((f->kind == C2B_VF_COS && (q % 4 == 1 || q % 4 == 2)) ||
            (f->kind == C2B_VF_SIN && (q % 4 == 2 || q % 4 == 3)))
            factor = -factor;
        return factor;
    case C2B_VF_EXPP:
    case C2B_VF_EXPM:
        for (int j = 0; j < q; j++)
            factor *= f->kind == C2B_VF_EXPP ? w : -w;
        return factor;
    }
    return 0.0;
}

int c2b_vfunc_compare(const c2b_vfunc *a, const c2b_vfunc *b)
{
    int pa = a->kind == C2B_VF_POW, pb = b->kind == C2B_VF_POW;
    if (pa != pb)
        return pb - pa;
    if (pa)
        return (a->power > b->power) - (a->power < b->power);
    if (a->omega != b->omega)
        return a->omega < b->omega ? -1 : 1;
    return (int)a->kind - (int)b->kind;
}

void c2b_vseries_clear(c2b_vseries *s)
{
    if (!s)
        return;
    free(s->terms);
    memset(s, 0, sizeof *s);
}

static int add_term(c2b_vseries *s, c2b_vkind kind, int power, double omega, double amp)
{
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 16;
        c2b_vterm *t = realloc(s->terms, (size_t)cap * sizeof *t);
        if (!t)
            return -1;
        s->terms = t;
        s->cap = cap;
    }
    c2b_vterm *t = &s->terms[s->n++];
    t->f.kind = kind;
    t->f.power = power;
    t->f.omega = omega;
    t->amp = amp;
    return 0;
}

void c2b_vseries_eval(const c2b_vseries *s, const c2b_vdomain *dom, double v, int maxd,
                      double *out)
{
    double L = dom->v1 - dom->v0, tmp[4];
    for (int q = 0; q <= maxd; q++)
        out[q] = 0.0;
    for (int i = 0; i < s->n; i++) {
        c2b_vfunc_eval(&s->terms[i].f, v - dom->v0, L, maxd, tmp);
        for (int q = 0; q <= maxd; q++)
            out[q] += s->terms[i].amp * tmp[q];
    }
}

/* Evaluate f and insist on a finite value. */
static c2b_status sample(c2b_vt_fn f, void *ctx, double v, double t, double *out,
                         c2b_error *err)
{
    double y = f(ctx, v, t);
    *out = y;
    if (!isfinite(y))
        return c2b_error_set(err, C2B_ERR_SPEC, "value is not finite (%g) at v=%.17g, t=%.17g",
                             y, v, t);
    return C2B_OK;
}

static double horner(const double *c, int deg, double x)
{
    double a = 0.0;
    for (int i = deg; i >= 0; i--)
        a = a * x + c[i];
    return a;
}

/* Exact structure: polynomial of low degree. */
static c2b_status try_polynomial(const c2b_vdomain *dom, c2b_vt_fn f, void *ctx, double t,
                                 const c2b_tolerances *tol, const double *xc,
                                 const double *yc, double scale, c2b_vseries *out,
                                 int *found, c2b_error *err)
{
    double L = dom->v1 - dom->v0;
    *found = 0;
    int dmax = tol->max_poly_degree < C2B_POLY_MAX_DEG ? tol->max_poly_degree : C2B_POLY_MAX_DEG;
    for (int d = 0; d <= dmax; d++) {
        int np = d + 1;
        double x[C2B_POLY_MAX_DEG + 1], y[C2B_POLY_MAX_DEG + 1], coef[C2B_POLY_MAX_DEG + 1];
        for (int j = 0; j < np; j++) {
            x[j] = c2b_poly_cheb_node(j, np);
            c2b_status st = sample(f, ctx, dom->v0 + x[j] * L, t, &y[j], err);
            if (st)
                return st;
        }
        c2b_poly_interpolate(np, x, y, coef);
        double e = 0.0;
        for (int i = 0; i < NCHECK; i++)
            e = fmax(e, fabs(horner(coef, d, xc[i]) - yc[i]));
        out->n_samples += np;
        if (e <= tol->structure_rel * scale) {
            double Lm = 1.0;
            for (int m = 0; m <= d; m++) {
                if (coef[m] != 0.0 && add_term(out, C2B_VF_POW, m, 0.0, coef[m] / Lm))
                    return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
                Lm *= L;
            }
            out->method = C2B_VM_POLY;
            out->err_abs = e;
            *found = 1;
            return C2B_OK;
        }
    }
    return C2B_OK;
}

/* Highest degree of the polynomial that try_mode() accepts beside the pair of modes. */
#define MODE_POLY_DEG 3

/* Exact structure: a polynomial of degree < p (p <= MODE_POLY_DEG + 1) plus one pair of
 * modes of one beta (cos/sin or the two exponentials), for the smallest p that fits.
 * The p-th differences of the check points (uniform spacing h) remove the polynomial
 * and keep the modes, whose neighbours satisfy z[i-1] + z[i+1] = 2 c z[i] with
 * c = cos(w h) or cosh(w h). The amplitudes come from least squares on the check
 * points and are verified at fresh points. */
static c2b_status try_mode(const c2b_vdomain *dom, c2b_vt_fn f, void *ctx, double t,
                           const c2b_tolerances *tol, const double *xc, const double *yc,
                           double scale, c2b_vseries *out, int *found, c2b_error *err)
{
    double L = dom->v1 - dom->v0, h = CHECK_STEP * L;
    *found = 0;
    for (int p = 0; p <= MODE_POLY_DEG + 1; p++) {
        double z[NCHECK], num = 0, den = 0, res = 0;
        int nz = NCHECK - p;
        memcpy(z, yc, sizeof z);
        for (int k = 0; k < p; k++)
            for (int i = 0; i < NCHECK - 1 - k; i++)
                z[i] = z[i + 1] - z[i];
        for (int i = 1; i < nz - 1; i++) {
            num += z[i] * (z[i - 1] + z[i + 1]);
            den += 2 * z[i] * z[i];
        }
        if (den == 0)
            continue;
        double c = num / den;
        for (int i = 1; i < nz - 1; i++)
            res = fmax(res, fabs(z[i - 1] + z[i + 1] - 2 * c * z[i]));
        if (res > tol->structure_rel * scale * (1 << p) || c < -1 || c == 1)
            continue;
        int trig = c < 1;
        double w = trig ? acos(c) / h : acosh(c) / h;
        c2b_vfunc fa = {trig ? C2B_VF_COS : C2B_VF_EXPP, 0, w};
        c2b_vfunc fb = {trig ? C2B_VF_SIN : C2B_VF_EXPM, 0, w};
        /* columns: x^m (m < p, x = s / L in [0, 1]), then the two modes */
        int nc = p + 2, rank;
        double A[NCHECK * (MODE_POLY_DEG + 3)], b[NCHECK], coef[MODE_POLY_DEG + 3];
        for (int i = 0; i < NCHECK; i++) {
            for (int m = 0; m < p; m++)
                A[m * NCHECK + i] = pow(xc[i], m);
            c2b_vfunc_eval(&fa, xc[i] * L, L, 0, &A[p * NCHECK + i]);
            c2b_vfunc_eval(&fb, xc[i] * L, L, 0, &A[(p + 1) * NCHECK + i]);
            b[i] = yc[i];
        }
        c2b_status st = c2b_lsq_solve(NCHECK, nc, A, b, 1e-13, coef, &rank, NULL,
                                      "boundary data as polynomial and modes", err);
        if (st)
            return st;
        if (rank < nc)
            continue;
        /* Verify at fresh points. */
        double e = 0;
        for (int i = 0; i < 16; i++) {
            double x = (i + 0.5) / 16.0, y, va, vb, poly = 0;
            st = sample(f, ctx, dom->v0 + x * L, t, &y, err);
            if (st)
                return st;
            c2b_vfunc_eval(&fa, x * L, L, 0, &va);
            c2b_vfunc_eval(&fb, x * L, L, 0, &vb);
            for (int m = p - 1; m >= 0; m--)
                poly = poly * x + coef[m];
            e = fmax(e, fabs(poly + coef[p] * va + coef[p + 1] * vb - y));
        }
        out->n_samples += 16;
        if (e > 10 * tol->structure_rel * scale)
            continue;
        for (int m = 0; m < p; m++)
            if (coef[m] != 0 && add_term(out, C2B_VF_POW, m, 0.0, coef[m] / pow(L, m)))
                return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        if ((coef[p] != 0 && add_term(out, fa.kind, 0, w, coef[p])) ||
            (coef[p + 1] != 0 && add_term(out, fb.kind, 0, w, coef[p + 1])))
            return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        out->method = C2B_VM_MODE;
        out->err_abs = e;
        *found = 1;
        return C2B_OK;
    }
    return C2B_OK;
}

/* Amplitude below which a series term is dropped: drop_rel times the half-range of the n
 * values y (stride apart), which moving the part does not change, but at least the
 * rounding of their magnitude (DBL_EPSILON times max |y|), below which terms are noise.
 * Relative to max |y| instead, a trimline 933 from the origin lost sine terms of 1e-11
 * whose slopes (times k pi / L) tilted the blend's normal at the end of a 0.77 long run
 * by 1.4e-8 rad (1.1e-9 with every term kept). */
static double drop_level(const double *y, ptrdiff_t stride, int n, double drop_rel)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; i++) {
        lo = fmin(lo, y[i * stride]);
        hi = fmax(hi, y[i * stride]);
    }
    return fmax(drop_rel * 0.5 * (hi - lo), DBL_EPSILON * fmax(fabs(lo), fabs(hi)));
}

/* Periodic: amplitudes from n samples (n even or odd), dropping small ones.
 * spec: fftw output buffer of n/2+1. Terms appended to out. */
static int fft_terms(const fftw_complex *X, int n, double L, double drop, c2b_vseries *out)
{
    double a0 = X[0][0] / n;
    if (fabs(a0) > drop && add_term(out, C2B_VF_POW, 0, 0.0, a0))
        return -1;
    for (int k = 1; k <= n / 2; k++) {
        int nyq = 2 * k == n;
        double a = (nyq ? 1.0 : 2.0) * X[k][0] / n, b = nyq ? 0.0 : -2.0 * X[k][1] / n;
        double w = 2.0 * C2B_PI * k / L;
        if (fabs(a) > drop && add_term(out, C2B_VF_COS, 0, w, a))
            return -1;
        if (fabs(b) > drop && add_term(out, C2B_VF_SIN, 0, w, b))
            return -1;
    }
    return 0;
}

/* Values of a periodic series (no POW terms except the constant) at n points
 * s_j = j L / n, using an inverse real FFT. */
static int periodic_values(const c2b_vseries *s, double L, int n, double *vals)
{
    fftw_complex *Y = fftw_alloc_complex((size_t)n / 2 + 1);
    if (!Y)
        return -1;
    memset(Y, 0, sizeof(fftw_complex) * ((size_t)n / 2 + 1));
    for (int i = 0; i < s->n; i++) {
        const c2b_vterm *t = &s->terms[i];
        if (t->f.kind == C2B_VF_POW) {
            Y[0][0] += t->amp;
            continue;
        }
        int k = (int)lround(t->f.omega * L / (2.0 * C2B_PI));
        if (k > n / 2)
            continue;
        double f = 2 * k == n ? 1.0 : 0.5;
        if (t->f.kind == C2B_VF_COS)
            Y[k][0] += f * t->amp;
        else
            Y[k][1] -= f * t->amp;
    }
    fftw_plan p = fftw_plan_dft_c2r_1d(n, Y, vals, FFTW_ESTIMATE);
    fftw_execute(p);
    fftw_destroy_plan(p);
    fftw_free(Y);
    return 0;
}

/* Largest |series - f| at the off-grid check points: a dyadic sampling grid cannot
 * tell a mode from its alias, these points can. */
static double offgrid_error(const c2b_vseries *s, const c2b_vdomain *dom, const double *xc,
                            const double *yc)
{
    double L = dom->v1 - dom->v0, e = 0;
    for (int i = 0; i < NCHECK; i++) {
        double y;
        c2b_vseries_eval(s, dom, dom->v0 + xc[i] * L, 0, &y);
        e = fmax(e, fabs(y - yc[i]));
    }
    return e;
}

static c2b_status project_fft(const c2b_vdomain *dom, c2b_vt_fn f, void *ctx, double t,
                              const c2b_tolerances *tol, const double *xc, const double *yc,
                              c2b_vseries *out, c2b_error *err)
{
    double L = dom->v1 - dom->v0;
    int n = 64;
    size_t cap = (size_t)tol->max_samples * 2;
    double *x = fftw_alloc_real(cap), *vals = fftw_alloc_real(cap);
    fftw_complex *X = fftw_alloc_complex(cap / 2 + 1);
    c2b_status st = C2B_OK;
    if (!x || !vals || !X) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        goto done;
    }
    for (int i = 0; i < n && !st; i++)
        st = sample(f, ctx, dom->v0 + i * L / n, t, &x[i], err);
    for (;;) {
        if (st)
            goto done;
        double scale = 0;
        for (int i = 0; i < n; i++)
            scale = fmax(scale, fabs(x[i]));
        fftw_plan p = fftw_plan_dft_r2c_1d(n, x, X, FFTW_ESTIMATE | FFTW_PRESERVE_INPUT);
        fftw_execute(p);
        fftw_destroy_plan(p);
        out->n = 0;
        if (fft_terms(X, n, L, drop_level(x, 1, n, tol->drop_rel), out)) {
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
            goto done;
        }
        /* Truncated series on the doubled grid against f at the midpoints. */
        if (periodic_values(out, L, 2 * n, vals)) {
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
            goto done;
        }
        double e = 0;
        for (int j = 0; j < n; j++) {
            double ym;
            st = sample(f, ctx, dom->v0 + (j + 0.5) * L / n, t, &ym, err);
            if (st)
                goto done;
            e = fmax(e, fabs(vals[2 * j + 1] - ym));
            e = fmax(e, fabs(vals[2 * j] - x[j]));
            vals[2 * j + 1] = ym; /* keep the midpoint samples for the next level */
            scale = fmax(scale, fabs(ym));
        }
        e = fmax(e, offgrid_error(out, dom, xc, yc));
        out->scale = scale;
        out->err_abs = e;
        out->n_samples = n;
        out->method = C2B_VM_FFT;
        if (e <= tol->truncation_rel * scale || 2 * n > tol->max_samples)
            break;
        for (int j = 0; j < n; j++) {
            double ym = vals[2 * j + 1];
            vals[2 * j] = x[j];
            vals[2 * j + 1] = ym;
        }
        memcpy(x, vals, sizeof(double) * 2 * (size_t)n);
        n *= 2;
    }
done:
    fftw_free(x);
    fftw_free(vals);
    fftw_free(X);
    return st;
}

/* Degree of the end polynomial subtracted from open data before the sine series. */
#define END_DEG 5

/* Quintic in s (s-monomials c[0..5]) matching the value f, second derivative g and
 * fourth derivative q at s = 0 (index 0) and s = L (index 1). The remainder then
 * vanishes with its even derivatives up to the fourth at both ends, so its odd
 * extension is C5 and its sine coefficients decay like k^-7: the series and its first
 * derivatives converge fast up to the ends, where a blend meets its neighbour. */
static void end_poly(const double f[2], const double g[2], const double q[2], double L,
                     double *c)
{
    c[4] = q[0] / 24;
    c[5] = (q[1] - q[0]) / (120 * L);
    c[2] = g[0] / 2;
    c[3] = (g[1] - g[0] - 12 * c[4] * L * L - 20 * c[5] * L * L * L) / (6 * L);
    c[0] = f[0];
    c[1] = (f[1] - f[0] - L * L * (c[2] + L * (c[3] + L * (c[4] + L * c[5])))) / L;
}

/* Sine coefficients b_k (k = 1..n-1) of interior remainder r[1..n-1]. */
static void dst_coefficients(double *r_interior, int n, double *b)
{
    fftw_plan p = fftw_plan_r2r_1d(n - 1, r_interior, b, FFTW_RODFT00, FFTW_ESTIMATE);
    fftw_execute(p);
    fftw_destroy_plan(p);
    for (int k = 0; k < n - 1; k++)
        b[k] /= n;
}

/* Append end-polynomial + sine terms, dropping small sine amplitudes. */
static int dst_terms(const double *poly, const double *b, int n, double L, double drop,
                     c2b_vseries *out)
{
    out->n = 0;
    for (int m = 0; m <= END_DEG; m++)
        if (poly[m] != 0.0 && add_term(out, C2B_VF_POW, m, 0.0, poly[m]))
            return -1;
    for (int k = 1; k < n; k++)
        if (fabs(b[k - 1]) > drop && add_term(out, C2B_VF_SIN, 0, C2B_PI * k / L, b[k - 1]))
            return -1;
    return 0;
}

/* Sine part of a series at s_j = j L / n, j = 1..n-1 (values into vals[j-1]). */
static int sine_values(const c2b_vseries *s, double L, int n, double *vals)
{
    double *b = fftw_alloc_real((size_t)n);
    if (!b)
        return -1;
    memset(b, 0, sizeof(double) * (size_t)n);
    for (int i = 0; i < s->n; i++)
        if (s->terms[i].f.kind == C2B_VF_SIN) {
            int k = (int)lround(s->terms[i].f.omega * L / C2B_PI);
            if (k >= 1 && k < n)
                b[k - 1] += s->terms[i].amp;
        }
    fftw_plan p = fftw_plan_r2r_1d(n - 1, b, vals, FFTW_RODFT00, FFTW_ESTIMATE);
    fftw_execute(p);
    fftw_destroy_plan(p);
    for (int j = 0; j < n - 1; j++)
        vals[j] *= 0.5;
    fftw_free(b);
    return 0;
}

/* Points of the one-sided difference stencils at each end: second derivatives (order
 * 6; fewer points when fewer samples) and fourth derivatives (order 8). */
#define END_STENCIL2 8
#define END_STENCIL4 12

/* Derivative `order` at the start of a uniform sequence of spacing h, from its first
 * npts values (stride apart): the one-sided difference of the highest accuracy on
 * npts points, order npts - order. Weights by Fornberg's recursion over the nodes
 * 0, 1, ..., npts - 1 (Math. Comp. 51, 1988). */
static double end_derivative(const double *y, int stride, int npts, int order, double h)
{
    double c[END_STENCIL4][5] = {{0}}, c1 = 1.0, c4 = 0.0;
    c[0][0] = 1.0;
    for (int i = 1; i < npts; i++) {
        int mn = i < order ? i : order;
        double c2 = 1.0, c5 = c4;
        c4 = i;
        for (int j = 0; j < i; j++) {
            double c3 = i - j;
            c2 *= c3;
            if (j == i - 1) {
                for (int k = mn; k >= 1; k--)
                    c[i][k] = c1 * (k * c[i - 1][k - 1] - c5 * c[i - 1][k]) / c2;
                c[i][0] = -c1 * c5 * c[i - 1][0] / c2;
            }
            for (int k = mn; k >= 1; k--)
                c[j][k] = (c4 * c[j][k] - k * c[j][k - 1]) / c3;
            c[j][0] = c4 * c[j][0] / c3;
        }
        c1 = c2;
    }
    double d = 0.0;
    for (int i = 0; i < npts; i++)
        d += c[i][order] * y[(ptrdiff_t)i * stride];
    return d / pow(h, order);
}

/* Fourth derivative at the start of n uniform samples y (stride apart, spacing h),
 * or 0 where the samples do not resolve it. Each spacing H = k h (k = 1, 2, 4, ...)
 * gives an estimate, checked against the one of spacing 2H: their truncation errors
 * differ by 256x and their rounding noise (amplified by H^-4) by 16x, so the
 * difference measures the worse of the two errors. The estimate whose difference is
 * least is taken, if within 10%; 23 samples at least are needed for one pair. Zero
 * makes the end polynomial a cubic (a sine series decaying like k^-5), whose slope at
 * the end is off by the missing fourth derivative times ~h^3: a G2 blend face's
 * trimline around a box's corner (the side's curvature rising from 0 over 17% of the
 * run) lost it at 1/64 of the range, where the 12-point stencils span 30% and 60% of
 * it, and the slope tilted out of the face by 4e-9 (512 samples) and 3e-8 (256); with
 * H = 2h it is 1e-11. A spacing fixed in advance either misses such data or, on fine
 * samples of slow data, amplifies their rounding noise. */
static double end_fourth(const double *y, int stride, int n, double h)
{
    double q = 0.0, best = INFINITY;
    for (int k = 1; 2 * k * (END_STENCIL4 - 1) <= n - 1; k *= 2) {
        double qa = end_derivative(y, k * stride, END_STENCIL4, 4, k * h);
        double qb = end_derivative(y, 2 * k * stride, END_STENCIL4, 4, 2 * k * h);
        double diff = fabs(qa - qb);
        if (diff <= 0.1 * fabs(qa) && diff < best) {
            q = qa;
            best = diff;
        }
    }
    return q;
}

/* Second derivative at the start of n uniform samples y (stride apart, spacing h). Each
 * spacing H = k h (k = 1, 2, 4, ...) gives an estimate, checked against the one of
 * spacing 2H: their truncation errors differ by 64x and their rounding noise (amplified
 * by H^-2) by 4x, so the difference measures the worse of the two errors. Smooth data
 * keep H = h. A wider spacing is taken where its difference is less than half the
 * narrower one's, as on finely sampled data far from the origin, whose samples carry
 * the rounding of their magnitude (a 60 degree arc 1000 from the origin, 513 samples:
 * its slope at the ends was off by 3.6e-9 of its scale at H = h, and by 2.6e-10 of it
 * with 65 samples), and where its stencils span at most a quarter of the range: on
 * data the samples barely resolve, the differences are large and erratic (1 / (1 +
 * 25 v^2) on [0, 1], 33 samples: the slope at the ends was 6x worse at 2h). With fewer
 * samples than one pair needs, the widest stencil of spacing h that they hold. */
static double end_second(const double *y, int stride, int n, double h)
{
    int npts = n < END_STENCIL2 ? n : END_STENCIL2;
    double g = end_derivative(y, stride, npts, 2, h);
    if (2 * (END_STENCIL2 - 1) > n - 1)
        return g;
    double best = fabs(g - end_derivative(y, 2 * stride, END_STENCIL2, 2, 2 * h));
    for (int k = 2; 8 * k * (END_STENCIL2 - 1) <= n - 1; k *= 2) {
        double ga = end_derivative(y, k * stride, END_STENCIL2, 2, k * h);
        double gb = end_derivative(y, 2 * k * stride, END_STENCIL2, 2, 2 * k * h);
        if (fabs(ga - gb) < 0.5 * best) {
            g = ga;
            best = fabs(ga - gb);
        }
    }
    return g;
}

/* Largest size of the end polynomial's fourth-derivative terms, relative to the data. */
#define END_POLY_MAX 1e3

/* Second and fourth derivatives at both ends of n uniform samples y (stride apart,
 * spacing h) into g and q; g is left as given when have_g. */
static void end_derivatives(const double *y, int stride, int n, double h, int have_g,
                            double g[2], double q[2])
{
    const double *last = y + (ptrdiff_t)(n - 1) * stride;
    if (!have_g) {
        g[0] = end_second(y, stride, n, h);
        g[1] = end_second(last, -stride, n, h);
    }
    q[0] = end_fourth(y, stride, n, h);
    q[1] = end_fourth(last, -stride, n, h);
    /* The quartic and quintic terms are about q L^4 / 24. Far above the data they cancel
     * against the sine series, and a blend loses as many digits: fast data (sin(150 v)
     * over 48 periods: 1.7e8 times their scale) keep the cubic; exp(cos 3v) over two
     * periods (216 times) and a box's corner run (0.2 times) keep the quintic. */
    double scale = 0.0, L4 = pow((n - 1) * h, 4);
    for (int i = 0; i < n; i++)
        scale = fmax(scale, fabs(y[(ptrdiff_t)i * stride]));
    if (fmax(fabs(q[0]), fabs(q[1])) * L4 / 24 > END_POLY_MAX * scale)
        q[0] = q[1] = 0.0;
}

static c2b_status project_dst(const c2b_vdomain *dom, c2b_vt_fn f, c2b_vt_fn f2, void *ctx,
                              double t, const c2b_tolerances *tol, const double *xc,
                              const double *yc, c2b_vseries *out, c2b_error *err)
{
    double L = dom->v1 - dom->v0;
    int n = 64; /* intervals */
    size_t cap = (size_t)tol->max_samples * 2 + 2;
    double *y = malloc(cap * sizeof *y), *ny = malloc(cap * sizeof *ny);
    double *r = fftw_alloc_real(cap), *b = fftw_alloc_real(cap), *vals = fftw_alloc_real(cap);
    c2b_status st = C2B_OK;
    double g[2] = {0, 0}, q[2], poly[END_DEG + 1];
    if (!y || !ny || !r || !b || !vals) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        goto done;
    }
    for (int i = 0; i <= n && !st; i++)
        st = sample(f, ctx, dom->v0 + i * L / n, t, &y[i], err);
    if (st)
        goto done;
    if (f2) {
        st = sample(f2, ctx, dom->v0, t, &g[0], err);
        if (!st)
            st = sample(f2, ctx, dom->v1, t, &g[1], err);
        if (st) {
            c2b_error_prefix(err, "second v-derivative: ");
            goto done;
        }
    }
    for (;;) {
        double h = L / n, scale = 0;
        for (int i = 0; i <= n; i++)
            scale = fmax(scale, fabs(y[i]));
        end_derivatives(y, 1, n + 1, h, f2 != NULL, g, q);
        end_poly((double[2]){y[0], y[n]}, g, q, L, poly);
        for (int i = 1; i < n; i++)
            r[i - 1] = y[i] - horner(poly, END_DEG, i * h);
        dst_coefficients(r, n, b);
        if (dst_terms(poly, b, n, L, drop_level(y, 1, n + 1, tol->drop_rel), out) ||
            sine_values(out, L, 2 * n, vals)) {
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
            goto done;
        }
        /* vals[j-1] = sine part at j L / (2n); compare at old points and midpoints. */
        double e = 0;
        ny[0] = y[0];
        for (int j = 1; j < 2 * n; j++) {
            double s = j * L / (2 * n), yj;
            if (j % 2 == 0) {
                yj = y[j / 2];
            } else {
                st = sample(f, ctx, dom->v0 + s, t, &yj, err);
                if (st)
                    goto done;
            }
            ny[j] = yj;
            scale = fmax(scale, fabs(yj));
            e = fmax(e, fabs(horner(poly, END_DEG, s) + vals[j - 1] - yj));
        }
        ny[2 * n] = y[n];
        e = fmax(e, offgrid_error(out, dom, xc, yc));
        out->scale = scale;
        out->err_abs = e;
        out->n_samples = n + 1;
        out->method = C2B_VM_DST;
        if (e <= tol->truncation_rel * scale || 2 * n > tol->max_samples)
            break;
        n *= 2;
        double *tmp = y;
        y = ny;
        ny = tmp;
    }
done:
    free(y);
    free(ny);
    fftw_free(r);
    fftw_free(b);
    fftw_free(vals);
    return st;
}

c2b_status c2b_vseries_project(const c2b_vdomain *dom, c2b_vt_fn f, c2b_vt_fn f2, void *ctx,
                               double t, const c2b_tolerances *tol, c2b_vseries *out,
                               c2b_error *err)
{
    c2b_tolerances def = c2b_tolerances_default();
    if (!tol)
        tol = &def;
    if (!dom || !f || !out || !(dom->v1 > dom->v0))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_vseries_project: invalid arguments");
    out->n = 0;
    out->n_samples = 0;
    out->err_abs = 0;
    double L = dom->v1 - dom->v0, xc[NCHECK], yc[NCHECK], scale = 0;
    for (int i = 0; i < NCHECK; i++) {
        xc[i] = CHECK_OFFSET + CHECK_STEP * i;
        c2b_status st = sample(f, ctx, dom->v0 + xc[i] * L, t, &yc[i], err);
        if (st)
            return st;
        scale = fmax(scale, fabs(yc[i]));
    }
    out->scale = scale;
    out->n_samples = NCHECK;
    if (scale == 0.0) {
        /* Zero on the check points; confirm on a second, uniform set. */
        int zero = 1;
        for (int i = 0; i <= 16 && zero; i++) {
            double y;
            c2b_status st = sample(f, ctx, dom->v0 + i * L / 16, t, &y, err);
            if (st)
                return st;
            zero = y == 0.0;
        }
        if (zero) {
            out->method = C2B_VM_ZERO;
            return C2B_OK;
        }
    }
    int found = 0;
    c2b_status st = try_polynomial(dom, f, ctx, t, tol, xc, yc, scale, out, &found, err);
    if (st || found)
        return st;
    if (!dom->periodic) {
        st = try_mode(dom, f, ctx, t, tol, xc, yc, scale, out, &found, err);
        if (st || found)
            return st;
        return project_dst(dom, f, f2, ctx, t, tol, xc, yc, out, err);
    }
    return project_fft(dom, f, ctx, t, tol, xc, yc, out, err);
}

/* Series of uniform samples, without error measurement. Periodic: n samples, end not
 * repeated. Open: n samples including both ends. */
static c2b_status samples_series(const c2b_vdomain *dom, const double *samples, int stride,
                                 int n, double drop, c2b_vseries *out, c2b_error *err)
{
    double L = dom->v1 - dom->v0;
    c2b_status st = C2B_OK;
    out->n = 0;
    if (dom->periodic) {
        double *x = fftw_alloc_real((size_t)n);
        fftw_complex *X = fftw_alloc_complex((size_t)n / 2 + 1);
        if (!x || !X) {
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        } else {
            for (int i = 0; i < n; i++)
                x[i] = samples[(size_t)i * (size_t)stride];
            fftw_plan p = fftw_plan_dft_r2c_1d(n, x, X, FFTW_ESTIMATE);
            fftw_execute(p);
            fftw_destroy_plan(p);
            if (fft_terms(X, n, L, drop, out))
                st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
            out->method = C2B_VM_FFT;
        }
        fftw_free(x);
        fftw_free(X);
        return st;
    }
    int iv = n - 1;
    double h = L / iv, g[2], q[2], poly[END_DEG + 1];
    end_derivatives(samples, stride, n, h, 0, g, q);
    end_poly((double[2]){samples[0], samples[(size_t)iv * (size_t)stride]}, g, q, L, poly);
    double *r = fftw_alloc_real((size_t)n), *b = fftw_alloc_real((size_t)n);
    if (!r || !b) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    } else {
        for (int i = 1; i < iv; i++)
            r[i - 1] = samples[(size_t)i * (size_t)stride] - horner(poly, END_DEG, i * h);
        if (iv > 1)
            dst_coefficients(r, iv, b);
        if (dst_terms(poly, b, iv, L, drop, out))
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        out->method = C2B_VM_DST;
    }
    fftw_free(r);
    fftw_free(b);
    return st;
}

/* Values of a samples_series() result on the m-point sample grid of the domain. */
static int series_on_grid(const c2b_vseries *s, const c2b_vdomain *dom, int m, double *vals)
{
    double L = dom->v1 - dom->v0;
    if (dom->periodic)
        return periodic_values(s, L, m, vals);
    int iv = m - 1;
    double *sv = fftw_alloc_real((size_t)m);
    if (!sv)
        return -1;
    if (iv > 1 && sine_values(s, L, iv, sv)) {
        fftw_free(sv);
        return -1;
    }
    for (int i = 0; i <= iv; i++) {
        double poly = 0, tmp;
        for (int k = 0; k < s->n; k++)
            if (s->terms[k].f.kind == C2B_VF_POW) {
                c2b_vfunc_eval(&s->terms[k].f, i * L / iv, L, 0, &tmp);
                poly += s->terms[k].amp * tmp;
            }
        vals[i] = poly + ((i > 0 && i < iv) ? sv[i - 1] : 0.0);
    }
    fftw_free(sv);
    return 0;
}

c2b_status c2b_vseries_project_samples(const c2b_vdomain *dom, const double *samples,
                                       int stride, int n, const c2b_tolerances *tol,
                                       c2b_vseries *out, c2b_error *err)
{
    c2b_tolerances def = c2b_tolerances_default();
    if (!tol)
        tol = &def;
    if (!dom || !samples || !out || stride < 1 || !(dom->v1 > dom->v0))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_vseries_project_samples: invalid arguments");
    int nmin = dom->periodic ? 4 : 7;
    if (n < nmin)
        return c2b_error_set(err, C2B_ERR_SPEC, "%d samples given, at least %d are needed", n,
                             nmin);
    if (n > 4 * tol->max_samples)
        return c2b_error_set(err, C2B_ERR_LIMIT, "%d samples given, the limit is %d", n,
                             4 * tol->max_samples);
    double scale = 0;
    for (int i = 0; i < n; i++) {
        double y = samples[(size_t)i * (size_t)stride];
        if (!isfinite(y))
            return c2b_error_set(err, C2B_ERR_SPEC, "sample %d is not finite (%g)", i, y);
        scale = fmax(scale, fabs(y));
    }
    double drop = drop_level(samples, stride, n, tol->drop_rel);
    c2b_status st = samples_series(dom, samples, stride, n, drop, out, err);
    if (st)
        return st;
    out->scale = scale;
    out->n_samples = n;
    out->err_abs = 0;
    /* Error at the samples (from dropped modes), and a leave-half-out estimate of the
     * error between samples: the series of every other sample, checked at the rest. */
    double *vals = malloc((size_t)n * sizeof *vals);
    c2b_vseries half;
    memset(&half, 0, sizeof half);
    if (!vals || series_on_grid(out, dom, n, vals)) {
        free(vals);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    }
    for (int i = 0; i < n; i++)
        out->err_abs = fmax(out->err_abs, fabs(vals[i] - samples[(size_t)i * (size_t)stride]));
    /* every other sample of m samples over sub; an even count on an open range uses the
     * first n - 1 samples (an odd count), over the range they span */
    c2b_vdomain sub = *dom;
    int m = n;
    if (!dom->periodic && n % 2 == 0) {
        m = n - 1;
        sub.v1 = dom->v0 + (dom->v1 - dom->v0) * (n - 2) / (n - 1);
    }
    int nh = dom->periodic ? (n % 2 == 0 ? n / 2 : 0) : (m - 1) / 2 + 1;
    if (nh >= nmin) {
        st = samples_series(&sub, samples, 2 * stride, nh, drop, &half, err);
        if (!st && series_on_grid(&half, &sub, m, vals))
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        for (int i = 1; !st && i < m; i += 2)
            out->err_abs = fmax(out->err_abs, fabs(vals[i] - samples[(size_t)i * (size_t)stride]));
    }
    c2b_vseries_clear(&half);
    free(vals);
    return st;
}
