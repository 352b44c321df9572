/* Column-scaled rank-revealing least squares; see c2b_lsq.h. */
#include "c2b_lsq.h"

#include <lapacke.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>

c2b_status c2b_lsq_solve(long rows, int ncols, double *A, double *b, double rcond, double *x,
                         int *rank, double *resid_ss, const char *what, c2b_error *err)
{
    if (!A || !b || !x || !rank || ncols < 1 || rows < ncols || rows > INT_MAX)
        return c2b_error_set(err, C2B_ERR_ARG, "%s: least squares needs rows >= columns >= 1 and rows <= INT_MAX",
                             what ? what : "c2b_lsq_solve");
    double *cn = malloc(sizeof(double) * (size_t)ncols);
    lapack_int *jpvt = calloc((size_t)ncols, sizeof *jpvt);
    if (!cn || !jpvt) {
        free(cn);
        free(jpvt);
        return c2b_error_set(err, C2B_ERR_NOMEM, "%s: out of memory", what ? what : "c2b_lsq_solve");
    }
    for (int k = 0; k < ncols; k++) {
        double *col = A + (size_t)rows * (size_t)k, s = 0;
        for (long r = 0; r < rows; r++)
            s += col[r] * col[r];
        cn[k] = s > 0 ? sqrt(s) : 1.0;
        for (long r = 0; r < rows; r++)
            col[r] /= cn[k];
    }
    lapack_int lrank = 0;
    lapack_int info = LAPACKE_dgelsy(LAPACK_COL_MAJOR, (lapack_int)rows, ncols, 1, A, (lapack_int)rows, b,
                                     (lapack_int)rows, jpvt,
                                     rcond, &lrank);
    c2b_status st = C2B_OK;
    if (info != 0) {
        st = c2b_error_set(err, C2B_ERR_NUMERIC, "%s: dgelsy failed (info %d)",
                           what ? what : "c2b_lsq_solve", (int)info);
    } else {
        *rank = (int)lrank;
        for (int k = 0; k < ncols; k++)
            x[k] = b[k] / cn[k];
        if (resid_ss) {
            double ss = 0;
            for (long r = ncols; r < rows; r++)
                ss += b[r] * b[r];
            *resid_ss = ss;
        }
    }
    free(cn);
    free(jpvt);
    return st;
}
