/* Seed 000 ODE surfaces from boundary and control curves; see c2b_odesurf.h. */
#include "c2b_odesurf.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The curves of a surface, by slot: c1, c4, then the controls cb2, cb3, cb5, cb6. */
#define NSLOT 6
/* Data per component: c1, c2, c3 (u = 0), c4, c5, c6 (u = 1). */
#define NDATUM 6

/* datum p (0..5 = c1..c6) of component c */
typedef struct dctx {
    const struct c2b_odesurf *s;
    int c, p;
} dctx;

struct c2b_odesurf {
    c2b_odesurf_input in;
    c2b_problem pb;
    dctx ctx[C2B_NCOMP][NDATUM];
    char label[C2B_NCOMP][NDATUM][64];
    c2b_vseries series[NSLOT][C2B_NCOMP]; /* sampled curves, expanded once */
    double *dsamples[C2B_NCOMP][NDATUM];  /* data combined sample by sample (owned) */
    double sample_err;                    /* c2b_odesurf_truncation_error() */
};

static const c2b_curve *slot_curve(const c2b_odesurf_input *in, int k)
{
    return k == 0 ? &in->c1 : k == 1 ? &in->c4 : &in->control[k - 2];
}

/* The spec field of slot k, for messages. */
static void slot_name(int k, char *buf, size_t len)
{
    if (k < 2)
        snprintf(buf, len, "curves.%s", k ? "c4" : "c1");
    else
        snprintf(buf, len, "curves.controls[%d].curve", k - 2);
}

/* The curves datum p is made of, as a bit set of slots. */
static unsigned datum_slots(const c2b_odesurf_input *in, int p)
{
    if (p == 0 || (p < 3 && in->approach == C2B_ODESURF_MULTIPLES))
        return 1u << 0;
    if (p == 3 || (p > 3 && in->approach == C2B_ODESURF_MULTIPLES))
        return 1u << 1;
    switch (p) {
    case 1: return 1u << 0 | 1u << 2;
    case 2: return 1u << 0 | 1u << 2 | 1u << 3;
    case 4: return 1u << 1 | 1u << 5;
    default: return 1u << 1 | 1u << 4 | 1u << 5;
    }
}

/* Datum p from the values x[k] of the curves in slot order (eq. 24 or eqs. 3-6). It is
 * linear in x, so it also combines second derivatives, samples and unit vectors. */
static double combine(const c2b_odesurf_input *in, int p, const double *x)
{
    double c1 = x[0], c4 = x[1];
    switch (p) {
    case 0: return c1;
    case 3: return c4;
    default: break;
    }
    if (in->approach == C2B_ODESURF_MULTIPLES) {
        switch (p) {
        case 1: return in->w[0] * c1;
        case 2: return in->w[1] * c1;
        case 4: return in->w[2] * c4;
        default: return in->w[3] * c4;
        }
    }
    const double u2 = in->uc[0], u3 = in->uc[1], u5 = in->uc[2], u6 = in->uc[3];
    switch (p) {
    case 1: return (x[2] - c1) / u2; /* eq. 3 */
    case 2: {                        /* eq. 4 */
        double b2 = x[2], b3 = x[3];
        return (u2 * b3 - u3 * b2 + (u3 - u2) * c1) / (u2 * u2 * (u3 - u2));
    }
    case 4: return (c4 - x[5]) / (1 - u6); /* eq. 5 */
    default: {                             /* eq. 6 */
        double b5 = x[4], b6 = x[5];
        return ((u6 - u5) * c4 + (1 - u6) * b5 - (1 - u5) * b6) / ((1 - u6) * (1 - u6) * (u6 - u5));
    }
    }
}

/* d^q/dv^q of curve k, component c (q = 2 only for sampled curves). */
static double curve_value(const struct c2b_odesurf *s, int k, int c, double v, double t, int q)
{
    const c2b_curve *cv = slot_curve(&s->in, k);
    if (cv->samples) {
        double d[3];
        c2b_vseries_eval(&s->series[k][c], &s->in.dom, v, q, d);
        return d[q];
    }
    if (q)
        return NAN;
    return cv->fn[c] ? cv->fn[c](cv->ctx[c], v, t) : 0.0;
}

