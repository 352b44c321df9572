/*
 * cheb_bvp.c -- independent Chebyshev spectral BVP oracle (see cheb_bvp.h).
 *
 * Conventions used throughout this file:
 *   x = 2u - 1 maps u in [0,1] onto x in [-1,1];
 *   a Chebyshev series is f(x) = sum_{k<len} f[k] T_k(x) (no halved f[0]);
 *   "J" is integration in u from u = 0, so d/du (J f) = f and (J f)(0) = 0.
 */
#include "cheb_bvp.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define ORACLE_PI 3.14159265358979323846264338327950288

/* ---------------------------------------------------------------------- */
/* Chebyshev series helpers                                               */
/* ---------------------------------------------------------------------- */

/* F (length len+1) = J f, f of length len >= 1.  Uses the exact relations
 *   int T_0 = T_1,  int T_1 = T_2/4,
 *   int T_k = T_{k+1}/(2(k+1)) - T_{k-1}/(2(k-1))   (k >= 2),
 * then fixes the constant so that F(x=-1) = 0 and multiplies by du/dx=1/2. */
static void cheb_integrate_u(const double *f, int len, double *F)
{
    int k;
    double alt = 0.0; /* sum_{k>=1} (-1)^k F_k */
    for (k = 1; k <= len; ++k) {
        double fm = f[k - 1];
        double fp = (k + 1 < len) ? f[k + 1] : 0.0;
        double v;
        if (k == 1)
            v = fm - 0.5 * fp;
        else
            v = (fm - fp) / (2.0 * (double)k);
        F[k] = v;
        alt += (k & 1) ? -v : v;
    }
    F[0] = -alt;
    for (k = 0; k <= len; ++k)
        F[k] *= 0.5;
}

/* df (length len-1, or 1 if len == 1) = d/du f. */
static void cheb_derivative_u(const double *f, int len, double *df)
{
    int k;
    if (len <= 1) {
        df[0] = 0.0;
        return;
    }
    /* d/dx: b_{k-1} = b_{k+1} + 2 k f_k, with b_{len-1} = b_len = 0 */
    {
        double bkp1 = 0.0, bk = 0.0; /* b_{k+1}, b_k */
        for (k = len - 1; k >= 1; --k) {
            double bkm1 = bkp1 + 2.0 * (double)k * f[k];
            df[k - 1] = bkm1;
            bkp1 = bk;
            bk = bkm1;
        }
    }
    df[0] *= 0.5;
    for (k = 0; k < len - 1; ++k)
        df[k] *= 2.0; /* du = dx / 2 */
}

/* Clenshaw evaluation of sum_{k<len} f[k] T_k(x). */
static double cheb_eval(const double *f, int len, double x)
{
    double b1 = 0.0, b2 = 0.0;
    int k;
    if (len <= 0)
        return 0.0;
    for (k = len - 1; k >= 1; --k) {
        double b0 = 2.0 * x * b1 - b2 + f[k];
        b2 = b1;
        b1 = b0;
    }
    return x * b1 - b2 + f[0];
}

static double factorial(int k)
{
    double r = 1.0;
    int i;
    for (i = 2; i <= k; ++i)
        r *= (double)i;
    return r;
}

/* Round a positive scale factor to the nearest power of two (exact scaling). */
static double pow2_round(double s)
{
    int e;
    double m;
    if (!(s > 0.0) || !isfinite(s))
        return 1.0;
    m = frexp(s, &e); /* s = m 2^e, m in [0.5,1) */
    if (m > 0.70710678118654752)
        return ldexp(1.0, e);
    return ldexp(1.0, e - 1);
}

/* ---------------------------------------------------------------------- */
/* One solve at fixed N                                                   */
/* ---------------------------------------------------------------------- */

/* Solves for the unknown vector sol (length N + 2n):
 *   sol[0..N-1]   Chebyshev coefficients of G^{(2n)},
 *   sol[N..N+m-1] b_i = G^{(i)}(0).
 * Returns 0 / 2 / 3 / 4 as oracle_cheb_bvp. */
