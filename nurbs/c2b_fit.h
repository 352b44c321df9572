/**
 * @file c2b_fit.h
 * B-spline surfaces from blends (MATH.md section 9), with measured deviation.
 *
 * The result is non-rational, of degree 2n-1 in u (3 for C1, 5 for C2, 7 for C3),
 * clamped at u = 0 and 1, and of degree 3 or 5 in v (periodic for closed trimlines).
 * Its first n pole rows at each end are fixed by S, S_u, ... S_u^(n-1) there, so the
 * contact with the primaries is exact up to the v-interpolation of those data. The
 * other rows interpolate S at the Greville abscissae. Knots are inserted at the
 * middle of each span whose deviation exceeds half the tolerance, measured
 * separately along u (at the v-interpolation sites) and along v (at the u-sites),
 * until a dense check grid offset from every site and knot is within tolerance. The
 * end rows S, S_u, ... at u = 0 and 1 are refined along v until each is within 1% of
 * tol_rel of its own magnitude, so the contact with the primaries (position, tangent
 * and curvature) is two orders tighter than the interior deviation; so is the
 * normal there (from S_u and S_v: S_v is no row, it follows from S's interpolation in
 * v), to within 30% of tol_rel in radians. An end row's
 * k-th derivative is a difference of k + 1 pole rows, amplified by 2^k p!/(p-k)!/h^k
 * (h: the end span); the rounding error this leaves (16 eps x largest pole coordinate
 * x that factor) is not counted, since no refinement along v can remove it.
 */
#ifndef C2B_FIT_H
#define C2B_FIT_H

#include "c2b_blend.h"
#include "c2b_nurbs.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Options; start from c2b_fit_options_default(). */
typedef struct c2b_fit_options {
    double tol_rel;   /**< max deviation relative to the bounding-box diagonal (1e-6) */
    int degree_v;     /**< 3 or 5 (5) */
    int max_poles;    /**< pole budget per direction (400) */
    int max_iter;     /**< refinement rounds (30) */
} c2b_fit_options;

/** The defaults given beside each field above. Cannot fail. */
c2b_fit_options c2b_fit_options_default(void);

/** What a fit achieved. Filled on success and on C2B_ERR_NUMERIC (budget exceeded). */
typedef struct c2b_fit_report {
    double deviation;     /**< max |S_fit - S| over the final check grid (8 points per span
                               in each direction, offset from knots and sites, plus the
                               ends): a sampled maximum, model units */
    double tolerance;     /**< tol_rel * bbox_diagonal */
    double bbox_diagonal; /**< of the analytic blend on the check grid */
    double residual[2][C2B_MAX_N]; /**< max |d^k S_fit/du^k - d^k S/du^k| at u = side, dense v */
    double site_residual[2][C2B_MAX_N]; /**< the same at the v-interpolation sites, where the
                                             end rows are exact up to rounding */
    double tilt[2];       /**< max angle (rad) between the fit's and the blend's normals at
                               u = 0 and 1, dense v */
    int npoles[2];        /**< distinct poles in u and v */
    int iterations;
    long check_points;    /**< size of the final check grid */
    double seconds;
} c2b_fit_report;

/**
 * Fit blend b at its current time. On success *out owns a new surface.
 * @return C2B_OK; C2B_ERR_ARG for bad options; C2B_ERR_NUMERIC when the tolerance is
 *         not reached within the pole budget or iterations (the message and *rep
 *         state the deviation reached; no surface is returned); C2B_ERR_NOMEM.
 */
c2b_status c2b_fit_blend(const c2b_blend *b, const c2b_fit_options *opt,
                         c2b_nurbs_surface **out, c2b_fit_report *rep, c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
