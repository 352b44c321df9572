/**
 * @file c2b_tolerance.h
 * Every numerical tolerance and size limit of the kernel, in one place.
 * Callers take ::c2b_tolerances_default() and override fields as needed.
 */
#ifndef C2B_TOLERANCE_H
#define C2B_TOLERANCE_H

#ifdef __cplusplus
extern "C" {
#endif

/** Boundary data given as functions (expressions, NURBS) whose expansion still has a
 *  truncation error above this fraction of the data scale when tol.max_samples is
 *  reached are not represented at all (typically a mode frequency far beyond what
 *  max_samples can resolve, or aliased onto the sampling grid): the blend reports
 *  C2B_ERR_LIMIT instead of silently missing its boundary data. Aliased data give
 *  errors of order 1; a kink (seed001_eq29) leaves 2.3e-5. Sampled data are exempt
 *  (their leave-half-out error also measures noise). */
#define C2B_UNRESOLVED_REL 1e-2

typedef struct c2b_tolerances {
    /** Exponents closer than this (absolute, in 1/unit-u) share a divided-difference
     *  cluster. The blend's u-interval has length 1, so within a cluster
     *  exp((r_i - r_j) u) varies by at most e^cluster on [0,1]. */
    double cluster;
    /** A mode whose equilibrated boundary system has a 1-norm condition number above
     *  this is reported as resonant (C2B_ERR_NUMERIC). */
    double cond_limit;
    /** Largest tolerated imaginary part of a mode's transfer functions, relative. */
    double imag_rel;
    /** Target relative truncation error of boundary data expanded into modes. */
    double truncation_rel;
    /** Relative tolerance of the exact-structure tests (polynomial in v, f''=beta f). */
    double structure_rel;
    /** Modes whose amplitude is below this fraction of the data's half-range (not
     *  their magnitude, which moving the part changes), or below the rounding of their
     *  magnitude, are dropped (FFT rounding noise is a few 1e-15); the error they
     *  leave is measured. */
    double drop_rel;
    /** Highest polynomial degree in v recognised exactly. */
    int max_poly_degree;
    /** Largest number of samples per trimline for adaptive FFT/DST projection. */
    int max_samples;
    /** Largest number of evaluation points in one grid or point request. */
    long max_eval_points;
} c2b_tolerances;

/** The defaults: cluster 1.0, cond_limit 1e10, imag_rel 1e-8, truncation_rel 1e-13,
 *  structure_rel 1e-12, drop_rel 1e-14, max_poly_degree 8, max_samples 16384,
 *  max_eval_points 5e7. */
c2b_tolerances c2b_tolerances_default(void);

#ifdef __cplusplus
}
#endif
#endif