static double datum_q(const dctx *d, double v, double t, int q)
{
    double x[NSLOT] = {0};
    unsigned used = datum_slots(&d->s->in, d->p);
    for (int k = 0; k < NSLOT; k++)
        if (used >> k & 1u)
            x[k] = curve_value(d->s, k, d->c, v, t, q);
    return combine(&d->s->in, d->p, x);
}

static double datum(void *ctx, double v, double t) { return datum_q(ctx, v, t, 0); }

/* Exact second v-derivative; installed only when every curve of the datum is sampled. */
static double datum_vv(void *ctx, double v, double t) { return datum_q(ctx, v, t, 2); }

/* Expand the sampled curves of the surface (all components), with names in errors. */
static c2b_status expand_samples(c2b_odesurf *s, int nslot, c2b_error *err)
{
    const c2b_odesurf_input *in = &s->in;
    for (int k = 0; k < nslot; k++) {
        const c2b_curve *cv = slot_curve(in, k);
        if (!cv->samples)
            continue;
        char name[48];
        slot_name(k, name, sizeof name);
        for (int c = 0; c < C2B_NCOMP; c++)
            if (cv->fn[c])
                return c2b_error_set(err, C2B_ERR_SPEC, "%s: give functions or samples, not both", name);
        if (!(in->dom.v1 > in->dom.v0) || !isfinite(in->dom.v0) || !isfinite(in->dom.v1))
            return c2b_error_set(err, C2B_ERR_SPEC, "v_range: [%g, %g] is not a finite range of positive length",
                                 in->dom.v0, in->dom.v1);
        for (int c = 0; c < C2B_NCOMP; c++) {
            c2b_status st = c2b_vseries_project_samples(&in->dom, cv->samples + c, 3, cv->n_samples, &s->pb.tol,
                                                        &s->series[k][c], err);
            if (st) {
                c2b_error_prefix(err, "%s.samples (component %c): ", name, "xyz"[c]);
                return st;
            }
        }
    }
    return C2B_OK;
}

/* Truncation error of the sampled curves in a datum the blend gets as a callback, into
 * *emax (maximum). The sampled part sum_k a_k (curve k) is linear, so with one sample
 * count it is itself a set of samples, whose leave-half-out estimate
 * (c2b_vseries_project_samples) measures it, errors of neighbouring curves cancelling as
 * they do in eqs. 3-6. With different counts: the bound sum_k |a_k| e_k. */
static c2b_status sampled_part_error(const c2b_odesurf *s, int c, int p, double *emax)
{
    const c2b_odesurf_input *in = &s->in;
    unsigned used = datum_slots(in, p);
    double a[NSLOT] = {0}, bound = 0;
    int n = -1;
    for (int k = 0; k < NSLOT; k++)
        if ((used >> k & 1u) && slot_curve(in, k)->samples) {
            double unit[NSLOT] = {0};
            unit[k] = 1.0;
            a[k] = combine(in, p, unit);
            bound += fabs(a[k]) * s->series[k][c].err_abs;
            int nk = slot_curve(in, k)->n_samples;
            n = n < 0 ? nk : n == nk ? n : 0;
        }
    if (n <= 0) { /* no sampled curve (n < 0) or different counts (n = 0) */
        *emax = fmax(*emax, bound);
        return C2B_OK;
    }
    double *part = malloc((size_t)n * sizeof *part);
    if (!part)
        return C2B_ERR_NOMEM;
    for (int i = 0; i < n; i++) {
        part[i] = 0;
        for (int k = 0; k < NSLOT; k++)
            if (a[k] != 0.0)
                part[i] += a[k] * slot_curve(in, k)->samples[3 * (size_t)i + (size_t)c];
    }
    c2b_vseries ser;
    memset(&ser, 0, sizeof ser);
    c2b_status st = c2b_vseries_project_samples(&in->dom, part, 1, n, &s->pb.tol, &ser, NULL);
    *emax = fmax(*emax, st ? bound : ser.err_abs);
    c2b_vseries_clear(&ser);
    free(part);
    return st == C2B_ERR_NOMEM ? st : C2B_OK;
}

