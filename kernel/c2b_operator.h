/**
 * @file c2b_operator.h
 * The blend PDE (MATH.md section 1) and its characteristic polynomial (section 2).
 *
 * A PDE of continuity order n (n = 2 for C1, 3 for C2, 4 for C3) is
 *     sum_{k=0}^{n} a_k d^{2n} S / (du^{2(n-k)} dv^{2k}) = F.
 * For a mode f(v) with f'' = beta f, S = G(u) f(v) gives the mode ODE
 *     sum_{k=0}^{n} c_k G^{(2(n-k))}(u) = 0,   c_k = a_k beta^k,
 * whose characteristic equation in z = r^2 is sum_k a_k beta^k z^{n-k} = 0. With
 * z = beta w, the roots w_i of the single polynomial sum_k a_k w^{n-k} serve every beta.
 * The ODE mode of seed 000 (rho G^(6) + eta G^(4) + lambda G'' = F) has no v-derivatives:
 * c_k = a_k for every mode and z = w.
 */
#ifndef C2B_OPERATOR_H
#define C2B_OPERATOR_H

#include <complex.h>

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Continuity classes (MATH.md section 1). */
typedef enum c2b_continuity {
    C2B_C1 = 1,  /**< order 4, shape (b, c, d), seed 001 eq. 2 */
    C2B_C2 = 2,  /**< order 6, shape (gamma, eta, lambda, rho), thesis eq. 5 */
    C2B_C3 = 3,  /**< order 8, shape (a0..a4) */
    C2B_ODE = 4  /**< seed 000 eq. 2, shape (rho, eta, lambda), no v-derivatives */
} c2b_continuity;

/** Largest number of constraints per trimline (C3). */
#define C2B_MAX_N 4
/** Largest order of the boundary system, 2 * C2B_MAX_N. */
#define C2B_MAX_M 8

/** One PDE operator: continuity class, coefficients and characteristic roots. Plain value. */
typedef struct c2b_operator {
    c2b_continuity continuity;
    int n;                        /**< constraints per trimline (S, S_u, ...): 2, 3 or 4 */
    double a[C2B_MAX_N + 1];      /**< a_0..a_n as above (ODE: a = rho, eta, lambda, 0) */
    int beta_free;                /**< 1 for C2B_ODE: mode ODE does not depend on beta */
    double complex w[C2B_MAX_N];  /**< roots of sum_k a_k w^{n-k} (n of them) */
} c2b_operator;

/** Number of shape parameters a continuity class takes: 3, 4, 5 or 3 (ODE). */
int c2b_continuity_nshape(c2b_continuity c);

/** Constraints per trimline (2, 3, 4; ODE 3). */
int c2b_continuity_n(c2b_continuity c);

/** "C1", "C2", "C3" or "ODE". */
const char *c2b_continuity_name(c2b_continuity c);

/** Name of shape parameter i of a class, e.g. "gamma" for C2 index 0. */
const char *c2b_continuity_param_name(c2b_continuity c, int i);

/**
 * Build an operator from `nshape` shape parameters (must equal
 * c2b_continuity_nshape(cont)) and compute its characteristic roots with LAPACK
 * (eigenvalues of the balanced companion matrix: backward stable).
 * @return C2B_OK; C2B_ERR_SPEC if a parameter is non-finite, the count is wrong or
 *         the leading parameter is zero (the order would drop); C2B_ERR_NUMERIC if
 *         the eigenvalue solver fails.
 */
c2b_status c2b_operator_init(c2b_operator *op, c2b_continuity cont, const double *shape,
                             int nshape, c2b_error *err);

/**
 * Check the shape parameters of `ncomp` components (rows of 5, the first
 * c2b_continuity_nshape(cont) used) exactly as c2b_operator_init() does, for solvers
 * that need no operator. Errors name the component: "shape (component y): ...".
 * @return C2B_OK; C2B_ERR_SPEC (non-finite or zero leading parameter); C2B_ERR_NUMERIC.
 */
c2b_status c2b_operator_check_shapes(c2b_continuity cont, int ncomp, const double (*shape)[5],
                                     c2b_error *err);

/** Mode-ODE coefficients c_0..c_n for a mode with f'' = beta f (see file comment). */
void c2b_operator_mode_coefficients(const c2b_operator *op, double beta, double *c);

/** The n roots z_i = r_i^2 of the mode's characteristic equation. */
void c2b_operator_z_roots(const c2b_operator *op, double beta, double complex *z);

/** 1 when two operators are the same PDE (same class and coefficients). */
int c2b_operator_equal(const c2b_operator *x, const c2b_operator *y);

/** Write "gamma=1, eta=1, lambda=1, rho=1" into buf (always NUL-terminated). */
void c2b_operator_describe(const c2b_operator *op, char *buf, int cap);

#ifdef __cplusplus
}
#endif
#endif
