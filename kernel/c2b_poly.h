/**
 * @file c2b_poly.h
 * Real polynomials in u in the monomial basis, and the exact polynomial parts of the
 * blend (MATH.md sections 3-5):
 *  - the Hermite basis of degree 2n-1 (quintic for C2, thesis eq. 18);
 *  - particular polynomial solutions of a mode ODE with polynomial right-hand side;
 *  - the triangular recursion that solves the PDE exactly for boundary data that are
 *    polynomials in v.
 * A polynomial is a coefficient array p[0..deg] (p[k] multiplies u^k) plus its degree;
 * the caller owns every buffer.
 */
#ifndef C2B_POLY_H
#define C2B_POLY_H

#include "c2b_error.h"
#include "c2b_operator.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest polynomial degree the kernel handles in u. */
#define C2B_POLY_MAX_DEG 48

/** A polynomial in u with inline storage. deg = -1 is the zero polynomial. */
typedef struct c2b_poly {
    int deg;
    double c[C2B_POLY_MAX_DEG + 1];
} c2b_poly;

/** Node j of np Chebyshev points on [0, 1] (0.5 when np == 1). */
double c2b_poly_cheb_node(int j, int np);

/**
 * Monomial coefficients coef[0..np-1] of the polynomial through (x[j], y[j]),
 * j < np (np <= C2B_POLY_MAX_DEG + 1, distinct nodes), via Newton divided differences.
 * Well conditioned for the low degrees used here on Chebyshev nodes in [0, 1].
 */
void c2b_poly_interpolate(int np, const double *x, const double *y, double *coef);

/** Set p to zero. */
void c2b_poly_zero(c2b_poly *p);

/** Values of p and its derivatives p^{(k)}(u), k = 0..maxd, into out[k]. */
void c2b_poly_eval(const c2b_poly *p, double u, int maxd, double *out);

/** q = p^{(k)} (q may alias p). */
void c2b_poly_derivative(const c2b_poly *p, int k, c2b_poly *q);

/** Boundary data of p for n constraints: p^{(q)}(0) then p^{(q)}(1), q < n, into d[2n]. */
void c2b_poly_boundary(const c2b_poly *p, int n, double *d);

/**
 * Hermite basis of degree 2n-1: basis[j] has derivative q at u=0 equal to [j == q]
 * and at u=1 equal to [j == n+q] (q < n). basis holds 2n polynomials.
 * @return C2B_OK, or C2B_ERR_ARG for n outside 1..C2B_MAX_N.
 */
c2b_status c2b_poly_hermite(int n, c2b_poly *basis, c2b_error *err);

/**
 * Particular solution P of sum_{k=0}^{n} c_k P^{(2(n-k))} = rhs, a polynomial found
 * by undetermined coefficients (a triangular solve). Some c_k may be zero; at least
 * c_0 must not be.
 * @return C2B_OK; C2B_ERR_LIMIT when the degree would exceed C2B_POLY_MAX_DEG;
 *         C2B_ERR_ARG when every c_k is zero.
 */
c2b_status c2b_poly_particular(int n, const double *c, const c2b_poly *rhs, c2b_poly *P,
                               c2b_error *err);

/**
 * Exact solution of the PDE of `op` (not the ODE class) for boundary data and force
 * that are polynomials in s = v - v0 (MATH.md section 3):
 *     S(u, v) = sum_{m=0}^{dm} G_m(u) s^m.
 * data[j * (dm+1) + m] is the s^m coefficient of boundary datum j (j < 2n, order
 * S, S_u, ... at u=0 then u=1). force (may be NULL) holds dm+1 polynomials in u:
 * the s^m coefficient of F. G receives dm+1 polynomials. Solved from m = dm down:
 *   a_0 G_m^{(2n)} = F_m - sum_{k>=1} a_k (m+2k)!/m! G_{m+2k}^{(2(n-k))},
 * each G_m = particular part + Hermite correction of its boundary data.
 * @return C2B_OK; C2B_ERR_LIMIT if degrees overflow C2B_POLY_MAX_DEG; C2B_ERR_ARG.
 */
c2b_status c2b_poly_solve_pde(const c2b_operator *op, int dm, const double *data,
                              const c2b_poly *force, c2b_poly *G, c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
