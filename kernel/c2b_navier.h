/**
 * @file c2b_navier.h
 * Seed 001's pseudo-Navier approximate solution of the C1 (fourth-order) blend PDE
 *     b S_uuuu + c S_uuvv + d S_vvvv = 0                          (seed 001 eq. 2)
 * for boundary data without a closed form (its "second group" functions g_k(v)):
 *     X(u, v) = sum_k H_k(u) g_k(v) + u (u-1)^2 sum_{m<=M, n<=N} A_mn sin(m u) sin(n w)
 * (eq. 9), where H_k is the cubic Hermite interpolant of the four data (eq. 10) and
 * w = 2 pi (v - v0)/(v1 - v0) (w = v on seed 001's domain [0, 2 pi]). The correction
 * vanishes with its first u-derivative at u = 0 and 1, so the data hold exactly. The
 * A_mn minimise the PDE residual (eqs. 11-14) at L = (I+1) x (J+1) collocation points,
 * solved as an overdetermined system by LAPACK's rank-revealing QR (dgelsy) rather than
 * the normal equations of eq. 15 (see c2b_approx.h for why). Seed 001 superimposes this
 * on the closed form of the "first group" data (eq. 16): callers pass only the second
 * group here and add c2b_blend's surface for the rest.
 *
 * Collocation points (seed 001 says only "uniformly choosing L collocation points
 * within the resolution region"): C2B_NAVIER_GRID_CLOSED uses u_i = i/I,
 * v_j = v0 + j (v1 - v0)/J including the boundary (the thesis' convention, eq. 124);
 * C2B_NAVIER_GRID_INTERIOR uses u_i = i/(I+2), ..., i.e. (I+1) x (J+1) interior points
 * of a uniform (I+2)-interval grid. Seed 001's 49 points are I = J = 6 in either reading,
 * but the closed reading is degenerate there: sin(3 w) vanishes at all seven v_j, so
 * the M = N = 3 system is rank deficient (reported as C2B_ERR_NUMERIC). The interior
 * grid is therefore the default.
 */
#ifndef C2B_NAVIER_H
#define C2B_NAVIER_H

#include <stddef.h>

#include "c2b_error.h"
#include "c2b_vdata.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest M * N. */
#define C2B_NAVIER_MAX_TERMS 1024

/** Placement of the collocation points (see the file comment). */
typedef enum c2b_navier_grid {
    C2B_NAVIER_GRID_CLOSED = 0,
    C2B_NAVIER_GRID_INTERIOR = 1
} c2b_navier_grid;

/** Method settings. */
typedef struct c2b_navier_options {
    int M, N;          /**< double sine series terms (default 3, 3: seed 001 section 3) */
    int ci, cj;        /**< (ci+1) x (cj+1) collocation points (default 6, 6: L = 49) */
    c2b_navier_grid grid;
    double rcond;      /**< dgelsy rank threshold (default 1e-13) */
} c2b_navier_options;

/** Defaults: M = N = 3, ci = cj = 6 (49 points), interior grid, rcond 1e-13. */
c2b_navier_options c2b_navier_options_default(void);

typedef struct c2b_navier c2b_navier;

/**
 * Build the pseudo-Navier solution for the data f[c][side][p] (p = 0, 1: S and S_u)
 * with shape[c][0..2] = (b, c, d) per component, at time t. Data are referenced.
 * @return C2B_OK; C2B_ERR_ARG for NULL arguments or options out of range (naming "M",
 *         "N", "collocation"); C2B_ERR_SPEC for b = 0 or non-finite data or shape;
 *         C2B_ERR_NUMERIC for a rank-deficient system; C2B_ERR_NOMEM.
 */
c2b_status c2b_navier_create(const double shape[C2B_NCOMP][5], const c2b_vdomain *dom,
                             const c2b_vdata *data, double t, const c2b_navier_options *opt,
                             c2b_navier **out, c2b_error *err);

/** Free. NULL-safe. */
void c2b_navier_destroy(c2b_navier *nv);

/**
 * Evaluate on the grid u[0..nu) x v[0..nv) (index i * nv + j), derivatives up to
 * order (0..2), layout [S, Su, Sv, Suu, Suv, Svv] x 3 as in c2b_blend.h.
 * @return C2B_OK; C2B_ERR_ARG; C2B_ERR_NOMEM.
 */
c2b_status c2b_navier_eval_grid(const c2b_navier *nv, size_t nu, const double *u, size_t nvv,
                                const double *v, int order, double *out, c2b_error *err);

/** The coefficients A_mn of component c (index (m-1) * N + (n-1)); M * N values. */
void c2b_navier_coefficients(const c2b_navier *nv, int c, double *A);

#ifdef __cplusplus
}
#endif
#endif
