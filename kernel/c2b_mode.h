/**
 * @file c2b_mode.h
 * Closed-form solution of one mode ODE (MATH.md section 2):
 *     sum_{k=0}^{n} c_k G^{(2(n-k))}(u) = 0 on [0,1],
 *     G^{(p)}(0) = d[p], G^{(p)}(1) = d[n+p], p = 0..n-1.
 *
 * Method (one mechanism for every parameter set):
 *  - exponents r = +-sqrt(z_i) from the operator's characteristic roots, in complex
 *    arithmetic;
 *  - exponents closer than the cluster tolerance are grouped; a cluster's basis
 *    functions are the divided differences of exp(r (u - u_a)) over its nodes. They
 *    span exactly the solution space for distinct nodes, tend continuously to
 *    (u - u_a)^k exp(r (u - u_a)) / k! as nodes merge, and stay well conditioned when
 *    they are nearly repeated;
 *  - the anchor u_a is 1 when Re r > 0, else 0, so no basis function exceeds
 *    e^(cluster span) on [0,1]: modes with |r| in the thousands neither overflow nor
 *    lose conditioning;
 *  - the 2n x 2n boundary system is row-equilibrated, inverted with LAPACK, and its
 *    1-norm condition number is computed exactly; above the limit the mode is
 *    resonant and creation fails.
 * The inverse gives the transfer functions H_j(u) = sum_i Minv[i][j] phi_i(u), the
 * response to unit datum j. A mode object depends only on (operator, beta) and is
 * reused for every component and time frame that needs it.
 */
#ifndef C2B_MODE_H
#define C2B_MODE_H

#include <complex.h>

#include "c2b_error.h"
#include "c2b_operator.h"
#include "c2b_tolerance.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Opaque solved mode (transfer functions for one beta and one operator). */
typedef struct c2b_mode c2b_mode;

/**
 * Solve the boundary system of the mode with f'' = beta f for operator `op`.
 * `tol` may be NULL (defaults). On success *out owns a new object; free it with
 * c2b_mode_destroy().
 * @return C2B_OK; C2B_ERR_ARG for NULL arguments or non-finite beta; C2B_ERR_NUMERIC
 *         when the system is singular or its condition estimate exceeds
 *         tol->cond_limit (resonance; the message gives beta, the estimate and the
 *         shape parameters) or when the transfer functions are not real;
 *         C2B_ERR_NOMEM.
 */
c2b_status c2b_mode_create(const c2b_operator *op, double beta, const c2b_tolerances *tol,
                           c2b_mode **out, c2b_error *err);

/** Free a mode. NULL-safe. */
void c2b_mode_destroy(c2b_mode *m);

/** Order of the boundary system, 2n. */
int c2b_mode_size(const c2b_mode *m);

/** The beta the mode was built for. */
double c2b_mode_beta(const c2b_mode *m);

/** 1-norm condition number of the row-equilibrated boundary system. */
double c2b_mode_condition(const c2b_mode *m);

/** Copy the 2n exponents r_i (1/unit u) into r (caller buffer of C2B_MAX_M). */
void c2b_mode_exponents(const c2b_mode *m, double complex *r);

/** Number of divided-difference clusters holding more than one exponent. */
int c2b_mode_repeated_clusters(const c2b_mode *m);

/**
 * Basis values phi_i^{(p)}(u) for p = 0..maxd (maxd <= 3), i = 0..2n-1, written to
 * phi[p * 2n + i] (caller buffer of (maxd+1)*2n). u is in [0,1] (extrapolation works
 * but may grow). No failure mode.
 */
void c2b_mode_basis(const c2b_mode *m, double u, int maxd, double complex *phi);

/**
 * Basis coefficients for real boundary data d[0..2n-1] (order: S, S_u, ... at u=0,
 * then at u=1): coef = Minv d. coef is a caller buffer of 2n.
 */
void c2b_mode_coefficients(const c2b_mode *m, const double *d, double complex *coef);

/** G^{(p)} = Re sum_i coef_i phi[p*2n + i], from c2b_mode_basis() output. */
double c2b_mode_combine(const c2b_mode *m, const double complex *coef,
                        const double complex *phi, int p);

/**
 * Convenience: G^{(p)}(u) for p = 0..maxd (maxd <= 3) for data d, written to G[p].
 */
void c2b_mode_eval(const c2b_mode *m, const double *d, double u, int maxd, double *G);

#ifdef __cplusplus
}
#endif
#endif
