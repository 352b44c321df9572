/**
 * @file c2b_spec.h
 * JSON blend specs (format in README.md, "Spec format"), parsed with cJSON; the
 * expressions with libmatheval (c2b_expr.h). A spec owns its expressions and samples
 * and exposes a ::c2b_problem that refers to them, so a spec must outlive every blend
 * created from its problem.
 *
 * Every error names the field: `primaries[1].surface[2]: unknown identifier 'h4'`.
 */
#ifndef C2B_SPEC_H
#define C2B_SPEC_H

#include <stddef.h>

#include "c2b_error.h"
#include "c2b_problem.h"
#include "c2b_vdata.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct c2b_spec c2b_spec;

/** Largest spec file accepted, in bytes. */
#define C2B_SPEC_MAX_BYTES (64L * 1024 * 1024)

/**
 * Parse a spec from `len` bytes of JSON text (need not be NUL-terminated).
 * @return C2B_OK; C2B_ERR_SPEC naming the field for malformed JSON (with the line),
 *         unknown or missing keys, wrong types, wrong row counts, unknown identifiers,
 *         non-finite numbers, too few samples (boundary rows and "curves", e.g.
 *         `curves.controls[2].curve.samples: 3 samples given, at least 7 are needed`)
 *         and zero-length ranges; C2B_ERR_LIMIT for oversized input or too many
 *         samples in a curve; C2B_ERR_NOMEM.
 */
c2b_status c2b_spec_parse(const char *json, size_t len, c2b_spec **out, c2b_error *err);

/**
 * Read and parse a spec file ("-" reads standard input).
 * @return as c2b_spec_parse(), plus C2B_ERR_IO when the file cannot be read.
 */
c2b_status c2b_spec_load(const char *path, c2b_spec **out, c2b_error *err);

/** Free a spec. NULL-safe. Blends made from its problem must be destroyed first. */
void c2b_spec_destroy(c2b_spec *s);

/** The problem described by the spec (owned by the spec). */
const c2b_problem *c2b_spec_problem(const c2b_spec *s);

/** 1 when the spec defines primary surfaces (not explicit boundary data). */
int c2b_spec_has_primaries(const c2b_spec *s);

/**
 * Evaluate primary `side` (0 or 1) in extended blend coordinates: the primary
 * continues the blend's parametrisation beyond its trimline, ub <= 0 for side 0 and
 * ub >= 1 for side 1, with the primary's cross parameter = trim + direction (ub - side)
 * and its along-trimline parameter the blend's v (mapped linearly onto a NURBS
 * domain). With this parametrisation the blend's boundary data are exactly the
 * primary's derivatives at ub = side. Writes derivatives of total order <= order
 * (<= 2) in the blend layout [S, Su, Sv, Suu, Suv, Svv] x 3 into out. Expression
 * derivatives are derived symbolically on first use (so s is not const).
 * @return C2B_OK; C2B_ERR_ARG for boundary-data specs or a NURBS parameter outside its
 *         domain; C2B_ERR_NOMEM.
 */
c2b_status c2b_spec_primary_eval(c2b_spec *s, int side, double ub, double v, double t, int order,
                                 double *out, c2b_error *err);

/** Solvers a spec selects with "solver" (docs/APPROX.md). */
typedef enum c2b_solver_kind {
    C2B_SOLVER_EXACT = 0,          /**< the closed form (c2b_blend.h), the default */
    C2B_SOLVER_THESIS_APPROX = 1,  /**< thesis eqs. 95-126 (c2b_approx.h) */
    C2B_SOLVER_PSEUDO_NAVIER = 2   /**< seed 001 eqs. 9-15 (c2b_navier.h) */
} c2b_solver_kind;

/** A spec's solver settings; 0 in M, N, ci, cj means the solver's default. */
typedef struct c2b_spec_solver {
    c2b_solver_kind kind;  /**< "solver" */
    int M, N;              /**< "M" (both), "N" (pseudo-navier) */
    int ci, cj;            /**< "collocation": [I, J] */
    int approach;          /**< "approach": 0 "differential" (default), 1 "decomposition" */
    int group2_closed;     /**< "group2": 0 "series" (default), 1 "closed" (thesis-approx) */
} c2b_spec_solver;

/** The spec's "solver", "M", "N", "collocation", "approach" and "group2" (zeros when
 *  absent). */
c2b_spec_solver c2b_spec_solver_settings(const c2b_spec *s);

/**
 * The boundary data with symbolic v-derivatives up to order kmax (<= C2B_VDATA_MAX_K),
 * for the approximate solvers. Derivatives are made once and kept in the spec (so s is
 * not const); out refers to the spec and is valid while it lives.
 * @return C2B_OK; C2B_ERR_SPEC naming the datum for NURBS, sampled or "curves" data,
 *         or when libmatheval cannot differentiate; C2B_ERR_ARG; C2B_ERR_NOMEM.
 */
c2b_status c2b_spec_vdata(c2b_spec *s, int kmax, c2b_vdata *out, c2b_error *err);

/** The spec's "name", or "" when absent. */
const char *c2b_spec_name(const c2b_spec *s);

#ifdef __cplusplus
}
#endif
#endif
