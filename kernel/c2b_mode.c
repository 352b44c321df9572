#include "c2b_mode.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Taylor terms kept for divided differences inside a cluster. */
#define C2B_MODE_MAX_TAYLOR 120

typedef struct cluster {
    int start, size;          /* exponents r[start .. start+size) */
    double complex mu;        /* centre (mean of the nodes) */
    double anchor;            /* 0 or 1 */
    int q;                    /* Taylor terms, 0 for singletons */
    double complex *h;        /* h[i * (q+1) + k] = h_k(delta_0..delta_i), size x (q+1) */
} cluster;

struct c2b_mode {
    int n, m;
    double beta;
    double cond;
    double complex r[C2B_MAX_M];
    int ncl;
    cluster cl[C2B_MAX_M];
    double complex minv[C2B_MAX_M * C2B_MAX_M]; /* row-major: coef_i = sum_j minv[i*m+j] d_j */
};

/* |z|: sqrt(re^2 + im^2) where that cannot overflow or underflow, else hypot. The mode's
 * condition estimate and transfer check take some 100 moduli per mode, and glibc's
 * hypot (correctly rounded) was a quarter of a mode's solve. */
static double mag(double complex z)
{
    double a = fabs(creal(z)), b = fabs(cimag(z)), big = a > b ? a : b;
    if (big > 1e150 || (big < 1e-150 && big > 0))
        return hypot(a, b);
    return sqrt(a * a + b * b);
}

/* Group exponents by single linkage (|r_i - r_j| <= tol) and order them by cluster. */
static void make_clusters(c2b_mode *md, const double complex *r, double tol)
{
    int m = md->m;
    int label[C2B_MAX_M];
    for (int i = 0; i < m; i++)
        label[i] = i;
    for (int changed = 1; changed;) {
        changed = 0;
        for (int i = 0; i < m; i++)
            for (int j = i + 1; j < m; j++)
                if (label[i] != label[j] && mag(r[i] - r[j]) <= tol) {
                    int lo = label[i] < label[j] ? label[i] : label[j];
                    label[i] = label[j] = lo;
                    changed = 1;
                }
    }
    int k = 0;
    md->ncl = 0;
    for (int l = 0; l < m; l++) {
        int start = k;
        for (int i = 0; i < m; i++)
            if (label[i] == l)
                md->r[k++] = r[i];
        if (k > start) {
            cluster *c = &md->cl[md->ncl++];
            memset(c, 0, sizeof *c);
            c->start = start;
            c->size = k - start;
        }
    }
}

/* Centre, anchor and the complete homogeneous symmetric polynomials of a cluster. */
static c2b_status prepare_cluster(c2b_mode *md, cluster *c)
{
    double complex mu = 0;
    for (int i = 0; i < c->size; i++)
        mu += md->r[c->start + i];
    mu /= c->size;
    c->mu = c->size == 1 ? md->r[c->start] : mu;
    c->anchor = creal(c->mu) > 0 ? 1.0 : 0.0;
    if (c->size == 1)
        return C2B_OK;
    double dmax = 0;
    for (int i = 0; i < c->size; i++)
        dmax = fmax(dmax, mag(md->r[c->start + i] - mu));
    /* Terms until C(q+size, size) dmax^q / q! < 1e-18 (|u - anchor| <= 1). */
    int q = c->size + 2;
    for (; q < C2B_MODE_MAX_TAYLOR; q++) {
        double bound = 1.0;
        for (int j = 1; j <= q; j++)
            bound *= dmax / j;
        for (int j = 1; j <= c->size; j++)
            bound *= (double)(q + j) / j;
        if (bound < 1e-18)
            break;
    }
    c->q = q;
    c->h = calloc((size_t)c->size * (size_t)(q + 1), sizeof *c->h);
    if (!c->h)
        return C2B_ERR_NOMEM;
    /* h_k(d_0..d_i) = h_k(d_0..d_{i-1}) + d_i h_{k-1}(d_0..d_i) */
    for (int i = 0; i < c->size; i++) {
        double complex di = md->r[c->start + i] - mu;
        double complex *hi = c->h + (size_t)i * (size_t)(q + 1);
        const double complex *hp = i ? hi - (q + 1) : NULL;
        for (int k = 0; k <= q; k++) {
            double complex prev = hp ? hp[k] : (k == 0 ? 1.0 : 0.0);
            hi[k] = prev + (k ? di * hi[k - 1] : 0.0);
        }
    }
    return C2B_OK;
}

