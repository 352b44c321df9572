/**
 * @file c2b_problem.h
 * The input of a blend, independent of any file format: continuity, shape
 * parameters, v-domain, the 2n boundary functions per component and the optional
 * force. The spec reader (c2b_spec.h) builds one from JSON; C callers can fill one
 * directly.
 *
 * Boundary datum (side, p) of a component is d^p S / du^p at u = side (0 or 1), as a
 * function of v and t. Lifetime: a blend keeps the callbacks, contexts and sample
 * arrays of the problem it was created from; they must outlive it.
 */
#ifndef C2B_PROBLEM_H
#define C2B_PROBLEM_H

#include "c2b_operator.h"
#include "c2b_tolerance.h"
#include "c2b_vseries.h"

#ifdef __cplusplus
extern "C" {
#endif

/** One scalar boundary function. All fields zero means identically zero. */
typedef struct c2b_bfunc {
    c2b_vt_fn fn;          /**< f(ctx, v, t), or NULL */
    c2b_vt_fn fn_vv;       /**< exact d^2 f / dv^2, or NULL (finite differences) */
    void *ctx;
    int time_dependent;    /**< 0: projected once and reused for every t */
    const double *samples; /**< used when fn is NULL: uniform samples (c2b_vseries.h) */
    int n_samples;
    int stride;            /**< distance between consecutive samples, in doubles */
    const char *label;     /**< names the source in error messages, e.g. "boundary.u0[1][2]" */
} c2b_bfunc;

/** The force F(u, v, t) of one component; must be a polynomial in u (degree <= 8). */
typedef struct c2b_ffunc {
    double (*fn)(void *ctx, double u, double v, double t); /**< NULL: no force */
    void *ctx;
    int time_dependent;
    const char *label;
} c2b_ffunc;

/** Components are x, y, z (index 0, 1, 2). */
#define C2B_NCOMP 3

typedef struct c2b_problem {
    c2b_continuity continuity;
    double shape[C2B_NCOMP][5];                   /**< per component, c2b_continuity_nshape() used */
    c2b_vdomain dom;                              /**< v range and periodicity */
    c2b_bfunc data[C2B_NCOMP][2][C2B_MAX_N];      /**< [component][side][derivative order] */
    c2b_ffunc force[C2B_NCOMP];
    double time;                                  /**< initial time */
    c2b_tolerances tol;
} c2b_problem;

/** A problem with C2 continuity, all shape parameters 1, v in [0,1] open, zero data,
 *  no force, t = 0 and default tolerances. */
c2b_problem c2b_problem_default(void);

#ifdef __cplusplus
}
#endif
#endif
