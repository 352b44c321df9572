/**
 * @file c2b_surface.h
 * One evaluator for whichever solver a spec selects ("solver": "exact", "thesis-approx"
 * or "pseudo-navier"; docs/APPROX.md), for front ends such as the CLI's eval.
 */
#ifndef C2B_SURFACE_H
#define C2B_SURFACE_H

#include <stddef.h>

#include "c2b_error.h"
#include "c2b_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct c2b_surface c2b_surface;

/**
 * Solve the spec's problem at time t with its solver. The spec must outlive the surface.
 * thesis-approx needs continuity C2, pseudo-navier C1; both need expression data and
 * no force.
 * @return C2B_OK; C2B_ERR_SPEC naming "solver", "force" or the datum; the errors of
 *         c2b_blend_create(), c2b_approx_create() or c2b_navier_create().
 */
c2b_status c2b_surface_create(c2b_spec *s, double t, c2b_surface **out, c2b_error *err);

/** Free. NULL-safe. */
void c2b_surface_destroy(c2b_surface *sf);

/** Highest derivative order c2b_surface_eval_grid() accepts (3 for exact, else 2). */
int c2b_surface_max_order(const c2b_surface *sf);

/**
 * Evaluate on the grid u[0..nu) x v[0..nv) (point index i * nv + j) with derivatives up
 * to order, in the layout of c2b_blend.h.
 * @return C2B_OK; C2B_ERR_ARG for NULL buffers or order above c2b_surface_max_order();
 *         C2B_ERR_LIMIT; C2B_ERR_NOMEM.
 */
c2b_status c2b_surface_eval_grid(const c2b_surface *sf, size_t nu, const double *u, size_t nv,
                                 const double *v, int order, double *out, c2b_error *err);

/** Evaluate at npts scattered points (u[i], v[i]); otherwise as c2b_surface_eval_grid(). */
c2b_status c2b_surface_eval(const c2b_surface *sf, size_t npts, const double *u, const double *v,
                            int order, double *out, c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
