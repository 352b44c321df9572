#include "c2b_spec.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_expr.h"
#include "c2b_json.h"
#include "c2b_nurbs.h"
#include "c2b_nurbs_json.h"
#include "c2b_odesurf.h"

#define MAX_CONSTANTS 256
#define LABEL_LEN 96

/* Context of one boundary function: sign * d^p S/du^p at u = trim (primaries) or a
 * v,t-expression (explicit boundary data). */
/* A primary surface: expressions in (u, v, t) or a NURBS surface. */
typedef struct primary {
    int kind;                   /* 0 none (explicit boundary data), 1 expressions, 2 NURBS */
    c2b_expr *surf[C2B_NCOMP];  /* S(u, v, t) per component */
    c2b_expr *deriv[C2B_NCOMP][6]; /* derived on first use: S, S_u, S_v, S_uu, S_uv, S_vv */
    int deriv_failed;
    c2b_nurbs_surface *nurbs;
    int across_v;               /* NURBS trimmed along v = trim (trim_v) */
    double trim, dir;
    double map0, map1;          /* NURBS along-trimline parameter = map0 + map1 (v - v0) */
} primary;

typedef struct datum {
    const primary *prim; /* NURBS data: the primary; NULL for expressions and samples */
    int comp, order;     /* NURBS data: component and derivative order */
    c2b_expr *e;     /* function of (u,) v, t */
    c2b_expr *evv;   /* its second v-derivative, derived on first use */
    int evv_failed;
    c2b_expr *ev[C2B_VDATA_MAX_K + 1]; /* d^k e/dv^k, k >= 1, made by c2b_spec_vdata() */
    int vkind;       /* c2b_spec_vdata: 0 symbolic up to kmax, 1 e'' = 0, 2 e'' = vbeta e */
    double vbeta;
    double u;        /* trim parameter (ignored for boundary expressions) */
    double sign;
    double *samples; /* owned, 3 per row */
    char label[LABEL_LEN];
} datum;

typedef struct forcing {
    c2b_expr *e;
    char label[LABEL_LEN];
} forcing;

struct c2b_spec {
    c2b_problem pb;
    primary prim[2];
    datum data[C2B_NCOMP][2][C2B_MAX_N];
    forcing force[C2B_NCOMP];
    char *cnames[MAX_CONSTANTS];
    double cvalues[MAX_CONSTANTS];
    int nconst;
    char name[128];
    c2b_spec_solver solver;           /* "solver", "M", "N", "collocation", "approach" */
    c2b_expr *curve[6][C2B_NCOMP];    /* "curves": c1, c4, controls[0..3] */
    double *curve_samples[6];         /* the same curves given as samples (owned) */
    c2b_odesurf *odesurf;             /* owns the data contexts of a "curves" spec */
};

/* d^order/dcross^order d^dv/dalong^dv of a NURBS primary at blend parameter v. */
static double nurbs_datum(const datum *d, double v0, double v, int dv)
{
    const primary *pr = d->prim;
    double a = pr->map0 + pr->map1 * (v - v0), skl[(C2B_MAX_N + 1) * 3 * 3];
    int k = d->order;
    c2b_status st = pr->across_v ? c2b_nurbs_surface_derivs(pr->nurbs, a, pr->trim, dv, k, skl, NULL)
                                 : c2b_nurbs_surface_derivs(pr->nurbs, pr->trim, a, k, dv, skl, NULL);
    if (st)
        return NAN;
    int idx = pr->across_v ? dv * (k + 1) + k : k * (dv + 1) + dv;
    return d->sign * pow(pr->map1, dv) * skl[idx * 3 + d->comp];
}

static double datum_fn(void *ctx, double v, double t)
{
    const datum *d = ctx;
    if (d->prim)
        return nurbs_datum(d, d->u, v, 0);
    return d->sign * c2b_expr_eval(d->e, d->u, v, t);
}

/* The exact second v-derivative is only needed for open trimlines whose data are
 * neither polynomials nor modes (end polynomial + DST), and symbolic derivatives of large
 * expressions are expensive in libmatheval, so it is derived on first use. */
static double datum_vv(void *ctx, double v, double t)
{
    datum *d = ctx;
    if (d->prim)
        return nurbs_datum(d, d->u, v, 2);
    if (!d->evv && !d->evv_failed && c2b_expr_derivative(d->e, 'v', 2, &d->evv, NULL))
        d->evv_failed = 1;
    return d->evv ? d->sign * c2b_expr_eval(d->evv, d->u, v, t) : NAN;
}

static double force_fn(void *ctx, double u, double v, double t)
{
    const forcing *f = ctx;
    return c2b_expr_eval(f->e, u, v, t);
}

void c2b_spec_destroy(c2b_spec *s)
{
    if (!s)
        return;
    for (int c = 0; c < C2B_NCOMP; c++) {
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < C2B_MAX_N; p++) {
                c2b_expr_destroy(s->data[c][side][p].e);
                c2b_expr_destroy(s->data[c][side][p].evv);
                for (int k = 0; k <= C2B_VDATA_MAX_K; k++)
                    c2b_expr_destroy(s->data[c][side][p].ev[k]);
                free(s->data[c][side][p].samples);
            }
        c2b_expr_destroy(s->force[c].e);
    }
    for (int i = 0; i < 2; i++) {
        for (int c = 0; c < C2B_NCOMP; c++) {
            c2b_expr_destroy(s->prim[i].surf[c]);
            for (int k = 0; k < 6; k++)
                c2b_expr_destroy(s->prim[i].deriv[c][k]);
        }
        c2b_nurbs_surface_destroy(s->prim[i].nurbs);
    }
    for (int i = 0; i < s->nconst; i++)
        free(s->cnames[i]);
    for (int k = 0; k < 6; k++)
        for (int c = 0; c < C2B_NCOMP; c++)
            c2b_expr_destroy(s->curve[k][c]);
    for (int k = 0; k < 6; k++)
        free(s->curve_samples[k]);
    c2b_odesurf_destroy(s->odesurf);
    free(s);
}

const c2b_problem *c2b_spec_problem(const c2b_spec *s) { return &s->pb; }

int c2b_spec_has_primaries(const c2b_spec *s) { return s->prim[0].kind != 0; }

