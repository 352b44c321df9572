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
 * c[0] != 0, and a polynomial right-hand side p(u) = sum_i rhs[i] u^i,
 *
 *     sum_{k=0}^{n} c[k] * G^{(2(n-k))}(u) = p(u),     u in [0,1],
 *
 * with the Hermite-type boundary conditions
 *
 *     G^{(q)}(0) = d[q],   G^{(q)}(1) = d[n+q],   q = 0..n-1.
 *
 * Method (integral / "highest derivative" formulation)
 * ---------------------------------------------------
 * The unknowns are the N Chebyshev coefficients a_j of the highest
 * derivative w = G^{(m)} (in the variable x = 2u-1 on [-1,1]) plus the m
 * Taylor coefficients b_i of a polynomial of degree < m:
 *
 *     G^{(m)}(u)   = sum_{j<N} a_j T_j(2u-1)
 *     G^{(m-s)}(u) = (J^s w)(u) + sum_{i>=m-s} b_i u^{i-(m-s)}/(i-(m-s))!
 *
 * where J is the exact Chebyshev-coefficient integration operator
 * (J f)(u) = int_0^u f, so (J^s w)^{(q)}(0) = 0 for q < s and hence
 * G^{(q)}(0) = b_q.  No differentiation matrix is ever formed; all the
 * operators applied to the unknowns are integrations (bounded, smoothing),
 * which keeps the linear system well conditioned even for orders 6 and 8.
 *
 * The N + m equations are: the ODE collocated at the N Chebyshev-Gauss
 * points x_i = cos(pi (2i+1)/(2N)) (interior points), and the 2n = m
 * boundary conditions.  The system is equilibrated (LAPACKE_dgeequ, scale
 * factors rounded to powers of two), LU-factorised (dgetrf), its 1-norm
 * condition number estimated (dgecon), solved (dgetrs) and improved by two
 * steps of iterative refinement with the residual accumulated in long double.
 *
 * The solution is evaluated with the Clenshaw recurrence on the Chebyshev
 * coefficients of J^{m-q} w (q <= m), plus Horner on the polynomial part.
 * For n = 1 the third derivative G''' = w' is obtained by exact Chebyshev
 * coefficient differentiation of w.
 *
 * The computed G is a polynomial of degree N-1+m.  Evaluation points
 * outside [0,1] are accepted (polynomial extrapolation) but only [0,1] is
 * meaningful.
 */
#ifndef C2B_TEST_ORACLE_CHEB_BVP_H
#define C2B_TEST_ORACLE_CHEB_BVP_H

#ifdef __cplusplus
extern "C" {
#endif

/* Default / limits of the automatic choice of N (see oracle_cheb_bvp). */
#define ORACLE_CHEB_BVP_N_START 32
#define ORACLE_CHEB_BVP_N_MAX 1024

/*
 * oracle_cheb_bvp -- solve the boundary-value problem described above.
 *
 *   n        half order, 1..4 (ODE order 2n).
 *   c        n+1 coefficients, c[0] != 0 (c[k] multiplies G^{(2(n-k))}).
 *   rhs_deg  degree of the polynomial right-hand side; < 0 means p = 0
 *            (rhs may then be NULL).
 *   rhs      rhs_deg+1 monomial coefficients, p(u) = sum_i rhs[i] u^i.
 *   d        2n boundary values: d[q] = G^{(q)}(0), d[n+q] = G^{(q)}(1).
 *   N        number of Chebyshev collocation points, equal to the number of
 *            Chebyshev coefficients of G^{(2n)} (G then has degree N-1+2n).
 *            N must be >= 2 when given.  If N <= 0 it is chosen
 *            automatically: starting at ORACLE_CHEB_BVP_N_START (32) and
 *            doubling up to ORACLE_CHEB_BVP_N_MAX (1024) until the last
 *            eight Chebyshev coefficients of G^{(2n)} are below
 *            1e-15 * (max coefficient) (if the cap is reached, the result of
 *            the cap is returned).
 *   n_eval   number of evaluation points (>= 0).
 *   u_eval   evaluation abscissae (in [0,1]).
 *   out      4*n_eval doubles: out[e*4 + q] = G^{(q)}(u_eval[e]), q=0..3.
 *   cond_out may be NULL; otherwise receives the 1-norm condition estimate
 *            1/rcond (LAPACKE_dgecon) of the equilibrated collocation
 *            system actually solved (INFINITY if exactly singular).
 *
 * Returns 0 on success; 1 for invalid arguments; 2 on allocation failure;
 * 3 if the collocation system is exactly singular (dgetrf info > 0) or
 * cannot be equilibrated (zero row/column); 4 for other LAPACK errors.
 * A nearly singular system still returns 0 -- check *cond_out.
 */
int oracle_cheb_bvp(int n, const double *c, int rhs_deg, const double *rhs,
                    const double *d, int N, int n_eval, const double *u_eval,
                    double *out, double *cond_out);

#ifdef __cplusplus
}
#endif

#endif /* C2B_TEST_ORACLE_CHEB_BVP_H */
