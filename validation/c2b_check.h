/**
 * @file c2b_check.h
 * Continuity report of a blend against its primaries (MATH.md section 8), at matched
 * points along both trimlines. The primary is evaluated in extended blend coordinates
 * (c2b_spec_primary_eval), so matched points share (u, v) and the parametric
 * residuals are direct differences of S_u and S_uu.
 *
 * Per trimline: G0 distance, G1 normal angle, G2 difference of the normal curvature
 * across the trimline (in the blend's S_u direction) plus the differences of k1, k2, K
 * and H, parametric C1/C2 residuals, each with its maximum and the v where it occurs,
 * and verdicts at stated tolerances.
 */
#ifndef C2B_CHECK_H
#define C2B_CHECK_H

#include "c2b_blend.h"
#include "c2b_spec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Tolerances of the verdicts; start from c2b_check_options_default(). */
typedef struct c2b_check_options {
    int samples;     /**< matched points per trimline (101) */
    double g0_rel;   /**< G0: distance / bounding-box diagonal of the trimlines (1e-9) */
    double g1_rad;   /**< G1: normal angle in radians (1e-8) */
    double g2_rel;   /**< G2: cross normal-curvature difference relative to
                          max(|k1|, |k2|, 1/diagonal) of the primary (1e-6) */
    double c_rel;    /**< C1/C2: |S_u| and |S_uu| differences relative to the primary's
                          max |S_u| (resp. max(|S_uu|, |S_u|^2/diagonal)) (1e-9) */
} c2b_check_options;

/** The defaults given beside each field above. Cannot fail. */
c2b_check_options c2b_check_options_default(void);

/** A maximum and the v where it occurs. */
typedef struct c2b_check_max {
    double max;
    double at_v;
} c2b_check_max;

/** Report for one trimline. */
typedef struct c2b_check_side {
    int side, samples, degenerate; /**< degenerate: points without a normal (skipped for G1/G2) */
    c2b_check_max g0, g1, g2, g2_rel, dk1, dk2, dK, dH, c1, c2;
    double scale_length, scale_curvature; /**< diagonal and the curvature floor used */
    const char *verdict;            /**< "G2", "G1", "G0" or "none" */
    const char *parametric_verdict; /**< "C2", "C1", "C0" or "none" (C3 not checked) */
    double table_blend[2], table_primary[2]; /**< thesis Table 4 style, at v = v0: normal
                                                  curvature along the trimline (S_v, the
                                                  thesis' "maximum") and across it (S_u, its
                                                  "minimum"); sign chosen so that their sum
                                                  is >= 0 for the primary */
} c2b_check_side;

/**
 * Check blend b (built from spec, at its current time) against both primaries.
 * @return C2B_OK; C2B_ERR_ARG when the spec has no primary surfaces (explicit boundary
 *         data) or samples < 2; errors from evaluating the primaries (a NURBS
 *         parameter outside its domain).
 */
c2b_status c2b_check_run(const c2b_blend *b, c2b_spec *spec, const c2b_check_options *opt,
                         c2b_check_side out[2], c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
