/*
 * cheb_bvp.h -- independent test oracle: linear constant-coefficient
 * boundary-value ODE solver by Chebyshev spectral collocation.
 *
 * This code is deliberately self-contained (C11 + LAPACKE only) and shares
 * nothing with the C2Blend kernel, so that it can be used to check the
 * kernel's closed-form exponential solutions.
 *
 * Problem
 * -------
 * For n in {1,2,3,4} (ODE order m = 2n), real coefficients c[0..n] with
 * c[0] != 0 (other c[k] may be zero), and a polynomial right-hand side
 * p(u) = sum_i rhs[i] u^i,
 *
 *     sum_{k=0}^{n} c[k] * G^{(2(n-k))}(u) = p(u),     u in [0,1],
 *
 * with the Hermite-type boundary conditions
 *
 *     G^{(q)}(0) = d[q],   G^{(q)}(1) = d[n+q],   q = 0..n-1.
 *
 * Method (multi-element Chebyshev collocation, integral formulation)
 * -------------------------------------------------------------------
 * [0,1] is split into S equal elements of width h = 1/S (S is chosen from
 * the coefficients, see below; S = 1 for moderate coefficients).  On each
 * element, with local variable x in [-1,1] and midpoint u_mid, the unknowns
 * are the N Chebyshev coefficients a_j of the highest derivative
 * w = G^{(m)} plus the m Taylor coefficients b_i = G^{(i)}(u_mid):
 *
 *     G^{(m)}(u)   = sum_{j<N} a_j T_j(x)
 *     G^{(m-s)}(u) = (J^s w)(u) + sum_{i>=m-s} b_i (u-u_mid)^(i-m+s) / (i-m+s)!
 *
 * where J is the exact Chebyshev-coefficient integration operator,
 * (J f)(u) = int_{u_mid}^u f.  No differentiation matrix is ever formed:
 * every operator applied to the unknowns is an integration (bounded and
 * smoothing), which keeps the system well conditioned for orders 6 and 8.
 *
 * Equations: the ODE collocated at the N Chebyshev-Gauss points
 * x_i = cos(pi (2i+1)/(2N)) of every element; the 2n boundary conditions;
 * continuity of G, G', ..., G^{(m-1)} across every interior element
 * boundary.  The system is pre-scaled with powers of a characteristic
 * wavenumber kc = max(R, 2/h) (unknowns b_i ~ kc^i, a ~ kc^m; equation for
 * G^{(q)} ~ kc^q), then equilibrated (LAPACKE_dgeequ); all scale factors
 * are rounded to powers of two, so scaling is exact.  It is LU-factorised
 * (dgetrf), its 1-norm condition number estimated (dgecon), solved (dgetrs)
 * and improved by two steps of iterative refinement with the residual
 * accumulated in long double.
 *
 * Elements: R = Fujiwara's upper bound on max|r| over the roots r of the
 * characteristic polynomial chi(r) = sum_k c[k] r^{2(n-k)},
 * R = sqrt(2 max_k |c[k]/c[0]|^{1/k}), and
 * S = clamp(ceil(R / ORACLE_CHEB_BVP_KH), 1, ORACLE_CHEB_BVP_S_MAX), i.e.
 * R*h <= 8 per element.  This keeps the Taylor/integral split free of
 * cancellation (a single global Taylor expansion loses a relative factor
 * ~ (R h/2)^m / m!; e.g. 1e-9 accuracy only, at R = 60 with m = 6).
 *
 * The solution is evaluated with the Clenshaw recurrence on the Chebyshev
 * coefficients of J^{m-q} w (q <= m) on the element containing u, plus
 * Horner on the Taylor part.  For n = 1 the third derivative G''' = w' is
 * obtained by exact Chebyshev coefficient differentiation of w.
 *
 * On each element G is a polynomial of degree N-1+m; the global G is
 * C^{m-1}.  Evaluation points outside [0,1] are accepted (polynomial
 * extrapolation of the first/last element) but only [0,1] is meaningful.
 *
 * Accuracy measured with test_cheb_bvp.c (error normalised by
 * max_{[0,1]} |G^{(q)}| where G^{(q)} is small, pointwise relative
 * elsewhere; q = 0..3, default N): <= 1.2e-13 on every self-test case,
 * including |roots| = 60 for n = 1..4 and 200 for n = 3, 4.  Separately
 * measured for G^{(2n)} = K^{2n} G and n = 1..4: <= 3e-14 up to K = 200,
 * <= 2.1e-12 up to K = 400, <= 1.3e-11 at K = 700, and 1.6e-10 (n = 4) at
 * K = 1000, where S has hit its cap of 32.
 * Cost: one dense LU of size S*(N+2n): ~1 ms for S = 1, ~0.2 s for R ~ 200.
 */
