#include "c2b_poly.h"

#include "c2b_constants.h"

#include <lapacke.h>
#include <math.h>
#include <string.h>

double c2b_poly_cheb_node(int j, int np)
{
    return np == 1 ? 0.5 : 0.5 - 0.5 * cos(C2B_PI * (2 * j + 1) / (2.0 * np));
}

void c2b_poly_interpolate(int np, const double *x, const double *y, double *coef)
{
    double dd[C2B_POLY_MAX_DEG + 1];
    memcpy(dd, y, (size_t)np * sizeof *dd);
    for (int k = 1; k < np; k++)
        for (int i = np - 1; i >= k; i--)
            dd[i] = (dd[i] - dd[i - 1]) / (x[i] - x[i - k]);
    /* Newton form to monomials, innermost factor first. */
    for (int i = 0; i < np; i++)
        coef[i] = 0.0;
    for (int k = np - 1; k >= 0; k--) {
        for (int i = np - 1; i >= 1; i--)
            coef[i] = coef[i - 1] - x[k] * coef[i];
        coef[0] = -x[k] * coef[0] + dd[k];
    }
}

void c2b_poly_zero(c2b_poly *p)
{
    p->deg = -1;
    memset(p->c, 0, sizeof p->c);
}

void c2b_poly_eval(const c2b_poly *p, double u, int maxd, double *out)
{
    for (int k = 0; k <= maxd; k++)
        out[k] = 0.0;
    /* Horner for each derivative: p^{(k)}(u) = sum_i i!/(i-k)! c_i u^{i-k} */
    for (int k = 0; k <= maxd; k++) {
        double acc = 0.0;
        for (int i = p->deg; i >= k; i--) {
            double f = 1.0;
            for (int j = 0; j < k; j++)
                f *= (double)(i - j);
            acc = acc * u + f * p->c[i];
        }
        out[k] = acc;
    }
}

void c2b_poly_derivative(const c2b_poly *p, int k, c2b_poly *q)
{
    c2b_poly r;
    c2b_poly_zero(&r);
    for (int i = k; i <= p->deg; i++) {
        double f = 1.0;
        for (int j = 0; j < k; j++)
            f *= (double)(i - j);
        r.c[i - k] = f * p->c[i];
    }
    r.deg = p->deg - k < 0 ? -1 : p->deg - k;
    *q = r;
}

void c2b_poly_boundary(const c2b_poly *p, int n, double *d)
{
    double v0[C2B_MAX_N], v1[C2B_MAX_N];
    c2b_poly_eval(p, 0.0, n - 1, v0);
    c2b_poly_eval(p, 1.0, n - 1, v1);
    for (int q = 0; q < n; q++) {
        d[q] = v0[q];
        d[n + q] = v1[q];
    }
}

c2b_status c2b_poly_hermite(int n, c2b_poly *basis, c2b_error *err)
{
    if (n < 1 || n > C2B_MAX_N)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_poly_hermite: n=%d out of range", n);
    int m = 2 * n;
    /* Row-major A[row][col]: row = constraint, col = monomial u^col. */
    double a[C2B_MAX_M * C2B_MAX_M], b[C2B_MAX_M * C2B_MAX_M];
    memset(a, 0, sizeof a);
    memset(b, 0, sizeof b);
    for (int q = 0; q < n; q++)
        for (int col = 0; col < m; col++) {
            double f = 1.0;
            for (int j = 0; j < q; j++)
                f *= (double)(col - j);
            a[q * m + col] = col == q ? f : 0.0;       /* derivative q at u=0 */
            a[(n + q) * m + col] = col >= q ? f : 0.0; /* derivative q at u=1 */
        }
    for (int j = 0; j < m; j++)
        b[j * m + j] = 1.0;
    lapack_int ipiv[C2B_MAX_M];
    lapack_int info = LAPACKE_dgesv(LAPACK_ROW_MAJOR, m, m, a, m, ipiv, b, m);
    if (info != 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC, "Hermite system singular (info %d)",
                             (int)info);
    for (int j = 0; j < m; j++) {
        c2b_poly_zero(&basis[j]);
        basis[j].deg = m - 1;
        for (int col = 0; col < m; col++)
            basis[j].c[col] = b[col * m + j];
    }
    return C2B_OK;
}