/* Bind datum (c, p): samples combined sample by sample when all its curves are sampled
 * with one count, otherwise the callback. */
static c2b_status bind_datum(c2b_odesurf *s, int c, int p)
{
    const c2b_odesurf_input *in = &s->in;
    unsigned used = datum_slots(in, p);
    int all_sampled = 1, n = -1, td = 0;
    for (int k = 0; k < NSLOT; k++)
        if (used >> k & 1u) {
            const c2b_curve *cv = slot_curve(in, k);
            td |= cv->time_dependent && !cv->samples;
            if (!cv->samples)
                all_sampled = 0;
            else if (n < 0)
                n = cv->n_samples;
            else if (n != cv->n_samples)
                n = 0;
        }
    dctx *d = &s->ctx[c][p];
    d->s = s, d->c = c, d->p = p;
    c2b_bfunc *bf = &s->pb.data[c][p / 3][p % 3];
    memset(bf, 0, sizeof *bf);
    bf->label = s->label[c][p];
    if (all_sampled && n > 0) {
        double *buf = malloc((size_t)n * sizeof *buf);
        if (!buf)
            return C2B_ERR_NOMEM;
        for (int i = 0; i < n; i++) {
            double x[NSLOT] = {0};
            for (int k = 0; k < NSLOT; k++)
                if (used >> k & 1u)
                    x[k] = slot_curve(in, k)->samples[3 * (size_t)i + (size_t)c];
            buf[i] = combine(in, p, x);
        }
        s->dsamples[c][p] = buf;
        snprintf(s->label[c][p], sizeof s->label[c][p], "curves: datum c%d (samples), component %c", p + 1,
                 "xyz"[c]);
        bf->samples = buf;
        bf->n_samples = n;
        bf->stride = 1;
        return C2B_OK;
    }
    snprintf(s->label[c][p], sizeof s->label[c][p], "curves: datum c%d, component %c", p + 1, "xyz"[c]);
    c2b_status st = sampled_part_error(s, c, p, &s->sample_err);
    if (st)
        return st;
    bf->fn = datum;
    bf->fn_vv = all_sampled ? datum_vv : NULL;
    bf->ctx = d;
    bf->time_dependent = td;
    return C2B_OK;
}

c2b_status c2b_odesurf_create(const c2b_odesurf_input *in, c2b_odesurf **out, c2b_error *err)
{
    if (!in || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_odesurf_create: NULL argument");
    *out = NULL;
    int any1 = in->c1.samples != NULL, any4 = in->c4.samples != NULL;
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
    s->in.tol = NULL; /* copied into pb.tol below; the caller's pointer may not live on */
    s->pb = c2b_problem_default();
    if (in->tol)
        s->pb.tol = *in->tol;
    s->pb.continuity = C2B_ODE;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int k = 0; k < 3; k++)
            s->pb.shape[c][k] = in->shape[k];
    s->pb.dom = in->dom;
    s->pb.time = in->time;
    c2b_status st = expand_samples(s, in->approach == C2B_ODESURF_CONTROLS ? NSLOT : 2, err);
    for (int c = 0; c < C2B_NCOMP && !st; c++)
        for (int p = 0; p < NDATUM && !st; p++)
            if (bind_datum(s, c, p))
                st = c2b_error_set(err, C2B_ERR_NOMEM, "ODE surface: out of memory");
    if (st) {
        c2b_odesurf_destroy(s);
        return st;
    }
    *out = s;
    return C2B_OK;
}

void c2b_odesurf_destroy(c2b_odesurf *s)
{
    if (!s)
        return;
    for (int k = 0; k < NSLOT; k++)
        for (int c = 0; c < C2B_NCOMP; c++)
            c2b_vseries_clear(&s->series[k][c]);
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int p = 0; p < NDATUM; p++)
            free(s->dsamples[c][p]);
    free(s);
}

const c2b_problem *c2b_odesurf_problem(const c2b_odesurf *s) { return s ? &s->pb : NULL; }

double c2b_odesurf_truncation_error(const c2b_odesurf *s) { return s ? s->sample_err : 0.0; }