c2b_status c2b_spec_primary_eval(c2b_spec *s, int side, double ub, double v, double t, int order,
                                 double *out, c2b_error *err)
{
    if (!s || (side != 0 && side != 1) || order < 0 || order > 2 || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_spec_primary_eval: invalid arguments");
    primary *pr = &s->prim[side];
    if (!pr->kind)
        return c2b_error_set(err, C2B_ERR_ARG, "the spec gives boundary data, not primary surfaces");
    double cross = pr->trim + pr->dir * (ub - side), dc = pr->dir;
    size_t nd = (size_t)(order + 1) * (size_t)(order + 2) / 2;
    /* entry e = (a, b): a cross derivatives, b along derivatives */
    static const int ea[6] = {0, 1, 0, 2, 1, 0}, eb[6] = {0, 0, 1, 0, 1, 2};
    if (pr->kind == 2) {
        double a = pr->map0 + pr->map1 * (v - s->pb.dom.v0), skl[3 * 3 * 3];
        c2b_status st = pr->across_v ? c2b_nurbs_surface_derivs(pr->nurbs, a, cross, order, order, skl, err)
                                     : c2b_nurbs_surface_derivs(pr->nurbs, cross, a, order, order, skl, err);
        if (st) {
            c2b_error_prefix(err, "primaries[%d]: ", side);
            return st;
        }
        for (size_t e = 0; e < nd; e++) {
            int ka = ea[e], kb = eb[e];
            int idx = pr->across_v ? kb * (order + 1) + ka : ka * (order + 1) + kb;
            double f = pow(dc, ka) * pow(pr->map1, kb);
            for (int c = 0; c < 3; c++)
                out[e * 3 + (size_t)c] = f * skl[idx * 3 + c];
        }
        return C2B_OK;
    }
    for (int c = 0; c < C2B_NCOMP; c++)
        for (size_t e = 0; e < nd; e++) {
            c2b_expr **slot = &pr->deriv[c][e];
            if (!*slot && !pr->deriv_failed) {
                c2b_expr *du = NULL;
                c2b_status st = c2b_expr_derivative(pr->surf[c], 'u', ea[e], &du, err);
                if (!st)
                    st = c2b_expr_derivative(du, 'v', eb[e], slot, err);
                c2b_expr_destroy(du);
                if (st) {
                    pr->deriv_failed = 1;
                    c2b_error_prefix(err, "primaries[%d].surface[%d]: ", side, c);
                    return st;
                }
            }
            if (!*slot)
                return c2b_error_set(err, C2B_ERR_NUMERIC, "primaries[%d]: derivatives unavailable", side);
            out[e * 3 + (size_t)c] = pow(dc, ea[e]) * c2b_expr_eval(*slot, cross, v, t);
        }
    return C2B_OK;
}
const char *c2b_spec_name(const c2b_spec *s) { return s->name; }

/* ---- helpers that name the field ----------------------------------------------------- */

static c2b_status want_number(const cJSON *j, const char *field, double *out, c2b_error *err)
{
    if (!cJSON_IsNumber(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected a number", field);
    if (!isfinite(j->valuedouble))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: must be finite", field);
    *out = j->valuedouble;
    return C2B_OK;
}

static c2b_status want_numbers(const cJSON *j, const char *field, int n, double *out,
                               c2b_error *err)
{
    if (!cJSON_IsArray(j) || cJSON_GetArraySize(j) != n)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected an array of %d numbers", field, n);
    int i = 0;
    for (const cJSON *x = j->child; x; x = x->next, i++) {
        char f[LABEL_LEN];
        snprintf(f, sizeof f, "%s[%d]", field, i);
        c2b_status st = want_number(x, f, &out[i], err);
        if (st)
            return st;
    }
    return C2B_OK;
}

static c2b_constants constants_of(const c2b_spec *s)
{
    c2b_constants c = {s->nconst, (const char *const *)s->cnames, s->cvalues};
    return c;
}

static c2b_status make_expr(c2b_spec *s, const cJSON *j, const char *field, int allowed,
                            c2b_expr **out, c2b_error *err)
{
    if (cJSON_IsNumber(j)) {
        char buf[64];
        if (!isfinite(j->valuedouble))
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: must be finite", field);
        snprintf(buf, sizeof buf, "%.17g", j->valuedouble);
        return c2b_expr_create(buf, NULL, allowed, out, err);
    }
    if (!cJSON_IsString(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected an expression string", field);
    c2b_constants cs = constants_of(s);
    c2b_status st = c2b_expr_create(j->valuestring, &cs, allowed, out, err);
    if (st)
        c2b_error_prefix(err, "%s: ", field);
    return st;
}

/* ---- sections ---------------------------------------------------------------------- */

static c2b_status parse_constants(c2b_spec *s, const cJSON *j, c2b_error *err)
{
    if (!j)
        return C2B_OK;
    /* the count first: the check for repeated names compares every pair */
    if (cJSON_IsObject(j) && cJSON_GetArraySize(j) > MAX_CONSTANTS)
        return c2b_error_set(err, C2B_ERR_LIMIT, "constants: more than %d", MAX_CONSTANTS);
    c2b_status cs = c2b_json_keys(j, "constants", "of numbers", NULL, 0, NULL, err);
    if (cs)
        return cs;
    for (const cJSON *x = j->child; x; x = x->next) {
        char f[LABEL_LEN + 32];
        snprintf(f, sizeof f, "constants.%s", x->string);
        const char *nm = x->string;
        int valid = (nm[0] == '_' || (nm[0] >= 'a' && nm[0] <= 'z') || (nm[0] >= 'A' && nm[0] <= 'Z'));
        for (const char *p = nm; *p && valid; p++)
            valid = *p == '_' || (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
                    (*p >= '0' && *p <= '9');
        if (!valid)
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: not a valid identifier", f);
        if (!strcmp(nm, "u") || !strcmp(nm, "v") || !strcmp(nm, "t") || !strcmp(nm, "pi") ||
            !strcmp(nm, "e"))
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: '%s' is reserved (u, v, t, pi, e)", f, nm);
        if (s->nconst == MAX_CONSTANTS)
            return c2b_error_set(err, C2B_ERR_LIMIT, "constants: more than %d", MAX_CONSTANTS);
        double val = 0;
        c2b_status st = want_number(x, f, &val, err);
        if (st)
            return st;
        s->cnames[s->nconst] = malloc(strlen(nm) + 1);
        if (!s->cnames[s->nconst])
            return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        strcpy(s->cnames[s->nconst], nm);
        s->cvalues[s->nconst++] = val;
    }
    return C2B_OK;
}

static c2b_status parse_shape(c2b_spec *s, const cJSON *j, c2b_error *err)
{
    int ns = c2b_continuity_nshape(s->pb.continuity);
    if (!j)
        return C2B_OK;
    if (cJSON_IsArray(j)) {
        c2b_status st = want_numbers(j, "shape", ns, s->pb.shape[0], err);
        if (st) {
            c2b_error_prefix(err, "(%s takes %d: %s%s%s%s%s%s%s%s%s) ",
                             c2b_continuity_name(s->pb.continuity), ns,
                             c2b_continuity_param_name(s->pb.continuity, 0), ", ",
                             c2b_continuity_param_name(s->pb.continuity, 1), ", ",
                             c2b_continuity_param_name(s->pb.continuity, 2),
                             ns > 3 ? ", " : "",
                             ns > 3 ? c2b_continuity_param_name(s->pb.continuity, 3) : "",
                             ns > 4 ? ", " : "",
                             ns > 4 ? c2b_continuity_param_name(s->pb.continuity, 4) : "");
            return st;
        }
        memcpy(s->pb.shape[1], s->pb.shape[0], sizeof s->pb.shape[0]);
        memcpy(s->pb.shape[2], s->pb.shape[0], sizeof s->pb.shape[0]);
        return C2B_OK;
    }
    if (cJSON_IsObject(j)) {
        static const char *const keys[] = {"x", "y", "z", NULL};
        c2b_status st = c2b_json_keys(j, "shape", NULL, keys, 0, NULL, err);
        if (st)
            return st;
        for (int c = 0; c < C2B_NCOMP; c++) {
            char f[16];
            snprintf(f, sizeof f, "shape.%s", keys[c]);
            const cJSON *x = cJSON_GetObjectItemCaseSensitive(j, keys[c]);
            if (!x)
                return c2b_error_set(err, C2B_ERR_SPEC, "%s: missing (give x, y and z)", f);
            st = want_numbers(x, f, ns, s->pb.shape[c], err);
            if (st)
                return st;
        }
        return C2B_OK;
    }
    return c2b_error_set(err, C2B_ERR_SPEC,
                         "shape: expected an array of %d numbers or {\"x\": [...], \"y\": [...], \"z\": [...]}",
                         ns);
}

/* Bind datum (c, side, p) to an expression context. */
static void bind_expr_datum(c2b_spec *s, int c, int side, int p, c2b_expr *e, double u,
                            double sign)
{
    datum *d = &s->data[c][side][p];
    d->e = e;
    d->u = u;
    d->sign = sign;
    c2b_bfunc *bf = &s->pb.data[c][side][p];
    bf->fn = datum_fn;
    bf->fn_vv = datum_vv;
    bf->ctx = d;
    bf->time_dependent = c2b_expr_depends(e, 't');
    bf->label = d->label;
}

/* Data of a NURBS primary: d^k/dcross^k at the trim parameter, sampled along the
 * trimline with the other parameter mapped linearly from v_range. */
static c2b_status parse_nurbs_primary(c2b_spec *s, const cJSON *j, int side, const char *where,
                                      c2b_error *err)
{
    primary *pr = &s->prim[side];
    char f[LABEL_LEN];
    snprintf(f, sizeof f, "%s.nurbs", where);
    c2b_status st = c2b_nurbs_surface_from_json(cJSON_GetObjectItemCaseSensitive(j, "nurbs"), f,
                                                &pr->nurbs, err);
    if (st)
        return st;
    const cJSON *tu = cJSON_GetObjectItemCaseSensitive(j, "trim_u");
    const cJSON *tv = cJSON_GetObjectItemCaseSensitive(j, "trim_v");
    if (!!tu == !!tv)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: give exactly one of trim_u and trim_v", where);
    pr->across_v = tv != NULL;
    snprintf(f, sizeof f, "%s.%s", where, tv ? "trim_v" : "trim_u");
    if ((st = want_number(tv ? tv : tu, f, &pr->trim, err)))
        return st;
    double dom[4];
    c2b_nurbs_surface_domain(pr->nurbs, dom);
    int cross = pr->across_v, along = !cross;
    double lo = dom[2 * cross], hi = dom[2 * cross + 1];
    if (!c2b_nurbs_surface_periodic(pr->nurbs, cross) &&
        (pr->trim < lo - 1e-12 * (hi - lo) || pr->trim > hi + 1e-12 * (hi - lo)))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: %g is outside the knot range [%g, %g]", f,
                             pr->trim, lo, hi);
    pr->map0 = dom[2 * along];
    pr->map1 = (dom[2 * along + 1] - dom[2 * along]) / (s->pb.dom.v1 - s->pb.dom.v0);
    int n = c2b_continuity_n(s->pb.continuity);
    for (int c = 0; c < C2B_NCOMP; c++) {
        double sign = 1.0;
        for (int p = 0; p < n; p++) {
            datum *d = &s->data[c][side][p];
            d->prim = pr;
            d->comp = c;
            d->order = p;
            d->u = s->pb.dom.v0; /* the start of v_range, for the parameter map */
            d->sign = sign;
            snprintf(d->label, LABEL_LEN, "%s.nurbs (d^%d/d%c^%d at %c=%g, component %c)", where, p,
                     tv ? 'v' : 'u', p, tv ? 'v' : 'u', pr->trim, "xyz"[c]);
            c2b_bfunc *bf = &s->pb.data[c][side][p];
            bf->fn = datum_fn;
            bf->fn_vv = datum_vv;
            bf->ctx = d;
            bf->time_dependent = 0;
            bf->label = d->label;
            sign *= pr->dir;
        }
    }
    pr->kind = 2;
    return C2B_OK;
}

static c2b_status parse_primary(c2b_spec *s, const cJSON *j, int side, c2b_error *err)
{
    char where[LABEL_LEN];
    snprintf(where, sizeof where, "primaries[%d]", side);
    if (!cJSON_IsObject(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected an object", where);
    static const char *const keys[] = {"surface", "nurbs", "trim_u", "trim_v", "direction", "name", NULL};
    c2b_status st = c2b_json_keys(j, where, NULL, keys, 0, NULL, err);
    if (st)
        return st;
    primary *pr = &s->prim[side];
    const cJSON *surf = cJSON_GetObjectItemCaseSensitive(j, "surface");
    const cJSON *nj = cJSON_GetObjectItemCaseSensitive(j, "nurbs");
    const cJSON *tj = cJSON_GetObjectItemCaseSensitive(j, "trim_u");
    const cJSON *dj = cJSON_GetObjectItemCaseSensitive(j, "direction");
    char f[LABEL_LEN];
    pr->dir = 1.0;
    if (dj) {
        snprintf(f, sizeof f, "%s.direction", where);
        st = want_number(dj, f, &pr->dir, err);
        if (st)
            return st;
        if (pr->dir != 1.0 && pr->dir != -1.0)
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: must be 1 or -1, got %g", f, pr->dir);
    }
    if (!!surf == !!nj)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: give exactly one of 'surface' and 'nurbs'", where);
    if (nj)
        return parse_nurbs_primary(s, j, side, where, err);
    if (cJSON_GetObjectItemCaseSensitive(j, "trim_v"))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s.trim_v: only NURBS primaries take trim_v", where);
    if (!tj)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s.trim_u: missing", where);
    if (!cJSON_IsArray(surf) || cJSON_GetArraySize(surf) != 3)
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "%s.surface: expected 3 expressions [x, y, z] in u, v, t", where);
    snprintf(f, sizeof f, "%s.trim_u", where);
    st = want_number(tj, f, &pr->trim, err);
    if (st)
        return st;
    pr->kind = 1;
    int n = c2b_continuity_n(s->pb.continuity);
    int c = 0;
    for (const cJSON *x = surf->child; x; x = x->next, c++) {
        snprintf(f, sizeof f, "%s.surface[%d]", where, c);
        st = make_expr(s, x, f, C2B_EXPR_U | C2B_EXPR_V | C2B_EXPR_T, &pr->surf[c], err);
        if (st)
            return st;
        /* C_p = direction^p d^p S / du^p at u = trim_u (thesis sign convention) */
        double sign = 1.0;
        for (int p = 0; p < n; p++) {
            c2b_expr *dp = NULL;
            st = c2b_expr_derivative(pr->surf[c], 'u', p, &dp, err);
            if (st) {
                c2b_error_prefix(err, "%s: ", f);
                return st;
            }
            snprintf(s->data[c][side][p].label, LABEL_LEN, "%s (d^%d/du^%d at u=%g)", f, p, p,
                     pr->trim);
            bind_expr_datum(s, c, side, p, dp, pr->trim, sign);
            sign *= pr->dir;
        }
    }
    return C2B_OK;
}

/* {"samples": [[x, y, z], ...]} (the object j, at field `where`): uniform over v_range,
 * the end point not repeated on periodic ranges. *out gets n rows of 3 finite numbers,
 * malloc'd (the caller owns it). `what` names the sampled thing in the count message. */
static c2b_status parse_samples(const c2b_spec *s, const cJSON *j, const char *where, const char *what,
                                double **out, int *n, c2b_error *err)
{
    static const char *const keys[] = {"samples", NULL};
    c2b_status st = c2b_json_keys(j, where, NULL, keys, 0, NULL, err);
    if (st)
        return st;
    const cJSON *sm = cJSON_GetObjectItemCaseSensitive(j, "samples");
    if (!cJSON_IsArray(sm))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s.samples: expected an array of [x, y, z]", where);
    int ns = cJSON_GetArraySize(sm);
    int nmin = s->pb.dom.periodic ? 4 : 7;
    if (ns < nmin)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s.samples: %d samples given, at least %d are needed (%s %s)",
                             where, ns, nmin, s->pb.dom.periodic ? "periodic" : "open", what);
    double *buf = malloc((size_t)ns * 3 * sizeof *buf);
    if (!buf)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    int i = 0;
    for (const cJSON *x = sm->child; x; x = x->next, i++) {
        char f[LABEL_LEN + 16];
        snprintf(f, sizeof f, "%s.samples[%d]", where, i);
        st = want_numbers(x, f, 3, buf + 3 * i, err);
        if (st) {
            free(buf);
            return st;
        }
    }
    *out = buf;
    *n = ns;
    return C2B_OK;
}

static c2b_status parse_boundary_row(c2b_spec *s, const cJSON *row, int side, int p,
                                     const char *where, c2b_error *err)
{
    if (cJSON_IsArray(row)) {
        if (cJSON_GetArraySize(row) != 3)
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "%s: expected 3 expressions [x, y, z] in v and t, got %d",
                                 where, cJSON_GetArraySize(row));
        int c = 0;
        for (const cJSON *x = row->child; x; x = x->next, c++) {
            char f[LABEL_LEN];
            snprintf(f, sizeof f, "%s[%d]", where, c);
            c2b_expr *e = NULL;
            c2b_status st = make_expr(s, x, f, C2B_EXPR_V | C2B_EXPR_T, &e, err);
            if (st)
                return st;
            snprintf(s->data[c][side][p].label, LABEL_LEN, "%s", f);
            bind_expr_datum(s, c, side, p, e, 0.0, 1.0);
        }
        return C2B_OK;
    }
    if (cJSON_IsObject(row)) {
        double *buf = NULL;
        int ns = 0;
        c2b_status st = parse_samples(s, row, where, "trimline", &buf, &ns, err);
        if (st)
            return st;
        for (int c = 0; c < C2B_NCOMP; c++) {
            datum *d = &s->data[c][side][p];
            snprintf(d->label, LABEL_LEN, "%s.samples (component %c)", where, "xyz"[c]);
            c2b_bfunc *bf = &s->pb.data[c][side][p];
            bf->samples = buf + c;
            bf->n_samples = ns;
            bf->stride = 3;
            bf->label = d->label;
        }
        s->data[0][side][p].samples = buf; /* owner */
        return C2B_OK;
    }
    return c2b_error_set(err, C2B_ERR_SPEC,
                         "%s: expected [x, y, z] expressions or {\"samples\": [[x, y, z], ...]}",
                         where);
}

static c2b_status parse_boundary(c2b_spec *s, const cJSON *j, c2b_error *err)
{
    if (!cJSON_IsObject(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "boundary: expected {\"u0\": [...], \"u1\": [...]}");
    static const char *const keys[] = {"u0", "u1", NULL};
    c2b_status st = c2b_json_keys(j, "boundary", NULL, keys, 0, NULL, err);
    if (st)
        return st;
    int n = c2b_continuity_n(s->pb.continuity);
    static const char *const rows[] = {"S", "S_u", "S_uu", "S_uuu"};
    for (int side = 0; side < 2; side++) {
        const cJSON *sj = cJSON_GetObjectItemCaseSensitive(j, keys[side]);
        if (!sj)
            return c2b_error_set(err, C2B_ERR_SPEC, "boundary.%s: missing", keys[side]);
        if (!cJSON_IsArray(sj) || cJSON_GetArraySize(sj) != n) {
            char list[64] = "";
            for (int p = 0; p < n; p++) {
                strcat(list, p ? ", " : "");
                strcat(list, rows[p]);
            }
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "boundary.%s: %s needs %d rows (%s), got %d",
                                 keys[side], c2b_continuity_name(s->pb.continuity), n, list,
                                 cJSON_IsArray(sj) ? cJSON_GetArraySize(sj) : 0);
        }
        int p = 0;
        for (const cJSON *row = sj->child; row; row = row->next, p++) {
            char where[LABEL_LEN];
            snprintf(where, sizeof where, "boundary.%s[%d]", keys[side], p);
            st = parse_boundary_row(s, row, side, p, where, err);
            if (st)
                return st;
        }
    }
    return C2B_OK;
}

static c2b_status parse_force(c2b_spec *s, const cJSON *j, c2b_error *err)
{
    if (!cJSON_IsArray(j) || cJSON_GetArraySize(j) != 3)
        return c2b_error_set(err, C2B_ERR_SPEC, "force: expected 3 expressions [Fx, Fy, Fz] in u, v, t");
    int c = 0;
    for (const cJSON *x = j->child; x; x = x->next, c++) {
        forcing *fo = &s->force[c];
        snprintf(fo->label, LABEL_LEN, "force[%d]", c);
        c2b_status st = make_expr(s, x, fo->label, C2B_EXPR_U | C2B_EXPR_V | C2B_EXPR_T, &fo->e, err);
        if (st)
            return st;
        /* An identically zero force is no force: skip it. */
        if (!c2b_expr_depends(fo->e, 'u') && !c2b_expr_depends(fo->e, 'v') &&
            !c2b_expr_depends(fo->e, 't') && c2b_expr_eval(fo->e, 0, 0, 0) == 0.0)
            continue;
        s->pb.force[c].fn = force_fn;
        s->pb.force[c].ctx = fo;
        s->pb.force[c].time_dependent = c2b_expr_depends(fo->e, 't');
        s->pb.force[c].label = fo->label;
    }
    return C2B_OK;
}


/* "solver", "M", "N", "collocation", "approach", "group2" (docs/APPROX.md). */
static c2b_status parse_solver(c2b_spec *s, const cJSON *root, c2b_error *err)
{
    const cJSON *j = cJSON_GetObjectItemCaseSensitive(root, "solver");
    memset(&s->solver, 0, sizeof s->solver);
    if (j) {
        if (!cJSON_IsString(j))
            return c2b_error_set(err, C2B_ERR_SPEC, "solver: expected \"exact\", \"thesis-approx\" or \"pseudo-navier\"");
        if (!strcmp(j->valuestring, "exact"))
            s->solver.kind = C2B_SOLVER_EXACT;
        else if (!strcmp(j->valuestring, "thesis-approx"))
            s->solver.kind = C2B_SOLVER_THESIS_APPROX;
        else if (!strcmp(j->valuestring, "pseudo-navier"))
            s->solver.kind = C2B_SOLVER_PSEUDO_NAVIER;
        else
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "solver: '%s' is not one of exact, thesis-approx, pseudo-navier", j->valuestring);
    }
    static const char *const ints[] = {"M", "N"};
    int *dst[2] = {&s->solver.M, &s->solver.N};
    for (int k = 0; k < 2; k++) {
        j = cJSON_GetObjectItemCaseSensitive(root, ints[k]);
        if (!j)
            continue;
        if (!cJSON_IsNumber(j) || j->valuedouble != floor(j->valuedouble) || j->valuedouble < 1 ||
            j->valuedouble > 1024)
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected an integer in 1..1024", ints[k]);
        *dst[k] = (int)j->valuedouble;
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "collocation");
    if (j) {
        double ij[2];
        c2b_status st = want_numbers(j, "collocation", 2, ij, err);
        if (st)
            return st;
        if (ij[0] != floor(ij[0]) || ij[1] != floor(ij[1]) || ij[0] < 1 || ij[1] < 1 || ij[0] > 10000 ||
            ij[1] > 10000)
            return c2b_error_set(err, C2B_ERR_SPEC, "collocation: expected [I, J], integers in 1..10000");
        s->solver.ci = (int)ij[0], s->solver.cj = (int)ij[1];
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "approach");
    if (j) {
        if (!cJSON_IsString(j) || (strcmp(j->valuestring, "differential") && strcmp(j->valuestring, "decomposition")))
            return c2b_error_set(err, C2B_ERR_SPEC, "approach: expected \"differential\" or \"decomposition\"");
        s->solver.approach = !strcmp(j->valuestring, "decomposition");
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "group2");
    if (j) {
        if (!cJSON_IsString(j) || (strcmp(j->valuestring, "series") && strcmp(j->valuestring, "closed")))
            return c2b_error_set(err, C2B_ERR_SPEC, "group2: expected \"series\" or \"closed\"");
        if (s->solver.kind != C2B_SOLVER_THESIS_APPROX)
            return c2b_error_set(err, C2B_ERR_SPEC, "group2: only valid with \"solver\": \"thesis-approx\"");
        s->solver.group2_closed = !strcmp(j->valuestring, "closed");
    }
    if (s->solver.kind == C2B_SOLVER_EXACT &&
        (s->solver.M || s->solver.N || s->solver.ci || cJSON_GetObjectItemCaseSensitive(root, "approach")))
        return c2b_error_set(err, C2B_ERR_SPEC, "M/N/collocation/approach: only valid with an approximate \"solver\"");
    return C2B_OK;
}

static double curve_fn(void *ctx, double v, double t) { return c2b_expr_eval(ctx, 0.0, v, t); }

/* A curve into slot k: three expressions in v, t (into s->curve[k]) or
 * {"samples": [[x, y, z], ...]}, uniform over v_range like sampled boundary rows (into
 * s->curve_samples[k]; c2b_odesurf expands them). *out gets the curve. */
static c2b_status parse_curve(c2b_spec *s, const cJSON *j, const char *where, int k, c2b_curve *out,
                              c2b_error *err)
{
    memset(out, 0, sizeof *out);
    if (cJSON_IsObject(j)) {
        c2b_status st = parse_samples(s, j, where, "curve", &s->curve_samples[k], &out->n_samples, err);
        out->samples = s->curve_samples[k];
        return st;
    }
    if (!cJSON_IsArray(j) || cJSON_GetArraySize(j) != 3)
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "%s: expected 3 expressions [x, y, z] in v and t, or {\"samples\": [[x, y, z], ...]}",
                             where);
    int c = 0;
    for (const cJSON *x = j->child; x; x = x->next, c++) {
        char f[LABEL_LEN];
        snprintf(f, sizeof f, "%s[%d]", where, c);
        c2b_status st = make_expr(s, x, f, C2B_EXPR_V | C2B_EXPR_T, &s->curve[k][c], err);
        if (st)
            return st;
        out->fn[c] = curve_fn;
        out->ctx[c] = s->curve[k][c];
        out->time_dependent |= c2b_expr_depends(s->curve[k][c], 't');
    }
    return C2B_OK;
}

/* Seed 000 surfaces: "curves": {"c1": [...], "c4": [...], "w": [w1..w4]} or
 * {"c1", "c4", "controls": [{"u": u2, "curve": [...]}, x 4]} (c2b_odesurf.h); every
 * curve is [x, y, z] expressions or {"samples": [[x, y, z], ...]}. */
static c2b_status parse_curves(c2b_spec *s, const cJSON *j, c2b_error *err)
{
    if (!cJSON_IsObject(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "curves: expected an object");
    static const char *const keys[] = {"c1", "c4", "w", "controls", NULL};
    c2b_status st = c2b_json_keys(j, "curves", NULL, keys, 0, NULL, err);
    if (st)
        return st;
    if (s->pb.continuity != C2B_ODE)
        return c2b_error_set(err, C2B_ERR_SPEC, "curves: needs \"continuity\": \"ODE\" (seed 000 eq. 2)");
    if (s->solver.kind != C2B_SOLVER_EXACT)
        return c2b_error_set(err, C2B_ERR_SPEC, "solver: 'curves' surfaces are solved exactly; remove \"solver\"");
    c2b_odesurf_input in;
    memset(&in, 0, sizeof in);
    const cJSON *c1 = cJSON_GetObjectItemCaseSensitive(j, "c1"), *c4 = cJSON_GetObjectItemCaseSensitive(j, "c4");
    if (!c1 || !c4)
        return c2b_error_set(err, C2B_ERR_SPEC, "curves.%s: missing", c1 ? "c4" : "c1");
    if ((st = parse_curve(s, c1, "curves.c1", 0, &in.c1, err)) || (st = parse_curve(s, c4, "curves.c4", 1, &in.c4, err)))
        return st;
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(j, "w"), *ctl = cJSON_GetObjectItemCaseSensitive(j, "controls");
    if (!!w == !!ctl)
        return c2b_error_set(err, C2B_ERR_SPEC, "curves: give exactly one of 'w' (eq. 24) and 'controls' (eqs. 3-7)");
    if (w) {
        in.approach = C2B_ODESURF_MULTIPLES;
        if ((st = want_numbers(w, "curves.w", 4, in.w, err)))
            return st;
    } else {
        in.approach = C2B_ODESURF_CONTROLS;
        if (!cJSON_IsArray(ctl) || cJSON_GetArraySize(ctl) != 4)
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "curves.controls: expected 4 control curves (at u2 < u3 near u = 0, u5 < u6 near u = 1)");
        int k = 0;
        for (const cJSON *x = ctl->child; x; x = x->next, k++) {
            char f[LABEL_LEN];
            snprintf(f, sizeof f, "curves.controls[%d]", k);
            static const char *const ck[] = {"u", "curve", NULL};
            if (!cJSON_IsObject(x))
                return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected {\"u\": ..., \"curve\": [x, y, z]}", f);
            if ((st = c2b_json_keys(x, f, NULL, ck, 0, NULL, err)))
                return st;
            char fu[LABEL_LEN + 8], fc[LABEL_LEN + 8];
            snprintf(fu, sizeof fu, "%s.u", f);
            snprintf(fc, sizeof fc, "%s.curve", f);
            const cJSON *u = cJSON_GetObjectItemCaseSensitive(x, "u");
            if (!u)
                return c2b_error_set(err, C2B_ERR_SPEC, "%s: missing", fu);
            if ((st = want_number(u, fu, &in.uc[k], err)) ||
                (st = parse_curve(s, cJSON_GetObjectItemCaseSensitive(x, "curve"), fc, 2 + k, &in.control[k], err)))
                return st;
        }
    }
    for (int k = 0; k < 3; k++)
        in.shape[k] = s->pb.shape[0][k];
    in.dom = s->pb.dom;
    in.time = s->pb.time;
    in.tol = &s->pb.tol;
    if ((st = c2b_odesurf_create(&in, &s->odesurf, err)))
        return st;
    const c2b_problem *op = c2b_odesurf_problem(s->odesurf);
    memcpy(s->pb.data, op->data, sizeof s->pb.data);
    return C2B_OK;
}

static c2b_status parse_root(c2b_spec *s, const cJSON *root, c2b_error *err)
{
    if (!cJSON_IsObject(root))
        return c2b_error_set(err, C2B_ERR_SPEC, "spec: the top level must be a JSON object");
    static const char *const keys[] = {"name", "description", "source", "continuity", "shape",
                                       "v_range", "periodic", "constants", "time", "primaries",
                                       "boundary", "force", "tolerance", "solver", "M", "N",
                                       "collocation", "approach", "group2", "curves", NULL};
    c2b_status st = c2b_json_keys(root, "", NULL, keys, 0, NULL, err);
    if (st)
        return st;
    const cJSON *j;
    for (int i = 0; i < 3; i++) {
        j = cJSON_GetObjectItemCaseSensitive(root, keys[i]);
        if (j && !cJSON_IsString(j))
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected a string", keys[i]);
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "name");
    if (j)
        snprintf(s->name, sizeof s->name, "%s", j->valuestring);

    j = cJSON_GetObjectItemCaseSensitive(root, "continuity");
    if (j) {
        if (!cJSON_IsString(j))
            return c2b_error_set(err, C2B_ERR_SPEC, "continuity: expected \"C1\", \"C2\", \"C3\" or \"ODE\"");
        const char *v = j->valuestring;
        if (!strcmp(v, "C1"))
            s->pb.continuity = C2B_C1;
        else if (!strcmp(v, "C2"))
            s->pb.continuity = C2B_C2;
        else if (!strcmp(v, "C3"))
            s->pb.continuity = C2B_C3;
        else if (!strcmp(v, "ODE"))
            s->pb.continuity = C2B_ODE;
        else
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "continuity: '%s' is not one of C1, C2, C3, ODE", v);
    }
    st = parse_shape(s, cJSON_GetObjectItemCaseSensitive(root, "shape"), err);
    if (st)
        return st;
    j = cJSON_GetObjectItemCaseSensitive(root, "v_range");
    if (j) {
        double vr[2];
        st = want_numbers(j, "v_range", 2, vr, err);
        if (st)
            return st;
        if (!(vr[1] > vr[0]))
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "v_range: [%g, %g] has zero or negative length", vr[0], vr[1]);
        s->pb.dom.v0 = vr[0];
        s->pb.dom.v1 = vr[1];
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "periodic");
    if (j) {
        if (!cJSON_IsBool(j))
            return c2b_error_set(err, C2B_ERR_SPEC, "periodic: expected true or false");
        s->pb.dom.periodic = cJSON_IsTrue(j);
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "time");
    if (j && (st = want_number(j, "time", &s->pb.time, err)))
        return st;
    j = cJSON_GetObjectItemCaseSensitive(root, "tolerance");
    if (j) {
        double tol = 0;
        if ((st = want_number(j, "tolerance", &tol, err)))
            return st;
        if (!(tol > 0 && tol < 1))
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "tolerance: relative truncation tolerance must be in (0, 1), got %g", tol);
        s->pb.tol.truncation_rel = tol;
    }
    st = parse_constants(s, cJSON_GetObjectItemCaseSensitive(root, "constants"), err);
    if (st)
        return st;
    if ((st = parse_solver(s, root, err)))
        return st;
    const cJSON *prim = cJSON_GetObjectItemCaseSensitive(root, "primaries");
    const cJSON *bnd = cJSON_GetObjectItemCaseSensitive(root, "boundary");
    const cJSON *crv = cJSON_GetObjectItemCaseSensitive(root, "curves");
    if (crv) {
        if (prim || bnd)
            return c2b_error_set(err, C2B_ERR_SPEC, "curves: give 'curves' alone, without 'primaries' or 'boundary'");
        if ((st = parse_curves(s, crv, err)))
            return st;
        if ((j = cJSON_GetObjectItemCaseSensitive(root, "force")))
            return c2b_error_set(err, C2B_ERR_SPEC, "force: not supported with 'curves'");
        return C2B_OK;
    }
    if (prim && bnd)
        return c2b_error_set(err, C2B_ERR_SPEC, "spec: give either 'primaries' or 'boundary', not both");
    if (!prim && !bnd)
        return c2b_error_set(err, C2B_ERR_SPEC, "spec: missing 'primaries' (or explicit 'boundary' data, or 'curves')");
    if (prim) {
        if (!cJSON_IsArray(prim) || cJSON_GetArraySize(prim) != 2)
            return c2b_error_set(err, C2B_ERR_SPEC, "primaries: expected an array of exactly 2 primaries");
        int side = 0;
        for (const cJSON *x = prim->child; x; x = x->next, side++)
            if ((st = parse_primary(s, x, side, err)))
                return st;
    } else if ((st = parse_boundary(s, bnd, err))) {
        return st;
    }
    j = cJSON_GetObjectItemCaseSensitive(root, "force");
    if (j && (st = parse_force(s, j, err)))
        return st;
    /* NURBS data are piecewise polynomial: their mode expansions converge algebraically,
     * so the default target is 1e-9 of the data scale unless the spec sets one. */
    if ((s->prim[0].kind == 2 || s->prim[1].kind == 2) &&
        !cJSON_GetObjectItemCaseSensitive(root, "tolerance"))
        s->pb.tol.truncation_rel = 1e-9;
    return C2B_OK;
}