/* phi^{(p)} for the basis functions of one cluster at u. out[p * m + idx]. */
static void cluster_basis(const c2b_mode *md, const cluster *c, double u, int maxd,
                          double complex *out)
{
    int m = md->m;
    double s = u - c->anchor;
    double complex e = s == 0 ? 1.0 : cexp(c->mu * s);
    if (c->size == 1) {
        double complex rp = 1.0;
        for (int p = 0; p <= maxd; p++) {
            out[p * m + c->start] = rp * e;
            rp *= c->mu;
        }
        return;
    }
    /* psi_i^{(l)}(s) = sum_{k>=max(i,l)} s^{k-l}/(k-l)! h_{k-i}(d_0..d_i) */
    double sp[C2B_MODE_MAX_TAYLOR + 1];
    sp[0] = 1.0;
    for (int k = 1; k <= c->q; k++)
        sp[k] = sp[k - 1] * s / k;
    static const double binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    for (int i = 0; i < c->size; i++) {
        const double complex *hi = c->h + (size_t)i * (size_t)(c->q + 1);
        double complex psi[4] = {0, 0, 0, 0};
        for (int l = 0; l <= maxd; l++) {
            int k0 = i > l ? i : l;
            double complex acc = 0;
            for (int k = c->q; k >= k0; k--)
                acc += sp[k - l] * hi[k - i];
            psi[l] = acc;
        }
        for (int p = 0; p <= maxd; p++) {
            double complex acc = 0, mupow = 1.0;
            for (int l = p; l >= 0; l--) { /* C(p,l) mu^{p-l} psi^{(l)} */
                acc += binom[p][l] * mupow * psi[l];
                mupow *= c->mu;
            }
            out[p * m + c->start + i] = e * acc;
        }
    }
}

void c2b_mode_basis(const c2b_mode *m, double u, int maxd, double complex *phi)
{
    if (maxd > 3)
        maxd = 3;
    for (int c = 0; c < m->ncl; c++)
        cluster_basis(m, &m->cl[c], u, maxd, phi);
}

static double norm1(const double complex *a, int m)
{
    double best = 0;
    for (int j = 0; j < m; j++) {
        double s = 0;
        for (int i = 0; i < m; i++)
            s += mag(a[j * m + i]);
        best = fmax(best, s);
    }
    return best;
}

void c2b_mode_destroy(c2b_mode *m)
{
    if (!m)
        return;
    for (int c = 0; c < m->ncl; c++)
        free(m->cl[c].h);
    free(m);
}

