/*
 * cheb_bvp.c -- independent Chebyshev spectral BVP oracle (see cheb_bvp.h).
 *
 * Conventions used throughout this file:
 *   [0,1] is split into S equal elements of width h = 1/S; on element e,
 *   u = u_e + h (x+1)/2 with x in [-1,1], midpoint mid_e = u_e + h/2;
 *   a Chebyshev series is f(x) = sum_{k<len} f[k] T_k(x) (no halved f[0]);
 *   "J" is integration in u starting at the element midpoint (x = 0), so
 *   d/du (J f) = f and (J f)(mid_e) = 0.
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

/* F (length len+1) = J f for f of length len >= 1, where du = hh dx
 * (hh = h/2).  Uses the exact relations
 *   int T_0 = T_1,  int T_1 = T_2/4,
 *   int T_k = T_{k+1}/(2(k+1)) - T_{k-1}/(2(k-1))   (k >= 2),
 * then fixes the constant so that F(x=0) = 0 (T_k(0) = cos(k pi/2)). */
static void cheb_integrate(const double *f, int len, double hh, double *F)
{
    int k;
    double at0 = 0.0; /* sum_{k>=1} F_k T_k(0) */
    for (k = 1; k <= len; ++k) {
        double fm = f[k - 1];
        double fp = (k + 1 < len) ? f[k + 1] : 0.0;
        double v;
        if (k == 1)
            v = fm - 0.5 * fp;
        else
            v = (fm - fp) / (2.0 * (double)k);
        F[k] = v;
        if ((k & 1) == 0)
            at0 += (k & 2) ? -v : v;
    }
    F[0] = -at0;
    for (k = 0; k <= len; ++k)
        F[k] *= hh;
}