static int solve_fixed(int n, const double *c, int rhs_deg, const double *rhs,
                       const double *d, int N, double *sol, double *cond)
{
    const int m = 2 * n;
    const int M = N + m;
    const int L = N + m; /* max series length of J^s e_j, s <= m */
    double *A = NULL, *As = NULL, *T = NULL, *work = NULL, *comb = NULL;
    double *b = NULL, *xs = NULL, *rr = NULL, *cc = NULL, *ucol = NULL;
    lapack_int *ipiv = NULL;
    double rowcnd, colcnd, amax, anorm, rcond = 0.0;
    lapack_int info;
    int i, j, k, s, q, it, status = 0;

    A = malloc(sizeof(double) * (size_t)M * (size_t)M);
    As = malloc(sizeof(double) * (size_t)M * (size_t)M);
    T = malloc(sizeof(double) * (size_t)N * (size_t)L);
    work = malloc(sizeof(double) * 2 * (size_t)(L + 1));
    comb = malloc(sizeof(double) * (size_t)(L + 1));
    b = malloc(sizeof(double) * (size_t)M);
    xs = malloc(sizeof(double) * (size_t)M);
    rr = malloc(sizeof(double) * (size_t)M);
    cc = malloc(sizeof(double) * (size_t)M);
    ucol = malloc(sizeof(double) * (size_t)N);
    ipiv = malloc(sizeof(lapack_int) * (size_t)M);
    if (!A || !As || !T || !work || !comb || !b || !xs || !rr || !cc || !ucol ||
        !ipiv) {
        status = 2;
        goto done;
    }
    memset(A, 0, sizeof(double) * (size_t)M * (size_t)M);

    /* Collocation points: Chebyshev-Gauss, x_i = cos(theta_i);
     * u_i = (1 + cos theta_i)/2 = cos^2(theta_i/2) (accurate near u = 0). */
    for (i = 0; i < N; ++i) {
        double th = ORACLE_PI * (2.0 * i + 1.0) / (2.0 * N);
        double ch = cos(0.5 * th);
        ucol[i] = ch * ch;
        for (k = 0; k < L; ++k)
            T[(size_t)i * (size_t)L + (size_t)k] = cos((double)k * th);
    }

    /* Columns for the Chebyshev coefficients a_j of G^{(m)}. */
    for (j = 0; j < N; ++j) {
        double *cur = work, *nxt = work + (L + 1);
        int len = j + 1;
        memset(cur, 0, sizeof(double) * (size_t)len);
        cur[j] = 1.0;
        /* comb = sum_k c[k] J^{2k} e_j (length j+1+m) */
        memset(comb, 0, sizeof(double) * (size_t)(j + 1 + m));
        comb[j] = c[0];
        for (s = 1; s <= m; ++s) {
            double *tmp;
            cheb_integrate_u(cur, len, nxt);
            ++len;
            tmp = cur;
            cur = nxt;
            nxt = tmp;
            if ((s & 1) == 0 && c[s / 2] != 0.0) {
                for (k = 0; k < len; ++k)
                    comb[k] += c[s / 2] * cur[k];
            }
            if (s > n) {
                /* right boundary row: G^{(m-s)}(1) gets (J^s e_j)(x=1) */
                double sum = 0.0;
                q = m - s;
                for (k = len - 1; k >= 0; --k)
                    sum += cur[k];
                A[(size_t)(N + n + q) + (size_t)j * (size_t)M] = sum;
            }
        }
        for (i = 0; i < N; ++i) {
            const double *Ti = T + (size_t)i * (size_t)L;
            double sum = 0.0;
            for (k = j + m; k >= 0; --k)
                sum += comb[k] * Ti[k];
            A[(size_t)i + (size_t)j * (size_t)M] = sum;
        }
    }

    /* Columns for the polynomial part sum_i b_i u^i / i!. */
    for (j = 0; j < m; ++j) {
        const size_t col = (size_t)(N + j) * (size_t)M;
        for (i = 0; i < N; ++i) {
            double sum = 0.0;
            for (k = 0; k <= n; ++k) {
                int order = m - 2 * k; /* derivative order hit by c[k] */
                if (c[k] != 0.0 && j >= order)
                    sum += c[k] * pow(ucol[i], (double)(j - order)) /
                           factorial(j - order);
            }
            A[(size_t)i + col] = sum;
        }
        /* left boundary: G^{(q)}(0) = b_q */
        if (j < n)
            A[(size_t)(N + j) + col] = 1.0;
        /* right boundary: G^{(q)}(1) = sum_{i>=q} b_i / (i-q)! + ... */
        for (q = 0; q < n; ++q)
            if (j >= q)
                A[(size_t)(N + n + q) + col] = 1.0 / factorial(j - q);
    }

    /* Right-hand side. */
    for (i = 0; i < N; ++i) {
        double v = 0.0;
        for (k = rhs_deg; k >= 0; --k)
            v = v * ucol[i] + rhs[k];
        b[i] = v;
    }
    for (q = 0; q < m; ++q)
        b[N + q] = d[q];

    /* Equilibrate with power-of-two factors. */
    info = LAPACKE_dgeequ(LAPACK_COL_MAJOR, M, M, A, M, rr, cc, &rowcnd,
                          &colcnd, &amax);
    if (info > 0) {
        status = 3;
        goto done;
    } else if (info < 0) {
        status = 4;
        goto done;
    }
    for (i = 0; i < M; ++i) {
        rr[i] = pow2_round(rr[i]);
        cc[i] = pow2_round(cc[i]);
    }
    for (j = 0; j < M; ++j)
        for (i = 0; i < M; ++i)
            A[(size_t)i + (size_t)j * (size_t)M] *= rr[i] * cc[j];
    for (i = 0; i < M; ++i)
        b[i] *= rr[i];
    memcpy(As, A, sizeof(double) * (size_t)M * (size_t)M);

    anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', M, M, As, M);
    info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, M, M, A, M, ipiv);
    if (info > 0) {
        *cond = INFINITY;
        status = 3;
        goto done;
    } else if (info < 0) {
        status = 4;
        goto done;
    }
    info = LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', M, A, M, anorm, &rcond);
    if (info != 0) {
        status = 4;
        goto done;
    }
    *cond = (rcond > 0.0) ? 1.0 / rcond : INFINITY;

    memcpy(xs, b, sizeof(double) * (size_t)M);
    info = LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', M, 1, A, M, ipiv, xs, M);
    if (info != 0) {
        status = 4;
        goto done;
    }
    /* Iterative refinement, residual in long double. */
    for (it = 0; it < 2; ++it) {
        for (i = 0; i < M; ++i) {
            long double r = (long double)b[i];
            for (j = 0; j < M; ++j)
                r -= (long double)As[(size_t)i + (size_t)j * (size_t)M] *
                     (long double)xs[j];
            rr[i] = (double)r;
        }
        info = LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', M, 1, A, M, ipiv, rr, M);
        if (info != 0) {
            status = 4;
            goto done;
        }
        for (i = 0; i < M; ++i)
            xs[i] += rr[i];
    }
    for (i = 0; i < M; ++i)
        sol[i] = xs[i] * cc[i];

