#include "c2b_operator.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int c2b_continuity_nshape(c2b_continuity c)
{
    switch (c) {
    case C2B_C1: return 3;
    case C2B_C2: return 4;
    case C2B_C3: return 5;
    case C2B_ODE: return 3;
    }
    return 0;
}

int c2b_continuity_n(c2b_continuity c)
{
    switch (c) {
    case C2B_C1: return 2;
    case C2B_C2: return 3;
    case C2B_C3: return 4;
    case C2B_ODE: return 3;
    }
    return 0;
}

const char *c2b_continuity_name(c2b_continuity c)
{
    switch (c) {
    case C2B_C1: return "C1";
    case C2B_C2: return "C2";
    case C2B_C3: return "C3";
    case C2B_ODE: return "ODE";
    }
    return "?";
}

const char *c2b_continuity_param_name(c2b_continuity c, int i)
{
    static const char *const c1[] = {"b", "c", "d"};
    static const char *const c2[] = {"gamma", "eta", "lambda", "rho"};
    static const char *const c3[] = {"a0", "a1", "a2", "a3", "a4"};
    static const char *const ode[] = {"rho", "eta", "lambda"};
    if (i < 0 || i >= c2b_continuity_nshape(c))
        return "?";
    switch (c) {
    case C2B_C1: return c1[i];
    case C2B_C2: return c2[i];
    case C2B_C3: return c3[i];
    case C2B_ODE: return ode[i];
    }
    return "?";
}

c2b_status c2b_operator_init(c2b_operator *op, c2b_continuity cont, const double *shape,
                             int nshape, c2b_error *err)
{
    int want = c2b_continuity_nshape(cont);
    if (!op || !shape || want == 0)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_operator_init: invalid arguments");
    if (nshape != want)
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "%s takes %d shape parameters (%s), got %d",
                             c2b_continuity_name(cont), want,
                             cont == C2B_C1 ? "b, c, d"
                             : cont == C2B_C2 ? "gamma, eta, lambda, rho"
                             : cont == C2B_C3 ? "a0..a4" : "rho, eta, lambda",
                             nshape);
    for (int i = 0; i < nshape; i++)
        if (!isfinite(shape[i]))
            return c2b_error_set(err, C2B_ERR_SPEC, "shape parameter %s is not finite",
                                 c2b_continuity_param_name(cont, i));
    if (shape[0] == 0.0)
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "shape parameter %s must be nonzero: it multiplies the "
                             "highest u-derivative, and without it the %s blend cannot "
                             "meet all boundary constraints",
                             c2b_continuity_param_name(cont, 0), c2b_continuity_name(cont));
    memset(op, 0, sizeof *op);
    op->continuity = cont;
    op->n = c2b_continuity_n(cont);
    op->beta_free = cont == C2B_ODE;
    for (int i = 0; i < nshape; i++)
        op->a[i] = shape[i];
    /* ODE: a = rho, eta, lambda, 0 (no undifferentiated term) */

    /* Companion matrix of w^n + (a1/a0) w^{n-1} + ... + an/a0, column-major. */
    int n = op->n;
    double comp[C2B_MAX_N * C2B_MAX_N] = {0};
    for (int j = 0; j < n; j++)
        comp[j * n + 0] = -op->a[j + 1] / op->a[0]; /* first row */
    for (int i = 1; i < n; i++)
        comp[(i - 1) * n + i] = 1.0; /* subdiagonal */
    double wr[C2B_MAX_N], wi[C2B_MAX_N];
    lapack_int info = LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n, comp, n, wr, wi, NULL, 1,
                                    NULL, 1);
    if (info != 0)
        return c2b_error_set(err, C2B_ERR_NUMERIC,
                             "characteristic roots of the %s operator could not be computed "
                             "(LAPACK dgeev info %d)",
                             c2b_continuity_name(cont), (int)info);
    for (int i = 0; i < n; i++)
        op->w[i] = wr[i] + I * wi[i];
    return C2B_OK;
}

c2b_status c2b_operator_check_shapes(c2b_continuity cont, int ncomp, const double (*shape)[5],
                                     c2b_error *err)
{
    for (int c = 0; c < ncomp; c++) {
        c2b_operator op;
        c2b_status st = c2b_operator_init(&op, cont, shape[c], c2b_continuity_nshape(cont), err);
        if (st) {
            c2b_error_prefix(err, "shape (component %c): ", "xyz"[c]);
            return st;
        }
    }
    return C2B_OK;
}

void c2b_operator_mode_coefficients(const c2b_operator *op, double beta, double *c)
{
    double bk = 1.0;
    for (int k = 0; k <= op->n; k++) {
        c[k] = op->beta_free ? op->a[k] : op->a[k] * bk;
        bk *= beta;
    }
}

void c2b_operator_z_roots(const c2b_operator *op, double beta, double complex *z)
{
    for (int i = 0; i < op->n; i++)
        z[i] = op->beta_free ? op->w[i] : beta * op->w[i];
}

int c2b_operator_equal(const c2b_operator *x, const c2b_operator *y)
{
    if (x->continuity != y->continuity)
        return 0;
    for (int k = 0; k <= x->n; k++)
        if (x->a[k] != y->a[k])
            return 0;
    return 1;
}

void c2b_operator_describe(const c2b_operator *op, char *buf, int cap)
{
    int used = 0;
    int ns = c2b_continuity_nshape(op->continuity);
    buf[0] = '\0';
    for (int i = 0; i < ns && used < cap; i++)
        used += snprintf(buf + used, (size_t)(cap - used), "%s%s=%.17g", i ? ", " : "",
                         c2b_continuity_param_name(op->continuity, i), op->a[i]);
}
