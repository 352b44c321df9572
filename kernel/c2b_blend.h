/**
 * @file c2b_blend.h
 * A PDE blend surface S(u, v, t) between two trimlines (MATH.md sections 1-6).
 *
 * Built once from a ::c2b_problem: boundary data are expanded into modes, the modes'
 * transfer functions are computed and cached per (beta, operator), polynomial parts
 * are solved by the exact recursion, and force terms get particular solutions.
 * c2b_blend_set_time() re-projects only the time-dependent data; cached transfer
 * functions are reused, and time-independent data keep their projections, so
 * primaries that do not move give bit-identical surfaces at every t.
 *
 * Derivative layout (CONVENTIONS.md): for order k the nd = (k+1)(k+2)/2 entries per
 * point are [S, Su, Sv, Suu, Suv, Svv, Suuu, Suuv, Suvv, Svvv] truncated to nd; each
 * entry is 3 doubles (x, y, z). Output index: ((point * nd) + entry) * 3 + component.
 */
#ifndef C2B_BLEND_H
#define C2B_BLEND_H

#include <stddef.h>

#include "c2b_error.h"
#include "c2b_problem.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct c2b_blend c2b_blend;

/** Highest derivative order evaluated (S_uuu etc.). */
#define C2B_MAX_DERIV 3

/**
 * Create a blend for `pb` at pb->time. The problem is copied; its callbacks, contexts
 * and sample arrays are referenced and must outlive the blend.
 * @return C2B_OK; C2B_ERR_SPEC for bad shape parameters, domain or non-finite data
 *         (message names the datum's label); C2B_ERR_NUMERIC for a resonant mode
 *         (message names component, mode, beta, condition and shape parameters);
 *         C2B_ERR_LIMIT; C2B_ERR_NOMEM.
 */
c2b_status c2b_blend_create(const c2b_problem *pb, c2b_blend **out, c2b_error *err);

/** Free a blend. NULL-safe. */
void c2b_blend_destroy(c2b_blend *b);

/**
 * Move the blend to time t: time-dependent data are re-projected and the mode
 * coefficients recomputed; transfer functions are taken from the cache.
 * On failure the blend keeps its previous time and surface.
 * @return as c2b_blend_create().
 */
c2b_status c2b_blend_set_time(c2b_blend *b, double t, c2b_error *err);

/** The current time. */
double c2b_blend_time(const c2b_blend *b);

/** Number of derivative entries for order k: (k+1)(k+2)/2. */
size_t c2b_blend_deriv_count(int order);

/**
 * Evaluate at npts points (u[i], v[i]) with derivatives up to `order` (0..3).
 * out: caller buffer of npts * c2b_blend_deriv_count(order) * 3 doubles.
 * @return C2B_OK; C2B_ERR_ARG for NULL buffers, order outside 0..3 or non-finite
 *         u/v; C2B_ERR_LIMIT above tol.max_eval_points.
 */
c2b_status c2b_blend_eval(const c2b_blend *b, size_t npts, const double *u, const double *v,
                          int order, double *out, c2b_error *err);

/**
 * Evaluate on the tensor grid u[0..nu) x v[0..nv), rows ordered by u then v
 * (point index i * nv + j). Uses the separable structure: each term's u-profile is
 * evaluated nu times, and each distinct v-function (a term's v-derivatives, and terms of
 * the three components, share them) nv times. Its sums may differ from
 * c2b_blend_eval()'s in rounding only.
 * @return as c2b_blend_eval(); C2B_ERR_NOMEM for the internal tables.
 */
c2b_status c2b_blend_eval_grid(const c2b_blend *b, size_t nu, const double *u, size_t nv,
                               const double *v, int order, double *out, c2b_error *err);

/** Largest measured truncation error of the boundary data expansion, in model units. */
double c2b_blend_truncation_error(const c2b_blend *b);

/**
 * Measure how well the blend reproduces its boundary data: at ns uniformly spaced v
 * (ns >= 2), compare d^p S/du^p at u = side with the boundary function of the problem
 * itself (callback or sample interpolation is not used: sampled data are compared at
 * their own sample points). res[side * n + p] receives the maximum absolute difference
 * over v and components, scale[side * n + p] the maximum magnitude of the datum
 * (both caller buffers of 2n, n = constraints per trimline).
 * @return C2B_OK; C2B_ERR_ARG; C2B_ERR_NOMEM.
 */
c2b_status c2b_blend_boundary_residual(const c2b_blend *b, int ns, double *res, double *scale,
                                       c2b_error *err);

/** The v-domain (range and periodicity) of the blend. */
c2b_vdomain c2b_blend_domain(const c2b_blend *b);

/** Constraints per trimline n (2 for C1, 3 for C2 and ODE, 4 for C3). */
int c2b_blend_constraints(const c2b_blend *b);

/** Largest condition estimate over the modes in use (1 if there are none). */
double c2b_blend_max_condition(const c2b_blend *b);

/**
 * Write a JSON description (modes per component with kind, beta and amplitudes,
 * characteristic roots, condition estimates, truncation errors, time per stage) into
 * buf (capacity cap, NUL-terminated). *needed receives the length required, without
 * the NUL, so a caller can retry with a larger buffer.
 * @return C2B_OK; C2B_ERR_LIMIT when cap is too small (buf untouched); C2B_ERR_NOMEM.
 */
c2b_status c2b_blend_info_json(const c2b_blend *b, char *buf, size_t cap, size_t *needed,
                               c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