c2b_status c2b_mode_create(const c2b_operator *op, double beta, const c2b_tolerances *tol,
                           c2b_mode **out, c2b_error *err)
{
    if (!op || !out || !isfinite(beta))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_mode_create: invalid arguments");
    *out = NULL;
    c2b_tolerances def = c2b_tolerances_default();
    if (!tol)
        tol = &def;
    c2b_mode *md = calloc(1, sizeof *md);
    if (!md)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory creating a mode");
    int n = op->n, m = 2 * n;
    md->n = n;
    md->m = m;
    md->beta = beta;

    double complex z[C2B_MAX_N], r[C2B_MAX_M];
    c2b_operator_z_roots(op, beta, z);
    for (int i = 0; i < n; i++) {
        double complex s = csqrt(z[i]);
        r[2 * i] = s;
        r[2 * i + 1] = -s;
    }
    make_clusters(md, r, tol->cluster);
    for (int c = 0; c < md->ncl; c++)
        if (prepare_cluster(md, &md->cl[c]) != C2B_OK) {
            c2b_mode_destroy(md);
            return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory creating a mode");
        }

    /* Boundary matrix, column-major A[col*m + row], rows scaled by sigma^-p. */
    double sigma = 1.0;
    for (int i = 0; i < m; i++)
        sigma = fmax(sigma, mag(md->r[i]));
    double complex phi0[4 * C2B_MAX_M], phi1[4 * C2B_MAX_M];
    c2b_mode_basis(md, 0.0, n - 1, phi0);
    c2b_mode_basis(md, 1.0, n - 1, phi1);
    double complex a[C2B_MAX_M * C2B_MAX_M];
    double rs[C2B_MAX_M];
    for (int p = 0; p < n; p++) {
        rs[p] = rs[n + p] = pow(sigma, -p);
        for (int col = 0; col < m; col++) {
            a[col * m + p] = phi0[p * m + col] * rs[p];
            a[col * m + n + p] = phi1[p * m + col] * rs[p];
        }
    }
    double anorm = norm1(a, m);
    /* The _work forms: no NaN scan (a NaN gives a NaN estimate, refused below) and no
     * workspace allocated; a workspace of m columns makes zgetri unblocked, as suits a
     * matrix this small. */
    lapack_int ipiv[C2B_MAX_M];
    double complex work[C2B_MAX_M * C2B_MAX_M];
    lapack_int info = LAPACKE_zgetrf_work(LAPACK_COL_MAJOR, m, m, a, m, ipiv);
    if (info == 0)
        info = LAPACKE_zgetri_work(LAPACK_COL_MAJOR, m, a, m, ipiv, work, m * m);
    md->cond = info == 0 ? anorm * norm1(a, m) : INFINITY;
    if (!(md->cond <= tol->cond_limit)) {
        char shape[256];
        c2b_operator_describe(op, shape, sizeof shape);
        c2b_status st = c2b_error_set(
            err, C2B_ERR_NUMERIC,
            "mode beta=%.17g is resonant: its %dx%d boundary system has condition "
            "estimate %.3g (limit %.3g) for shape parameters %s%s; change the shape "
            "parameters",
            beta, m, m, md->cond, tol->cond_limit, shape,
            info != 0 ? " (exactly singular)" : "");
        c2b_mode_destroy(md);
        return st;
    }
    /* Unscaled inverse: Minv = As^-1 diag(rs); a holds As^-1 column-major. */
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++)
            md->minv[i * m + j] = a[j * m + i] * rs[j];

    /* The transfer functions must be real: check at an interior point. */
    double complex phih[C2B_MAX_M];
    c2b_mode_basis(md, 0.5, 0, phih);
    for (int j = 0; j < m; j++) {
        double complex sum = 0;
        double total = 0;
        for (int i = 0; i < m; i++) {
            double complex t = md->minv[i * m + j] * phih[i];
            sum += t;
            total += mag(t);
        }
        if (fabs(cimag(sum)) > tol->imag_rel * fmax(total, 1e-300)) {
            char shape[256];
            c2b_operator_describe(op, shape, sizeof shape);
            c2b_status st = c2b_error_set(
                err, C2B_ERR_NUMERIC,
                "mode beta=%.17g: transfer function %d has imaginary part %.3g "
                "(relative %.3g) for shape parameters %s",
                beta, j, cimag(sum), fabs(cimag(sum)) / fmax(total, 1e-300), shape);
            c2b_mode_destroy(md);
            return st;
        }
    }
    *out = md;
    return C2B_OK;
}

int c2b_mode_size(const c2b_mode *m) { return m->m; }
double c2b_mode_beta(const c2b_mode *m) { return m->beta; }
double c2b_mode_condition(const c2b_mode *m) { return m->cond; }

void c2b_mode_exponents(const c2b_mode *m, double complex *r)
{
    memcpy(r, m->r, (size_t)m->m * sizeof *r);
}

int c2b_mode_repeated_clusters(const c2b_mode *m)
{
    int k = 0;
    for (int c = 0; c < m->ncl; c++)
        k += m->cl[c].size > 1;
    return k;
}

void c2b_mode_coefficients(const c2b_mode *m, const double *d, double complex *coef)
{
    for (int i = 0; i < m->m; i++) {
        double complex s = 0;
        for (int j = 0; j < m->m; j++)
            s += m->minv[i * m->m + j] * d[j];
        coef[i] = s;
    }
}

double c2b_mode_combine(const c2b_mode *m, const double complex *coef,
                        const double complex *phi, int p)
{
    double s = 0;
    const double complex *row = phi + p * m->m;
    for (int i = 0; i < m->m; i++)
        s += creal(coef[i]) * creal(row[i]) - cimag(coef[i]) * cimag(row[i]);
    return s;
}

void c2b_mode_eval(const c2b_mode *m, const double *d, double u, int maxd, double *G)
{
    double complex coef[C2B_MAX_M], phi[4 * C2B_MAX_M];
    if (maxd > 3)
        maxd = 3;
    c2b_mode_coefficients(m, d, coef);
    c2b_mode_basis(m, u, maxd, phi);
    for (int p = 0; p <= maxd; p++)
        G[p] = c2b_mode_combine(m, coef, phi, p);
}