/* Points per trimline, and the relative distance (of the largest |S|) below which two
 * points count as equal, in the degenerate-trimline check below. */
#define TRIMLINE_CHECK_POINTS 33
#define TRIMLINE_DEGENERATE_REL 1e-12

/* Primaries whose trimline is a single point, or whose two trimlines coincide, leave
 * nothing to blend: report them by name. Non-finite values are left to the blend,
 * whose message gives the datum and v. */
static c2b_status check_trimlines(c2b_spec *s, c2b_error *err)
{
    if (!s->prim[0].kind || !s->prim[1].kind)
        return C2B_OK;
    double S[2][TRIMLINE_CHECK_POINTS][3], scale = 0.0;
    const c2b_vdomain *dom = &s->pb.dom;
    int np = TRIMLINE_CHECK_POINTS;
    for (int side = 0; side < 2; side++)
        for (int i = 0; i < np; i++) {
            double v = dom->v0 + (dom->v1 - dom->v0) * i / (dom->periodic ? np : np - 1);
            c2b_error ignored; /* not NULL: c2b_error_prefix() returns C2B_OK for NULL */
            if (c2b_spec_primary_eval(s, side, side, v, s->pb.time, 0, S[side][i], &ignored))
                return C2B_OK;
            for (int c = 0; c < 3; c++) {
                if (!isfinite(S[side][i][c]))
                    return C2B_OK;
                scale = fmax(scale, fabs(S[side][i][c]));
            }
        }
    double tol = TRIMLINE_DEGENERATE_REL * scale, len[2] = {0, 0}, gap = 0;
    for (int i = 0; i < np; i++)
        for (int c = 0; c < 3; c++) {
            for (int side = 0; side < 2; side++)
                len[side] = fmax(len[side], fabs(S[side][i][c] - S[side][0][c]));
            gap = fmax(gap, fabs(S[0][i][c] - S[1][i][c]));
        }
    for (int side = 0; side < 2; side++)
        if (len[side] <= tol)
            return c2b_error_set(err, C2B_ERR_SPEC,
                                 "primaries[%d]: degenerate trimline at %s = %g: zero length (every "
                                 "v gives the point (%g, %g, %g))",
                                 side, s->prim[side].across_v ? "trim_v" : "trim_u",
                                 s->prim[side].trim, S[side][0][0], S[side][0][1], S[side][0][2]);
    if (gap <= tol)
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "primaries[0] and primaries[1]: the two trimlines are identical "
                             "(largest distance %g over %d points in v): there is nothing to blend",
                             gap, np);
    return C2B_OK;
}