#ifndef C2B_TEST_ORACLE_CHEB_BVP_H
#define C2B_TEST_ORACLE_CHEB_BVP_H

#ifdef __cplusplus
extern "C" {
#endif

/* Defaults / limits of the automatic choices of N and S (see above and
 * oracle_cheb_bvp).  KH may be overridden at compile time (testing only). */
#define ORACLE_CHEB_BVP_N_START 32
#define ORACLE_CHEB_BVP_N_MAX 1024
#define ORACLE_CHEB_BVP_SIZE_MAX 2048
#ifndef ORACLE_CHEB_BVP_KH
#define ORACLE_CHEB_BVP_KH 8.0
#endif
#define ORACLE_CHEB_BVP_S_MAX 32

/*
 * oracle_cheb_bvp -- solve the boundary-value problem described above.
 *
 *   n        half order, 1..4 (ODE order 2n).
 *   c        n+1 coefficients, c[0] != 0 (c[k] multiplies G^{(2(n-k))}).
 *   rhs_deg  degree of the polynomial right-hand side; < 0 means p = 0
 *            (rhs may then be NULL).
 *   rhs      rhs_deg+1 monomial coefficients, p(u) = sum_i rhs[i] u^i.
 *   d        2n boundary values: d[q] = G^{(q)}(0), d[n+q] = G^{(q)}(1).
 *   N        number of Chebyshev collocation points PER ELEMENT, equal to
 *            the number of Chebyshev coefficients of G^{(2n)} on each
 *            element (G is there a polynomial of degree N-1+2n).  The number
 *            of elements S is always chosen automatically (S = 1 unless the
 *            root bound R exceeds 8).  When given, 2 <= N <=
 *            ORACLE_CHEB_BVP_N_MAX and S*N <= 2*ORACLE_CHEB_BVP_SIZE_MAX
 *            (else return 1).  If N <= 0 it is chosen automatically:
 *            start at ORACLE_CHEB_BVP_N_START (32, or rhs_deg+9 if larger)
 *            and double until the last eight Chebyshev coefficients of
 *            G^{(2n)} (worst element) are below 1e-15 times the largest
 *            coefficient of G^{(2n)} on any element, or they stop decreasing
 *            by at least 10x (rounding plateau), or the next doubling would
 *            exceed N_MAX or make S*N > ORACLE_CHEB_BVP_SIZE_MAX; the last
 *            solve is returned.  (32 suffices for all moderate problems.)
 *   n_eval   number of evaluation points (>= 0).
 *   u_eval   evaluation abscissae (in [0,1]).
 *   out      4*n_eval doubles: out[e*4 + q] = G^{(q)}(u_eval[e]), q=0..3.
 *   cond_out may be NULL; otherwise receives the 1-norm condition estimate
 *            1/rcond (LAPACKE_dgecon) of the scaled + equilibrated
 *            collocation system actually solved (INFINITY if exactly
 *            singular).  The well-posed self-test problems give 6e1..2e4
 *            (up to ~8e6 for |roots| ~ 400); the singular self-test case
 *            (clamped beam at its first eigenvalue) gives ~2e17.
 *
 * Returns 0 on success; 1 for invalid arguments (n outside 1..4, c[0] == 0,
 * non-finite input, NULL pointers where data is required, bad N); 2 on
 * allocation failure; 3 if the collocation system is exactly singular
 * (dgetrf info > 0) or has a zero row/column; 4 for other LAPACK errors.
 * A nearly singular system still returns 0 -- check *cond_out.
 * out is written only on success.
 */
int oracle_cheb_bvp(int n, const double *c, int rhs_deg, const double *rhs,
                    const double *d, int N, int n_eval, const double *u_eval,
                    double *out, double *cond_out);

#ifdef __cplusplus
}
#endif

#endif /* C2B_TEST_ORACLE_CHEB_BVP_H */