/* df (length max(len-1,1)) = d/du f, with du = hh dx. */
static void cheb_derivative(const double *f, int len, double hh, double *df)
{
    int k;
    double bkp1 = 0.0, bk = 0.0; /* b_{k+1}, b_k */
    if (len <= 1) {
        df[0] = 0.0;
        return;
    }
    /* d/dx coefficients: b_{k-1} = b_{k+1} + 2 k f_k, b_{len-1} = b_len = 0 */
    for (k = len - 1; k >= 1; --k) {
        double bkm1 = bkp1 + 2.0 * (double)k * f[k];
        df[k - 1] = bkm1;
        bkp1 = bk;
        bk = bkm1;
    }
    df[0] *= 0.5;
    for (k = 0; k < len - 1; ++k)
        df[k] /= hh;
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

/* sum_{i=q}^{m-1} b_i t^{i-q}/(i-q)!  (Horner) */
static double taylor_part(const double *b, int m, int q, double t)
{
    double v = 0.0;
    int i;
    for (i = m - 1; i >= q; --i)
        v = v * t / (double)(i - q + 1) + b[i];
    return v;
}

/* Round a positive scale factor to the nearest power of two (exact scaling). */
static double pow2_round(double s)
{
    int e;
    double mt;
    if (!(s > 0.0) || !isfinite(s))
        return 1.0;
    mt = frexp(s, &e); /* s = mt 2^e, mt in [0.5,1) */
    if (mt > 0.70710678118654752)
        return ldexp(1.0, e);
    return ldexp(1.0, e - 1);
}

/* Upper bound for max |r| over the roots of chi(r) = sum_k c[k] r^{2(n-k)}:
 * Fujiwara's bound for s = r^2, |s| <= 2 max_k |c[k]/c[0]|^{1/k}. */
static double root_bound(int n, const double *c)
{
    double sb = 0.0;
    int k;
    for (k = 1; k <= n; ++k) {
        double v = pow(fabs(c[k] / c[0]), 1.0 / (double)k);
        if (v > sb)
            sb = v;
    }
    return sqrt(2.0 * sb);
}

/* Number of elements: keep (max|r|) * h <= ORACLE_CHEB_BVP_KH. */
static int choose_elements(int n, const double *c)
{
    double K = root_bound(n, c);
    double s = ceil(K / ORACLE_CHEB_BVP_KH);
    if (!(s >= 1.0))
        return 1;
    if (s > ORACLE_CHEB_BVP_S_MAX)
        return ORACLE_CHEB_BVP_S_MAX;
    return (int)s;
}

/* ---------------------------------------------------------------------- */
/* One solve at fixed (N, S)                                              */
/* ---------------------------------------------------------------------- */

/* Unknowns, per element e (block of B = N + m columns starting at e*B):
 *   [0..N-1]   Chebyshev coefficients of G^{(m)} on the element,
 *   [N..N+m-1] b_i = G^{(i)}(mid_e).
 * Rows: e*N + i collocation; then S*N + [0..n-1] left BCs; then
 * S*N + n + e*m + q continuity of G^{(q)} between e and e+1 (e < S-1);
 * then the last n rows right BCs.
 * Returns 0 / 2 / 3 / 4 as oracle_cheb_bvp. */
static int solve_fixed(int n, const double *c, int rhs_deg, const double *rhs,
                       const double *d, int N, int S, double *sol,
                       double *cond)
{
    const int m = 2 * n;
    const int B = N + m;
    const int M = S * B;
    const int L = N + m; /* max series length of J^s e_j, s <= m */
    const double h = 1.0 / (double)S;
    const double hh = 0.5 * h;
    double *A = NULL, *As = NULL, *T = NULL, *work = NULL, *comb = NULL;
    double *blk = NULL, *endv = NULL, *xloc = NULL;
    double *bv = NULL, *xs = NULL, *rr = NULL, *cc = NULL, *pr = NULL;
    double *pc = NULL;
    lapack_int *ipiv = NULL;
    double rowcnd, colcnd, amax, anorm, rcond = 0.0;
    lapack_int info;
    int i, j, k, s, q, e, it, status = 0;

    A = malloc(sizeof(double) * (size_t)M * (size_t)M);
    As = malloc(sizeof(double) * (size_t)M * (size_t)M);
    T = malloc(sizeof(double) * (size_t)N * (size_t)L);
    work = malloc(sizeof(double) * 2 * (size_t)(L + 1));
    comb = malloc(sizeof(double) * (size_t)(L + 1));
    blk = malloc(sizeof(double) * (size_t)N * (size_t)B);
    endv = malloc(sizeof(double) * 2 * (size_t)m * (size_t)B);
    xloc = malloc(sizeof(double) * (size_t)N);
    bv = malloc(sizeof(double) * (size_t)M);
    xs = malloc(sizeof(double) * (size_t)M);
    rr = malloc(sizeof(double) * (size_t)M);
    cc = malloc(sizeof(double) * (size_t)M);
    pr = malloc(sizeof(double) * (size_t)M);
    pc = malloc(sizeof(double) * (size_t)M);
    ipiv = malloc(sizeof(lapack_int) * (size_t)M);
    if (!A || !As || !T || !work || !comb || !blk || !endv || !xloc || !bv ||
        !xs || !rr || !cc || !pr || !pc || !ipiv) {
        status = 2;
        goto done;
    }
    memset(A, 0, sizeof(double) * (size_t)M * (size_t)M);

    /* Chebyshev-Gauss points x_i = cos(theta_i) and T_k(x_i) = cos(k th). */
    for (i = 0; i < N; ++i) {
        double th = ORACLE_PI * (2.0 * i + 1.0) / (2.0 * N);
        xloc[i] = cos(th);
        for (k = 0; k < L; ++k)
            T[(size_t)i * (size_t)L + (size_t)k] = cos((double)k * th);
    }

    /* Local blocks (identical for every element):
     *   blk[i*B + j]          collocation row i, local column j;
     *   endv[(side*m+q)*B+j]  G^{(q)} at x = -1 (side 0) / +1 (side 1). */
    for (j = 0; j < N; ++j) {
        double *cur = work, *nxt = work + (L + 1);
        int len = j + 1;
        memset(cur, 0, sizeof(double) * (size_t)len);
        cur[j] = 1.0;
        memset(comb, 0, sizeof(double) * (size_t)(j + 1 + m));
        comb[j] = c[0];
        for (s = 1; s <= m; ++s) {
            double *tmp;
            double sp = 0.0, sm = 0.0;
            cheb_integrate(cur, len, hh, nxt);
            ++len;
            tmp = cur;
            cur = nxt;
            nxt = tmp;
            if ((s & 1) == 0 && c[s / 2] != 0.0)
                for (k = 0; k < len; ++k)
                    comb[k] += c[s / 2] * cur[k];
            /* G^{(m-s)} at x = +-1 gets (J^s e_j)(+-1) */
            for (k = len - 1; k >= 0; --k) {
                sp += cur[k];
                sm += (k & 1) ? -cur[k] : cur[k];
            }
            q = m - s;
            endv[(size_t)(0 * m + q) * (size_t)B + (size_t)j] = sm;
            endv[(size_t)(1 * m + q) * (size_t)B + (size_t)j] = sp;
        }
        for (i = 0; i < N; ++i) {
            const double *Ti = T + (size_t)i * (size_t)L;
            double sum = 0.0;
            for (k = j + m; k >= 0; --k)
                sum += comb[k] * Ti[k];
            blk[(size_t)i * (size_t)B + (size_t)j] = sum;
        }
    }
    /* Taylor part sum_i b_i t^i / i!, t = u - mid = hh x. */
    for (j = 0; j < m; ++j) {
        for (i = 0; i < N; ++i) {
            double t = hh * xloc[i], sum = 0.0;
            for (k = 0; k <= n; ++k) {
                int order = m - 2 * k; /* derivative order hit by c[k] */
                if (c[k] != 0.0 && j >= order)
                    sum += c[k] * pow(t, (double)(j - order)) /
                           factorial(j - order);
            }
            blk[(size_t)i * (size_t)B + (size_t)(N + j)] = sum;
        }
        for (q = 0; q < m; ++q) {
            double vm = 0.0, vp = 0.0;
            if (j >= q) {
                vm = pow(-hh, (double)(j - q)) / factorial(j - q);
                vp = pow(hh, (double)(j - q)) / factorial(j - q);
            }
            endv[(size_t)(0 * m + q) * (size_t)B + (size_t)(N + j)] = vm;
            endv[(size_t)(1 * m + q) * (size_t)B + (size_t)(N + j)] = vp;
        }
    }

    /* Assemble (column-major A[row + col*M]). */
    for (e = 0; e < S; ++e) {
        const size_t c0 = (size_t)e * (size_t)B;
        const double ue = (double)e * h;
        for (i = 0; i < N; ++i) {
            const size_t row = (size_t)e * (size_t)N + (size_t)i;
            /* u_i = u_e + h (1+x_i)/2 = u_e + h cos^2(theta_i/2) */
            double th = ORACLE_PI * (2.0 * i + 1.0) / (2.0 * N);
            double ch = cos(0.5 * th);
            double u = ue + h * ch * ch, v = 0.0;
            for (j = 0; j < B; ++j)
                A[row + (c0 + (size_t)j) * (size_t)M] =
                    blk[(size_t)i * (size_t)B + (size_t)j];
            for (k = rhs_deg; k >= 0; --k)
                v = v * u + rhs[k];
            bv[row] = v;
        }
    }
    for (q = 0; q < n; ++q) {
        const size_t rowl = (size_t)S * (size_t)N + (size_t)q;
        const size_t rowr = (size_t)M - (size_t)n + (size_t)q;
        const size_t cl = 0, cr = (size_t)(S - 1) * (size_t)B;
        for (j = 0; j < B; ++j) {
            A[rowl + (cl + (size_t)j) * (size_t)M] =
                endv[(size_t)(0 * m + q) * (size_t)B + (size_t)j];
            A[rowr + (cr + (size_t)j) * (size_t)M] =
                endv[(size_t)(1 * m + q) * (size_t)B + (size_t)j];
        }
        bv[rowl] = d[q];
        bv[rowr] = d[n + q];
    }
    for (e = 0; e + 1 < S; ++e) {
        const size_t cL = (size_t)e * (size_t)B, cR = cL + (size_t)B;
        for (q = 0; q < m; ++q) {
            const size_t row = (size_t)S * (size_t)N + (size_t)n +
                               (size_t)e * (size_t)m + (size_t)q;
            for (j = 0; j < B; ++j) {
                A[row + (cL + (size_t)j) * (size_t)M] =
                    endv[(size_t)(1 * m + q) * (size_t)B + (size_t)j];
                A[row + (cR + (size_t)j) * (size_t)M] =
                    -endv[(size_t)(0 * m + q) * (size_t)B + (size_t)j];
            }
            bv[row] = 0.0;
        }
    }

    /* Physical pre-scaling with a characteristic wavenumber kc (a power of
     * two, so exact): unknowns a -> a / kc^m, b_i -> b_i / kc^i; equations
     * for G^{(q)} (collocation: q = m) divided by kc^q.  This makes all the
     * blocks O(1) when the solution varies on the scale 1/kc; LAPACK's
     * dgeequ then equilibrates the rest. */
    {
        double kc = root_bound(n, c);
        int lk;
        if (kc < 1.0 / hh)
            kc = 1.0 / hh;
        (void)frexp(pow2_round(kc), &lk);
        lk -= 1; /* kc = 2^lk */
        for (e = 0; e < S; ++e) {
            for (j = 0; j < B; ++j)
                pc[(size_t)e * (size_t)B + (size_t)j] =
                    ldexp(1.0, lk * (j < N ? m : j - N));
            for (i = 0; i < N; ++i)
                pr[(size_t)e * (size_t)N + (size_t)i] = ldexp(1.0, -lk * m);
        }
        for (q = 0; q < n; ++q) {
            pr[(size_t)S * (size_t)N + (size_t)q] = ldexp(1.0, -lk * q);
            pr[(size_t)M - (size_t)n + (size_t)q] = ldexp(1.0, -lk * q);
        }
        for (e = 0; e + 1 < S; ++e)
            for (q = 0; q < m; ++q)
                pr[(size_t)S * (size_t)N + (size_t)n + (size_t)e * (size_t)m +
                   (size_t)q] = ldexp(1.0, -lk * q);
        for (j = 0; j < M; ++j)
            for (i = 0; i < M; ++i)
                A[(size_t)i + (size_t)j * (size_t)M] *= pr[i] * pc[j];
        for (i = 0; i < M; ++i)
            bv[i] *= pr[i];
    }

    /* Equilibrate with power-of-two factors. */
    info = LAPACKE_dgeequ(LAPACK_COL_MAJOR, M, M, A, M, rr, cc, &rowcnd,
                          &colcnd, &amax);
    if (info > 0) {
        *cond = INFINITY;
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
        bv[i] *= rr[i];
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

    memcpy(xs, bv, sizeof(double) * (size_t)M);
    info = LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', M, 1, A, M, ipiv, xs, M);
    if (info != 0) {
        status = 4;
        goto done;
    }
    /* Iterative refinement, residual accumulated in long double. */
    for (it = 0; it < 2; ++it) {
        for (i = 0; i < M; ++i) {
            long double r = (long double)bv[i];
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
        sol[i] = xs[i] * cc[i] * pc[i];

done:
    free(A);
    free(As);
    free(T);
    free(work);
    free(comb);
    free(blk);
    free(endv);
    free(xloc);
    free(bv);
    free(xs);
    free(rr);
    free(cc);
    free(pr);
    free(pc);
    free(ipiv);
    return status;
}

/* Size of the last 8 Chebyshev coefficients of G^{(m)} (largest over the
 * elements) relative to the largest coefficient of G^{(m)} overall. */
static double tail_ratio(const double *sol, int N, int B, int S)
{
    double amax = 0.0, tmax = 0.0;
    int e, k, t0 = N > 8 ? N - 8 : 0;
    for (e = 0; e < S; ++e) {
        const double *a = sol + (size_t)e * (size_t)B;
        for (k = 0; k < N; ++k) {
            double v = fabs(a[k]);
            if (v > amax)
                amax = v;
            if (k >= t0 && v > tmax)
                tmax = v;
        }
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
    int m, k, e, q, s, status, Nuse, S, B;
    double cond = INFINITY, h, hh;
    double *sol = NULL, *ser = NULL, *cur = NULL, *nxt = NULL;
    size_t sstride, estride;

    if (n < 1 || n > 4 || !c || !d || n_eval < 0 ||
        (n_eval > 0 && (!u_eval || !out)) || (rhs_deg >= 0 && !rhs) ||
        (N > 0 && N < 2) || N > ORACLE_CHEB_BVP_N_MAX)
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
    S = choose_elements(n, c);
    h = 1.0 / (double)S;
    hh = 0.5 * h;

    if (N > 0 && (long)N * (long)S > 2L * ORACLE_CHEB_BVP_SIZE_MAX)
        return 1; /* dense system would be too large */
    if (N > 0) {
        Nuse = N;
        sol = malloc(sizeof(double) * (size_t)S * (size_t)(Nuse + m));
        if (!sol)
            return 2;
        status = solve_fixed(n, c, rhs_deg, rhs, d, Nuse, S, sol, &cond);
    } else {
        /* Adaptive: double N until the Chebyshev tail of G^{(m)} is at
         * rounding level, or stops decreasing (noise plateau), or a cap. */
        double prev_tail = INFINITY;
        Nuse = ORACLE_CHEB_BVP_N_START;
        if (Nuse < rhs_deg + 9)
            Nuse = rhs_deg + 9;
        for (;;) {
            double tr;
            free(sol);
            sol = malloc(sizeof(double) * (size_t)S * (size_t)(Nuse + m));
            if (!sol)
                return 2;
            status = solve_fixed(n, c, rhs_deg, rhs, d, Nuse, S, sol, &cond);
            if (status != 0)
                break;
            tr = tail_ratio(sol, Nuse, Nuse + m, S);
            if (tr <= 1e-15 || tr > 0.1 * prev_tail ||
                2 * Nuse > ORACLE_CHEB_BVP_N_MAX ||
                2 * Nuse * S > ORACLE_CHEB_BVP_SIZE_MAX)
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
    B = Nuse + m;

    /* Per element, Chebyshev series of G^{(q)} minus its Taylor part,
     * q = 0..3: ser = J^{m-q} w (length B - q) for q <= m; for q = m+1
     * (n = 1, q = 3) ser = w' (length max(N-1,1)). */
    sstride = (size_t)(B + 1);
    estride = 4 * sstride;
    ser = malloc(sizeof(double) * (size_t)S * estride);
    cur = malloc(sizeof(double) * sstride);
    nxt = malloc(sizeof(double) * sstride);
    if (!ser || !cur || !nxt) {
        status = 2;
        goto done;
    }
    for (e = 0; e < S; ++e) {
        const double *a = sol + (size_t)e * (size_t)B;
        double *se = ser + (size_t)e * estride;
        memcpy(cur, a, sizeof(double) * (size_t)Nuse);
        if (m <= 3)
            memcpy(se + (size_t)m * sstride, a, sizeof(double) * (size_t)Nuse);
        if (m < 3)
            cheb_derivative(a, Nuse, hh, se + 3 * sstride);
        for (s = 1; s <= m; ++s) {
            double *tmp;
            cheb_integrate(cur, Nuse + s - 1, hh, nxt);
            tmp = cur;
            cur = nxt;
            nxt = tmp;
            q = m - s;
            if (q <= 3)
                memcpy(se + (size_t)q * sstride, cur,
                       sizeof(double) * (size_t)(Nuse + s));
        }
    }

    for (k = 0; k < n_eval; ++k) {
        double u = u_eval[k], x, t;
        const double *se, *bt;
        e = (int)floor(u * (double)S);
        if (e < 0)
            e = 0;
        if (e > S - 1)
            e = S - 1;
        x = 2.0 * (u - (double)e * h) / h - 1.0;
        t = u - ((double)e + 0.5) * h;
        se = ser + (size_t)e * estride;
        bt = sol + (size_t)e * (size_t)B + (size_t)Nuse;
        for (q = 0; q < 4; ++q) {
            int len;
            if (q <= m)
                len = B - q;
            else
                len = Nuse > 1 ? Nuse - 1 : 1;
            out[(size_t)k * 4 + (size_t)q] =
                cheb_eval(se + (size_t)q * sstride, len, x) +
                taylor_part(bt, m, q, t);
        }
    }
    status = 0;

done:
    free(sol);
    free(ser);
    free(cur);
    free(nxt);
    return status;
}