static void trim(c2b_poly *p)
{
    while (p->deg >= 0 && p->c[p->deg] == 0.0)
        p->deg--;
}

c2b_status c2b_poly_particular(int n, const double *c, const c2b_poly *rhs, c2b_poly *P,
                               c2b_error *err)
{
    int ks = -1; /* largest k with c_k != 0: lowest derivative order 2(n-ks) */
    for (int k = 0; k <= n; k++)
        if (c[k] != 0.0)
            ks = k;
    if (ks < 0)
        return c2b_error_set(err, C2B_ERR_ARG, "particular solution: operator is zero");
    c2b_poly_zero(P);
    if (rhs->deg < 0)
        return C2B_OK;
    int shift = 2 * (n - ks);
    if (rhs->deg + shift > C2B_POLY_MAX_DEG)
        return c2b_error_set(err, C2B_ERR_LIMIT,
                             "particular solution degree %d exceeds the limit %d",
                             rhs->deg + shift, C2B_POLY_MAX_DEG);
    /* Q = P^{(shift)}: c_ks Q + sum_{k<ks} c_k Q^{(2(ks-k))} = rhs, top-down. */
    c2b_poly Q;
    c2b_poly_zero(&Q);
    Q.deg = rhs->deg;
    for (int i = rhs->deg; i >= 0; i--) {
        double s = rhs->c[i];
        for (int k = 0; k < ks; k++) {
            int j = 2 * (ks - k);
            if (i + j > Q.deg)
                continue;
            double f = 1.0;
            for (int l = 1; l <= j; l++)
                f *= (double)(i + l);
            s -= c[k] * f * Q.c[i + j];
        }
        Q.c[i] = s / c[ks];
    }
    /* P = shift-fold antiderivative of Q with zero integration constants. */
    P->deg = Q.deg + shift;
    for (int i = 0; i <= Q.deg; i++) {
        double f = 1.0;
        for (int l = 1; l <= shift; l++)
            f *= (double)(i + l);
        P->c[i + shift] = Q.c[i] / f;
    }
    trim(P);
    return C2B_OK;
}

c2b_status c2b_poly_solve_pde(const c2b_operator *op, int dm, const double *data,
                              const c2b_poly *force, c2b_poly *G, c2b_error *err)
{
    if (!op || op->beta_free || dm < 0 || !data || !G)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_poly_solve_pde: invalid arguments");
    int n = op->n, m2 = 2 * n;
    c2b_poly herm[C2B_MAX_M];
    c2b_status st = c2b_poly_hermite(n, herm, err);
    if (st)
        return st;
    double c0[C2B_MAX_N + 1] = {0};
    c0[0] = op->a[0]; /* beta = 0: a_0 G^{(2n)} = rhs */
    for (int m = dm; m >= 0; m--) {
        c2b_poly rhs;
        if (force)
            rhs = force[m];
        else
            c2b_poly_zero(&rhs);
        for (int k = 1; k <= n; k++) {
            int mk = m + 2 * k;
            if (mk > dm)
                break;
            double f = 1.0;
            for (int l = m + 1; l <= mk; l++)
                f *= (double)l;
            c2b_poly d;
            c2b_poly_derivative(&G[mk], 2 * (n - k), &d);
            for (int i = 0; i <= d.deg; i++)
                rhs.c[i] -= op->a[k] * f * d.c[i];
            if (d.deg > rhs.deg)
                rhs.deg = d.deg;
        }
        trim(&rhs);
        st = c2b_poly_particular(n, c0, &rhs, &G[m], err);
        if (st) {
            c2b_error_prefix(err, "polynomial part, v^%d: ", m);
            return st;
        }
        double pb[C2B_MAX_M];
        c2b_poly_boundary(&G[m], n, pb);
        for (int j = 0; j < m2; j++) {
            double w = data[j * (dm + 1) + m] - pb[j];
            if (w == 0.0)
                continue;
            for (int i = 0; i < m2; i++)
                G[m].c[i] += w * herm[j].c[i];
            if (G[m].deg < m2 - 1)
                G[m].deg = m2 - 1;
        }
        trim(&G[m]);
    }
    return C2B_OK;
}