done:
    free(A);
    free(As);
    free(T);
    free(work);
    free(comb);
    free(b);
    free(xs);
    free(rr);
    free(cc);
    free(ucol);
    free(ipiv);
    return status;
}

/* Relative size of the last 8 coefficients of G^{(m)}. */
static double tail_ratio(const double *a, int N)
{
    double amax = 0.0, tmax = 0.0;
    int k, t0 = N > 8 ? N - 8 : 0;
    for (k = 0; k < N; ++k) {
        double v = fabs(a[k]);
        if (v > amax)
            amax = v;
        if (k >= t0 && v > tmax)
            tmax = v;
    }
    return amax > 0.0 ? tmax / amax : 0.0;
}

/* ---------------------------------------------------------------------- */
/* Public entry point                                                     */
/* ---------------------------------------------------------------------- */

int oracle_cheb_bvp(int n, const double *c, int rhs_deg, const double *rhs,
                    const double *d, int N, int n_eval, const double *u_eval,
                    double *out, double *cond_out)
{
    int m, k, e, q, s, status, Nuse;
    double cond = INFINITY;
    double *sol = NULL, *ser[4] = {NULL, NULL, NULL, NULL};
    double *cur = NULL, *nxt = NULL;

    if (n < 1 || n > 4 || !c || !d || n_eval < 0 ||
        (n_eval > 0 && (!u_eval || !out)) || (rhs_deg >= 0 && !rhs) ||
        (N > 0 && N < 2) || N > 1000000)
        return 1;
    if (c[0] == 0.0)
        return 1;
    for (k = 0; k <= n; ++k)
        if (!isfinite(c[k]))
            return 1;
    for (k = 0; k < 2 * n; ++k)
        if (!isfinite(d[k]))
            return 1;
    for (k = 0; k <= rhs_deg; ++k)
        if (!isfinite(rhs[k]))
            return 1;
    if (rhs_deg < 0)
        rhs_deg = -1;
    m = 2 * n;

    if (N > 0) {
        Nuse = N;
        sol = malloc(sizeof(double) * (size_t)(Nuse + m));
        if (!sol)
            return 2;
        status = solve_fixed(n, c, rhs_deg, rhs, d, Nuse, sol, &cond);
    } else {
        /* Adaptive: double N until the Chebyshev tail of G^{(m)} is at
         * rounding level, or stops decreasing (noise plateau), or the cap. */
        double prev_tail = INFINITY;
        Nuse = ORACLE_CHEB_BVP_N_START;
        if (Nuse < rhs_deg + 9)
            Nuse = rhs_deg + 9;
        for (;;) {
            double tr;
            free(sol);
            sol = malloc(sizeof(double) * (size_t)(Nuse + m));
            if (!sol)
                return 2;
            status = solve_fixed(n, c, rhs_deg, rhs, d, Nuse, sol, &cond);
            if (status != 0)
                break;
            tr = tail_ratio(sol, Nuse);
            if (tr <= 1e-15 || tr > 0.1 * prev_tail ||
                2 * Nuse > ORACLE_CHEB_BVP_N_MAX)
                break;
            prev_tail = tr;
            Nuse *= 2;
        }
    }
    if (cond_out)
        *cond_out = cond;
    if (status != 0) {
        free(sol);
        return status;
    }

    /* Chebyshev series of G^{(q)} - (polynomial part), q = 0..min(3,m):
     * ser[q] = J^{m-q} w, length Nuse + m - q.  For q = m+1 (n = 1, q = 3)
     * ser[3] = w' (length Nuse - 1, at least 1). */
    cur = malloc(sizeof(double) * (size_t)(Nuse + m + 1));
    nxt = malloc(sizeof(double) * (size_t)(Nuse + m + 1));
    for (q = 0; q < 4; ++q)
        ser[q] = malloc(sizeof(double) * (size_t)(Nuse + m + 1));
    if (!cur || !nxt || !ser[0] || !ser[1] || !ser[2] || !ser[3]) {
        status = 2;
        goto done;
    }
    memcpy(cur, sol, sizeof(double) * (size_t)Nuse);
    if (m <= 3)
        memcpy(ser[m], sol, sizeof(double) * (size_t)Nuse);
    if (m < 3)
        cheb_derivative_u(sol, Nuse, ser[3]);
    for (s = 1; s <= m; ++s) {
        double *tmp;
        cheb_integrate_u(cur, Nuse + s - 1, nxt);
        tmp = cur;
        cur = nxt;
        nxt = tmp;
        q = m - s;
        if (q <= 3)
            memcpy(ser[q], cur, sizeof(double) * (size_t)(Nuse + s));
    }

    for (e = 0; e < n_eval; ++e) {
        double u = u_eval[e];
        double x = 2.0 * u - 1.0;
        for (q = 0; q < 4; ++q) {
            double v, poly = 0.0;
            int len;
            if (q <= m)
                len = Nuse + m - q;
            else
                len = Nuse > 1 ? Nuse - 1 : 1;
            v = cheb_eval(ser[q], len, x);
            /* polynomial part: sum_{i=q}^{m-1} b_i u^{i-q}/(i-q)! (Horner) */
            for (k = m - 1; k >= q; --k)
                poly = poly * u / (double)(k - q + 1) + sol[Nuse + k];
            out[(size_t)e * 4 + (size_t)q] = v + poly;
        }
    }
    status = 0;

done:
    free(sol);
    free(cur);
    free(nxt);
    for (q = 0; q < 4; ++q)
        free(ser[q]);
    return status;
}
