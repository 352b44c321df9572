/**
 * @file c2b_expr.h
 * Expressions in u, v, t and named constants, parsed and differentiated symbolically
 * by GNU libmatheval. `pi` and `e` are predefined. Identifiers are checked before
 * parsing so that errors name the unknown identifier or function.
 */
#ifndef C2B_EXPR_H
#define C2B_EXPR_H

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Named constants (caller-owned arrays; names must stay valid while used). */
typedef struct c2b_constants {
    int n;
    const char *const *names;
    const double *values;
} c2b_constants;

typedef struct c2b_expr c2b_expr;

/** Variables an expression may use. */
enum { C2B_EXPR_U = 1, C2B_EXPR_V = 2, C2B_EXPR_T = 4 };

/**
 * Parse `text`. `allowed` is a mask of C2B_EXPR_U/V/T; constants may be NULL. The
 * constants' values are copied.
 * @return C2B_OK; C2B_ERR_SPEC with "unknown identifier 'h4'", "unknown function
 *         'foo'", "u is not allowed here" or "cannot parse expression '...'";
 *         C2B_ERR_NOMEM.
 */
c2b_status c2b_expr_create(const char *text, const c2b_constants *constants, int allowed,
                           c2b_expr **out, c2b_error *err);

/** Free an expression. NULL-safe. */
void c2b_expr_destroy(c2b_expr *e);

/**
 * Symbolic derivative of order k (0..6) with respect to var ('u', 'v' or 't').
 * k = 0 returns a copy. *out is a new object.
 * @return C2B_OK; C2B_ERR_ARG for a bad variable or order; C2B_ERR_NOMEM.
 */
c2b_status c2b_expr_derivative(const c2b_expr *e, char var, int k, c2b_expr **out,
                               c2b_error *err);

/** Value at (u, v, t). May be non-finite (1/0); callers check. Uses scratch space
 *  inside e, so one expression must not be evaluated from two threads at once. */
double c2b_expr_eval(const c2b_expr *e, double u, double v, double t);

/** 1 when the expression mentions var ('u', 'v' or 't'). */
int c2b_expr_depends(const c2b_expr *e, char var);

/** The source text (or libmatheval's rendering for derivatives). */
const char *c2b_expr_text(const c2b_expr *e);

#ifdef __cplusplus
}
#endif
#endif
