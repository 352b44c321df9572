/* Seed 000 ODE surfaces from boundary and control curves; see c2b_odesurf.h. */
#include "c2b_odesurf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* datum p (0..5 = c1..c6) of component c */
typedef struct dctx {
    const struct c2b_odesurf *s;
    int c, p;
} dctx;

struct c2b_odesurf {
    c2b_odesurf_input in;
    c2b_problem pb;
    dctx ctx[C2B_NCOMP][6];
    char label[C2B_NCOMP][6][48];
};

static double cv(const c2b_curve *k, int c, double v, double t)
{
    return k->fn[c] ? k->fn[c](k->ctx[c], v, t) : 0.0;
}

static double datum(void *ctx, double v, double t)
{
    const dctx *d = ctx;
    const c2b_odesurf_input *in = &d->s->in;
    int c = d->c;
    double c1 = cv(&in->c1, c, v, t), c4 = cv(&in->c4, c, v, t);
    switch (d->p) {
    case 0: return c1;
    case 3: return c4;
    default: break;
    }
    if (in->approach == C2B_ODESURF_MULTIPLES) {
        switch (d->p) {
        case 1: return in->w[0] * c1;
        case 2: return in->w[1] * c1;
        case 4: return in->w[2] * c4;
        default: return in->w[3] * c4;
        }
    }
    const double u2 = in->uc[0], u3 = in->uc[1], u5 = in->uc[2], u6 = in->uc[3];
    switch (d->p) {
    case 1: return (cv(&in->control[0], c, v, t) - c1) / u2; /* eq. 3 */
    case 2: {                                               /* eq. 4 */
        double b2 = cv(&in->control[0], c, v, t), b3 = cv(&in->control[1], c, v, t);
        return (u2 * b3 - u3 * b2 + (u3 - u2) * c1) / (u2 * u2 * (u3 - u2));
    }
    case 4: return (c4 - cv(&in->control[3], c, v, t)) / (1 - u6); /* eq. 5 */
    default: {                                                      /* eq. 6 */
        double b5 = cv(&in->control[2], c, v, t), b6 = cv(&in->control[3], c, v, t);
        return ((u6 - u5) * c4 + (1 - u6) * b5 - (1 - u5) * b6) / ((1 - u6) * (1 - u6) * (u6 - u5));
    }
    }
}

c2b_status c2b_odesurf_create(const c2b_odesurf_input *in, c2b_odesurf **out, c2b_error *err)
{
    if (!in || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_odesurf_create: NULL argument");
    *out = NULL;
    int any1 = 0, any4 = 0;
    for (int c = 0; c < C2B_NCOMP; c++)
        any1 |= in->c1.fn[c] != NULL, any4 |= in->c4.fn[c] != NULL;
    if (!any1 || !any4)
        return c2b_error_set(err, C2B_ERR_SPEC, "curves.%s: missing boundary curve", any1 ? "c4" : "c1");
    c2b_operator op; /* checks rho, eta, lambda as every blend does */
    c2b_status sst = c2b_operator_init(&op, C2B_ODE, in->shape, 3, err);
    if (sst) {
        c2b_error_prefix(err, "shape: ");
        return sst;
    }
    if (in->approach == C2B_ODESURF_MULTIPLES) {
        for (int k = 0; k < 4; k++)
            if (!isfinite(in->w[k]))
                return c2b_error_set(err, C2B_ERR_SPEC, "curves.w[%d]: not finite", k);
    } else if (in->approach == C2B_ODESURF_CONTROLS) {
        const double *u = in->uc;
        static const char *names[4] = {"u2", "u3", "u5", "u6"};
        for (int k = 0; k < 4; k++)
            if (!(u[k] > 0 && u[k] < 1))
                return c2b_error_set(err, C2B_ERR_SPEC, "curves.controls[%d].u: %s = %g must be in (0, 1)", k,
                                     names[k], u[k]);
        if (!(u[0] < u[1]))
            return c2b_error_set(err, C2B_ERR_SPEC, "curves.controls[1].u: u3 = %g must exceed u2 = %g", u[1], u[0]);
        if (!(u[2] < u[3]))
            return c2b_error_set(err, C2B_ERR_SPEC, "curves.controls[3].u: u6 = %g must exceed u5 = %g", u[3], u[2]);
    } else {
        return c2b_error_set(err, C2B_ERR_SPEC, "curves: unknown approach %d", (int)in->approach);
    }
    c2b_odesurf *s = calloc(1, sizeof *s);
    if (!s)
        return c2b_error_set(err, C2B_ERR_NOMEM, "ODE surface: out of memory");
    s->in = *in;
    s->pb = c2b_problem_default();
    s->pb.continuity = C2B_ODE;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int k = 0; k < 3; k++)
            s->pb.shape[c][k] = in->shape[k];
    s->pb.dom = in->dom;
    s->pb.time = in->time;
    int td = in->c1.time_dependent || in->c4.time_dependent;
    if (in->approach == C2B_ODESURF_CONTROLS)
        for (int k = 0; k < 4; k++)
            td |= in->control[k].time_dependent;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int p = 0; p < 6; p++) {
            dctx *d = &s->ctx[c][p];
            d->s = s, d->c = c, d->p = p;
            snprintf(s->label[c][p], sizeof s->label[c][p], "curves: datum c%d, component %c", p + 1, "xyz"[c]);
            c2b_bfunc f = {datum, NULL, d, td, NULL, 0, 0, s->label[c][p]};
            s->pb.data[c][p / 3][p % 3] = f;
        }
    *out = s;
    return C2B_OK;
}

void c2b_odesurf_destroy(c2b_odesurf *s) { free(s); }

const c2b_problem *c2b_odesurf_problem(const c2b_odesurf *s) { return s ? &s->pb : NULL; }
