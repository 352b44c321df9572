/**
 * @file c2b_approx.h
 * The thesis' approximate analytic solutions of the C2 blend PDE, kept for comparison
 * with the exact closed form (c2b_blend.h). Spec form: "solver": "thesis-approx".
 *
 * Every boundary datum C_l(v, t) (l = 1..6: S, S_u, S_uu at u = 0, then at u = 1) gets
 * its own term H_l(u) C_l(v, t) (thesis eqs. 114, 126). Two groupings:
 *  - C2B_APPROX_DIFFERENTIAL (section 3.4.1, eqs. 95-126): data with C_l'' = 0 in v
 *    (group 1) take the quintic Hermite H_l = g_l exactly; all other data take the
 *    trial function of eq. 120,
 *        H_l(u) = g_l(u) - sum_{m=1..M} c_m [m pi f_m(u) - sin(m pi u)],
 *        f_m = g_2 + (-1)^m g_5,
 *    whose correction terms vanish with their first two u-derivatives at u = 0 and 1,
 *    so the boundary data hold exactly. Data with C_l'' = beta C_l (group 2) are
 *    detected and reported. By default they are solved with eq. 120, as the thesis
 *    does for its Tables 1 and 3; with group2_closed they take their closed form
 *    instead (section 3.4.1's group 2): H_l is the mode transfer function of
 *    c2b_mode.h for that beta, exact for any M.
 *  - C2B_APPROX_DECOMPOSITION (section 3.3, eqs. 59-86): every datum is split into
 *    C^(1) + C^(2)(t) + C^(3)(v) + C^(4)(v, t) (eq. 59), with <C>(t) the mean over v
 *    and t0 the creation time: part 0 = <C>(t) (constants and t-only, eqs. 64, 69)
 *    takes g_l exactly; part 1 = C(v, t0) - <C>(t0) (eq. 73) and part 2, the rest (eq. 85),
 *    each take the eq. 120 trial function with their own c_m (a part that is
 *    identically zero takes no term). A datum such as h + sin(2 pi v) thus keeps its
 *    constant h exact instead of spreading the sine series over it.
 * The c_m minimise the squared PDE residual (eq. 117) at the (I+1) x (J+1) uniform
 * points u_i = i/I, v_j = v0 + j (v1 - v0)/J (eq. 124). The thesis solves the normal
 * equations (eq. 125); here the overdetermined system itself is solved by LAPACK's
 * rank-revealing QR with column pivoting (dgelsy) after scaling every column to unit
 * norm. Forming A^T A squares the condition number, and the columns of eq. 123 differ
 * by (M pi)^6 ~ 1e10 in scale at M = 20, so the normal equations lose up to all 16
 * digits where QR loses about half as many; dgelsy also reports the numerical rank.
 */
#ifndef C2B_APPROX_H
#define C2B_APPROX_H

#include <stddef.h>

#include "c2b_error.h"
#include "c2b_vdata.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Grouping of the boundary data (see the file comment). */
typedef enum c2b_approx_approach {
    C2B_APPROX_DIFFERENTIAL = 0, /**< thesis section 3.4.1 (default) */
    C2B_APPROX_DECOMPOSITION = 1 /**< thesis section 3.3 */
} c2b_approx_approach;

/** Largest number of sine terms M. */
#define C2B_APPROX_MAX_M 64

/** Method settings. */
typedef struct c2b_approx_options {
    int M;            /**< sine terms of eq. 120, 1..C2B_APPROX_MAX_M (default 20) */
    int ci, cj;         /**< collocation grid (I+1) x (J+1), I, J >= 1 (default 100, 100) */
    double rcond;     /**< dgelsy rank threshold (default 1e-13) */
    double zero_rel;  /**< |C''| or |C'| below zero_rel * max|C| on the grid counts as 0 (1e-12) */
    c2b_approx_approach approach;
    int group2_closed; /**< 1: group 2 data take their closed form; 0: eq. 120 (default) */
} c2b_approx_options;

/** Defaults: M = 20, I = J = 100 (the thesis' settings), rcond 1e-13, zero_rel 1e-12,
 *  the differential-property approach, group 2 data solved with eq. 120. */
c2b_approx_options c2b_approx_options_default(void);

typedef struct c2b_approx c2b_approx;

/** How one datum was treated. */
typedef enum c2b_approx_group {
    C2B_APPROX_ZERO = 0,     /**< identically zero: no term */
    C2B_APPROX_HERMITE = 1,  /**< exact quintic Hermite term (group 1 / C^(1), C^(2)) */
    C2B_APPROX_MODE = 2,     /**< C'' = beta C (group 2): least squares, or closed form
                                  with group2_closed */
    C2B_APPROX_SERIES = 3    /**< general function (group 3 / C^(3), C^(4)), least squares */
} c2b_approx_group;

/**
 * Build the approximate solution of the C2 PDE with shape parameters
 * shape[c][0..3] = (gamma, eta, lambda, rho) on the v-domain dom at time t. The data
 * and their contexts are referenced and must outlive the object.
 * @return C2B_OK; C2B_ERR_ARG for NULL arguments or options out of range (the message
 *         names the option: "M", "collocation"); C2B_ERR_SPEC for gamma = 0, non-finite
 *         shape parameters or non-finite data (naming component, side and order);
 *         C2B_ERR_NUMERIC when the least-squares problem is rank deficient or dgelsy
 *         fails, or when a group 2 datum's closed form is resonant (group2_closed);
 *         C2B_ERR_NOMEM.
 */
c2b_status c2b_approx_create(const double shape[C2B_NCOMP][5], const c2b_vdomain *dom,
                             const c2b_vdata *data, double t, const c2b_approx_options *opt,
                             c2b_approx **out, c2b_error *err);

/** Free. NULL-safe. */
void c2b_approx_destroy(c2b_approx *a);

/** Move to time t: the least squares of time-dependent data are solved again.
 *  @return as c2b_approx_create(); on failure the previous time is kept. */
c2b_status c2b_approx_set_time(c2b_approx *a, double t, c2b_error *err);

/**
 * Evaluate on the grid u[0..nu) x v[0..nv) (point index i * nv + j), derivatives up to
 * order (0..2) in the layout of c2b_blend.h: [S, Su, Sv, Suu, Suv, Svv] x 3.
 * out holds nu * nv * c2b_blend_deriv_count(order) * 3 doubles.
 * @return C2B_OK; C2B_ERR_ARG for NULL buffers or order outside 0..2; C2B_ERR_NOMEM.
 */
c2b_status c2b_approx_eval_grid(const c2b_approx *a, size_t nu, const double *u, size_t nv,
                                const double *v, int order, double *out, c2b_error *err);

/** The treatment of term `part` of datum (component c, side, order p) and, for
 *  least-squares terms, the coefficients c_1..c_M (coef may be NULL; it receives M
 *  values, zeros otherwise, as for a group 2 datum in closed form) and the numerical
 *  rank (rank may be NULL; 0 for terms without least squares). part is 0 in
 *  the differential approach and 0..2 (constant and t-only, v-only, (v, t)) in the
 *  decomposition. Returns C2B_APPROX_ZERO for indices out of range. */
c2b_approx_group c2b_approx_datum(const c2b_approx *a, int c, int side, int p, int part,
                                  double *coef, int *rank);

/** Root-mean-square PDE residual over the collocation grid after the fit, summed over
 *  all least-squares data, in model units (0 when every datum is exact). */
double c2b_approx_residual_rms(const c2b_approx *a);

#ifdef __cplusplus
}
#endif
#endif
