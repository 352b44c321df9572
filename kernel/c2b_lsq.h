/**
 * @file c2b_lsq.h
 * Overdetermined linear least squares for the collocation solvers (c2b_approx.h,
 * c2b_navier.h): min |A x - b| by LAPACK's rank-revealing QR with column pivoting
 * (dgelsy) after scaling every column of A to unit norm. The columns of the papers'
 * residual systems differ in scale by up to (M pi)^6; the scaling keeps dgelsy's rank
 * decision meaningful, and QR avoids squaring the condition number as the normal
 * equations would.
 */
#ifndef C2B_LSQ_H
#define C2B_LSQ_H

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Solve min |A x - b| for column-major A (rows x ncols, rows >= ncols >= 1, rows within
 * LAPACK's int range).
 * A and b (rows values) are overwritten. On success x[0..ncols) holds the solution in
 * the original column scaling, *rank the numerical rank (rcond as in dgelsy), and
 * *resid_ss (may be NULL) the residual sum of squares, read from rows ncols.. of the
 * transformed b (exact when the rank is full). The caller judges the rank.
 * @return C2B_OK; C2B_ERR_ARG for NULL buffers, rows < ncols or rows > INT_MAX; C2B_ERR_NUMERIC when
 *         dgelsy fails (message "<what>: dgelsy failed (info k)"); C2B_ERR_NOMEM.
 */
c2b_status c2b_lsq_solve(long rows, int ncols, double *A, double *b, double rcond, double *x,
                         int *rank, double *resid_ss, const char *what, c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