c2b_status c2b_spec_parse(const char *json, size_t len, c2b_spec **out, c2b_error *err)
{
    if (!json || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_spec_parse: NULL argument");
    *out = NULL;
    if (len > (size_t)C2B_SPEC_MAX_BYTES)
        return c2b_error_set(err, C2B_ERR_LIMIT, "spec: %zu bytes exceeds the limit of %ld", len,
                             C2B_SPEC_MAX_BYTES);
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(json, len, &end, 0);
    if (!root) {
        int line = 1, col = 1;
        const char *stop = end ? end : json;
        for (const char *p = json; p < stop && p < json + len; p++) {
            if (*p == '\n') {
                line++;
                col = 1;
            } else {
                col++;
            }
        }
        return c2b_error_set(err, C2B_ERR_SPEC, "spec: malformed JSON near line %d, column %d",
                             line, col);
    }
    c2b_spec *s = calloc(1, sizeof *s);
    if (!s) {
        cJSON_Delete(root);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    }
    s->pb = c2b_problem_default();
    c2b_status st = parse_root(s, root, err);
    cJSON_Delete(root);
    if (!st)
        st = check_trimlines(s, err);
    if (st) {
        c2b_spec_destroy(s);
        return st;
    }
    *out = s;
    return C2B_OK;
}

c2b_status c2b_spec_load(const char *path, c2b_spec **out, c2b_error *err)
{
    if (!path || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_spec_load: NULL argument");
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    if (!f)
        return c2b_error_set(err, C2B_ERR_IO, "%s: cannot open spec file", path);
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    c2b_status st = C2B_OK;
    while (buf) {
        if (len == cap) {
            if (cap >= (size_t)C2B_SPEC_MAX_BYTES) {
                st = c2b_error_set(err, C2B_ERR_LIMIT, "%s: larger than %ld bytes", path,
                                   C2B_SPEC_MAX_BYTES);
                break;
            }
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0)
            break;
    }
    if (!st && !buf)
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory reading %s", path);
    if (!st && ferror(f))
        st = c2b_error_set(err, C2B_ERR_IO, "%s: read error", path);
    if (f != stdin)
        fclose(f);
    if (!st) {
        st = c2b_spec_parse(buf, len, out, err);
        if (st)
            c2b_error_prefix(err, "%s: ", path);
    }
    free(buf);
    return st;
}

c2b_spec_solver c2b_spec_solver_settings(const c2b_spec *s)
{
    c2b_spec_solver z;
    memset(&z, 0, sizeof z);
    return s ? s->solver : z;
}

static double datum_vk(void *ctx, int k, double v, double t)
{
    const datum *d = ctx;
    if (k < 0 || k > C2B_VDATA_MAX_K)
        return NAN;
    if (k == 0)
        return d->sign * c2b_expr_eval(d->e, d->u, v, t);
    if (d->vkind == 1 && k > 2)
        return 0.0;
    if (d->vkind == 2 && k > 2) /* e^(2q + r) = beta^q e^(r) */
        return pow(d->vbeta, k / 2) * datum_vk(ctx, k % 2, v, t);
    return d->ev[k] ? d->sign * c2b_expr_eval(d->ev[k], d->u, v, t) : NAN;
}

/* Sample points of the structure test: v across the range, three times. */
#define VDATA_TEST_POINTS 37
#define VDATA_TEST_REL 1e-11

/* Classify datum d from e and e'': 1 when e'' = 0, 2 when e'' = beta e with one beta
 * at every test point (then all higher derivatives follow exactly), 0 otherwise. */
static int vdata_structure(const c2b_spec *s, datum *d)
{
    const double ts[3] = {s->pb.time, s->pb.time + 0.37, s->pb.time + 1.1};
    double f[3][VDATA_TEST_POINTS], f2[3][VDATA_TEST_POINTS], fmax_ = 0, f2max = 0, num = 0, den = 0;
    for (int it = 0; it < 3; it++)
        for (int i = 0; i < VDATA_TEST_POINTS; i++) {
            double v = s->pb.dom.v0 + (s->pb.dom.v1 - s->pb.dom.v0) * (i + 0.31) / VDATA_TEST_POINTS;
            f[it][i] = c2b_expr_eval(d->e, d->u, v, ts[it]);
            f2[it][i] = c2b_expr_eval(d->ev[2], d->u, v, ts[it]);
            if (!isfinite(f[it][i]) || !isfinite(f2[it][i]))
                return 0;
            fmax_ = fmax(fmax_, fabs(f[it][i]));
            f2max = fmax(f2max, fabs(f2[it][i]));
            num += f2[it][i] * f[it][i];
            den += f[it][i] * f[it][i];
        }
    if (f2max <= VDATA_TEST_REL * fmax_)
        return 1;
    if (!(den > 0))
        return 0;
    double beta = num / den;
    for (int it = 0; it < 3; it++)
        for (int i = 0; i < VDATA_TEST_POINTS; i++)
            if (fabs(f2[it][i] - beta * f[it][i]) > VDATA_TEST_REL * f2max)
                return 0;
    d->vbeta = beta;
    return 2;
}

c2b_status c2b_spec_vdata(c2b_spec *s, int kmax, c2b_vdata *out, c2b_error *err)
{
    if (!s || !out || kmax < 0 || kmax > C2B_VDATA_MAX_K)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_spec_vdata: NULL argument or kmax outside 0..%d",
                             C2B_VDATA_MAX_K);
    memset(out, 0, sizeof *out);
    int n = c2b_continuity_n(s->pb.continuity);
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < n; p++) {
                datum *d = &s->data[c][side][p];
                const c2b_bfunc *bf = &s->pb.data[c][side][p];
                if (!bf->fn && !bf->samples)
                    continue;
                if (!d->e || d->prim || s->odesurf)
                    return c2b_error_set(err, C2B_ERR_SPEC,
                                         "%s: the approximate solvers need expression data (symbolic v-derivatives), "
                                         "not NURBS, samples or curves",
                                         d->label[0] ? d->label : "boundary data");
                /* libmatheval does not simplify: each derivative order multiplies the
                 * expression size by ~5 (a 6th derivative of a small primary takes seconds).
                 * So e' and e'' are derived first; when e'' = 0 or e'' = beta e (the
                 * thesis' groups 1 and 2) the higher orders follow exactly, and only
                 * other data are differentiated further, one order at a time. */
                for (int k = 1; k <= kmax; k++) {
                    if (k == 3)
                        d->vkind = vdata_structure(s, d);
                    if (k >= 3 && d->vkind)
                        break;
                    if (!d->ev[k]) {
                        c2b_status st = c2b_expr_derivative(k == 1 ? d->e : d->ev[k - 1], 'v', 1, &d->ev[k], err);
                        if (st) {
                            c2b_error_prefix(err, "%s: d^%d/dv^%d: ", d->label, k, k);
                            return st;
                        }
                    }
                }
                c2b_vdfunc f = {datum_vk, d, bf->time_dependent};
                out->f[c][side][p] = f;
            }
    return C2B_OK;
}
