/**
 * @file c2b_vdata.h
 * Boundary functions with their v-derivatives, the input of the approximate solvers
 * (c2b_approx.h, c2b_navier.h). The least-squares residual of thesis eqs. 122-123 and
 * seed 001 eqs. 11-13 needs d^k f/dv^k up to k = 6 (C2) or 4 (C1); callers supply
 * them exactly (closed forms, or symbolic derivatives as c2b_spec_vdata() does).
 */
#ifndef C2B_VDATA_H
#define C2B_VDATA_H

#include "c2b_problem.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Highest v-derivative order a ::c2b_vderiv_fn must provide. */
#define C2B_VDATA_MAX_K 6

/** d^k f / dv^k (k = 0..C2B_VDATA_MAX_K) of one boundary function at (v, t). */
typedef double (*c2b_vderiv_fn)(void *ctx, int k, double v, double t);

/** One boundary function. fn == NULL means identically zero. */
typedef struct c2b_vdfunc {
    c2b_vderiv_fn fn;
    void *ctx;            /**< referenced, must outlive the solver */
    int time_dependent;   /**< 0: evaluated once and reused for every t */
} c2b_vdfunc;

/** The boundary data of a blend: f[component][side][order], as in ::c2b_problem. */
typedef struct c2b_vdata {
    c2b_vdfunc f[C2B_NCOMP][2][C2B_MAX_N];
} c2b_vdata;

#ifdef __cplusplus
}
#endif
#endif
