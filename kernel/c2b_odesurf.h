/**
 * @file c2b_odesurf.h
 * Seed 000's ODE surface creation: a surface S(u, v) whose every u-curve solves
 *     rho S^(6) + eta S^(4) + lambda S'' = 0                      (seed 000 eq. 2)
 * between two boundary curves c1(v) (u = 0) and c4(v) (u = 1), i.e. the kernel's ODE
 * continuity. The derivative data c2, c3 (u = 0) and c5, c6 (u = 1) come from
 *  - approach 1 (eq. 24, figs. 2-3): multiples of the boundary curves,
 *    c2 = w1 c1, c3 = w2 c1, c5 = w3 c4, c6 = w4 c4;
 *  - approach 2 (eqs. 3-7, figs. 4-5): four control curves cb2 at u2, cb3 at u3, cb5 at
 *    u5, cb6 at u6 (0 < u2 < u3, u5 < u6 < 1), by forward and backward differences:
 *    c2 = (cb2 - c1)/u2,  c3 = [u2 cb3 - u3 cb2 + (u3 - u2) c1] / [u2^2 (u3 - u2)],
 *    c5 = (c4 - cb6)/(1 - u6),
 *    c6 = [(u6 - u5) c4 + (1 - u6) cb5 - (1 - u5) cb6] / [(1 - u6)^2 (u6 - u5)].
 * The result is a ::c2b_problem for c2b_blend_create(); the object owns the contexts
 * the problem's callbacks refer to, so it must outlive every blend made from it.
 * Patches that share boundary data join C2 in u (section 5.1): give the second patch
 * the first one's u = 1 data as its u = 0 data.
 *
 * Curves are functions of (v, t) or uniform samples in v (the points of a digitised or
 * hand-drawn curve). Sampled curves use the kernel's sampled-data representation, as
 * sampled boundary rows do (c2b_vseries_project_samples(): FFT on periodic ranges,
 * end polynomial + DST-I sine series on open ones):
 *  - a datum all of whose curves (c1, c4 or controls, per the formulas above) are
 *    samples with one count is passed to the blend as samples, the same linear
 *    combination taken sample by sample; the blend then measures and reports the
 *    truncation error of that datum (c2b_blend_truncation_error(), its info JSON);
 *  - any other datum that uses a sampled curve evaluates the curve's series (made once
 *    here) inside the problem's callback (with the exact second v-derivative when all
 *    its curves are sampled). The blend sees an exactly known function then, so the
 *    sampled curves' own truncation error in these data is reported by
 *    c2b_odesurf_truncation_error() instead.
 * Expressions and samples may be mixed between the curves of one surface.
 */
#ifndef C2B_ODESURF_H
#define C2B_ODESURF_H

#include "c2b_error.h"
#include "c2b_problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * A space curve c(v, t): either one scalar function per component (NULL means 0), or
 * uniform samples. Samples are n_samples points [x, y, z], stored flat and row-major
 * (3 n_samples doubles), at v0 + i L / n_samples (periodic: the end point is not
 * repeated; n_samples >= 4) or v0 + i L / (n_samples - 1) (open: both ends;
 * n_samples >= 7), L = v1 - v0. Their truncation estimate needs an even count on a
 * periodic range (c2b_vseries_project_samples()). Sampled curves do not depend on t.
 */
typedef struct c2b_curve {
    c2b_vt_fn fn[C2B_NCOMP];
    void *ctx[C2B_NCOMP];
    int time_dependent;
    const double *samples;  /**< NULL: use fn; otherwise referenced, not copied */
    int n_samples;
} c2b_curve;

/** How the derivative data are made. */
typedef enum c2b_odesurf_approach {
    C2B_ODESURF_MULTIPLES = 1, /**< approach 1, eq. 24 */
    C2B_ODESURF_CONTROLS = 2   /**< approach 2, eqs. 3-7 */
} c2b_odesurf_approach;

/** Input of an ODE surface. Curves are referenced, not copied. */
typedef struct c2b_odesurf_input {
    c2b_odesurf_approach approach;
    c2b_curve c1, c4;        /**< boundary curves at u = 0 and u = 1 */
    double w[4];             /**< approach 1: w1..w4 */
    c2b_curve control[4];    /**< approach 2: cb2, cb3, cb5, cb6 */
    double uc[4];            /**< approach 2: u2, u3, u5, u6 */
    double shape[3];         /**< rho, eta, lambda (seed 000 eq. 2) */
    c2b_vdomain dom;
    double time;
    /** Sample limits and mode dropping for sampled curves (drop_rel, max_samples), and
     *  the problem's tolerances; NULL means c2b_tolerances_default(). Copied. */
    const c2b_tolerances *tol;
} c2b_odesurf_input;

typedef struct c2b_odesurf c2b_odesurf;

/**
 * Build the boundary-value problem of an ODE surface. Sampled curves are expanded
 * here, once.
 * @return C2B_OK; C2B_ERR_SPEC for a missing boundary curve, control positions out of
 *         order (the message names "controls[k].u"), non-finite weights or shape, a
 *         curve with both functions and samples, too few or non-finite samples (the
 *         message names the curve as the spec does, e.g. "curves.controls[2].curve.samples");
 *         C2B_ERR_LIMIT for more than 4 tol->max_samples samples;
 *         C2B_ERR_ARG for NULL arguments; C2B_ERR_NOMEM.
 */
c2b_status c2b_odesurf_create(const c2b_odesurf_input *in, c2b_odesurf **out, c2b_error *err);

/** Free. NULL-safe. Destroy blends made from its problem first. */
void c2b_odesurf_destroy(c2b_odesurf *s);

/** The problem (continuity C2B_ODE), owned by s. */
const c2b_problem *c2b_odesurf_problem(const c2b_odesurf *s);

/**
 * Truncation error of the sampled curves in the data the blend gets as callbacks (data
 * that combine sampled and function curves, or curves with different sample counts),
 * in model units, largest over those data and components. The blend measures the data
 * it gets as samples itself (c2b_blend_truncation_error()); together the two cover
 * every datum. A datum is sum_k a_k (curve k) by eq. 24 or eqs. 3-6; when its sampled
 * curves share one count, its sampled part sum_k a_k (samples k) gets the leave-half-out
 * estimate of c2b_vseries_project_samples(), as sampled data do in the blend; otherwise
 * the bound sum_k |a_k| e_k with e_k the estimate of curve k alone. 0 when no such datum
 * exists or s is NULL.
 */
double c2b_odesurf_truncation_error(const c2b_odesurf *s);

#ifdef __cplusplus
}
#endif
#endif
