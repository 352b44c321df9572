/*
 * JSON reader and writer of NURBS curves and surfaces (see c2b_nurbs_json.h).
 */
#include "c2b_nurbs_json.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_json.h"

/* Path buffers: a path prefix plus a short field name. */
#define NJ_PATH 512

/* "<field>.<sub>" into buf (or just sub / field). */
static const char *nj_path(char *buf, size_t len, const char *field, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static const char *nj_path(char *buf, size_t len, const char *field, const char *fmt, ...)
{
    char sub[128];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sub, sizeof sub, fmt, ap);
    va_end(ap);
    int hf = field && *field;
    snprintf(buf, len, "%s%s%s", hf ? field : "", hf && *sub ? "." : "", sub);
    return buf;
}

/* Name of the object itself in messages. */
static const char *nj_self(const char *field, const char *dflt)
{
    return field && *field ? field : dflt;
}

/* A degree: an integer-valued number (range checked by the create functions). */
static c2b_status nj_degree(const cJSON *j, const char *path, const char *what, int *out,
                            c2b_error *err)
{
    if (!cJSON_IsNumber(j) || !isfinite(j->valuedouble) || j->valuedouble != floor(j->valuedouble) ||
        fabs(j->valuedouble) > 1e6)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected %s with integers 1..%d", path, what,
                             C2B_NURBS_MAX_DEGREE);
    *out = (int)j->valuedouble;
    return C2B_OK;
}

/* An array of numbers: count into *n, values into a new array *out. */
static c2b_status nj_numbers(const cJSON *j, const char *path, double **out, int *n, c2b_error *err)
{
    *out = NULL;
    *n = 0;
    if (!cJSON_IsArray(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected an array of numbers", path);
    int cnt = cJSON_GetArraySize(j);
    double *v = malloc((size_t)(cnt > 0 ? cnt : 1) * sizeof *v);
    if (!v)
        return c2b_error_set(err, C2B_ERR_NOMEM, "%s: out of memory", path);
    int i = 0;
    for (const cJSON *x = j->child; x; x = x->next, i++) {
        if (!cJSON_IsNumber(x)) {
            free(v);
            return c2b_error_set(err, C2B_ERR_SPEC, "%s[%d]: expected a number", path, i);
        }
        v[i] = x->valuedouble;
    }
    *out = v;
    *n = cnt;
    return C2B_OK;
}

/* One pole [x, y, z, w] into P[4]. */
static c2b_status nj_pole(const cJSON *j, const char *path, double *P, c2b_error *err)
{
    if (!cJSON_IsArray(j) || cJSON_GetArraySize(j) != 4)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected [x, y, z, w] (4 numbers)", path);
    int i = 0;
    for (const cJSON *x = j->child; x; x = x->next, i++) {
        if (!cJSON_IsNumber(x))
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected [x, y, z, w] (4 numbers)", path);
        P[i] = x->valuedouble;
    }
    return C2B_OK;
}

/* Check a knot count against the degree and pole count. */
static c2b_status nj_knot_count(const char *path, int given, int p, int n, int periodic,
                                c2b_error *err)
{
    if (p < 1 || p > C2B_NURBS_MAX_DEGREE || n < p + 1 || n > C2B_NURBS_MAX_POLES)
        return C2B_OK; /* the create function reports these first, before reading knots */
    int need = periodic ? n + 2 * p + 1 : n + p + 1;
    if (given != need)
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "%s: %d values given, %d needed (%s with n = %d poles, p = %d)", path,
                             given, need, periodic ? "n + 2p + 1 (periodic)" : "n + p + 1", n, p);
    return C2B_OK;
}

/* A periodic flag: true or false. */
static c2b_status nj_bool(const cJSON *j, const char *path, const char *what, int *out,
                          c2b_error *err)
{
    if (!cJSON_IsBool(j))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected %s", path, what);
    *out = cJSON_IsTrue(j) ? 1 : 0;
    return C2B_OK;
}

c2b_status c2b_nurbs_surface_from_json(const cJSON *obj, const char *field,
                                       c2b_nurbs_surface **out, c2b_error *err)
{
    char path[NJ_PATH];
    const char *self = nj_self(field, "surface");
    if (!out)
        return c2b_error_set(err, C2B_ERR_ARG, "%s: NULL output pointer", self);
    *out = NULL;
    static const char *const keys[] = {"degree", "knots_u", "knots_v", "poles", "periodic", NULL};
    const cJSON *it[5];
    c2b_status st = c2b_json_keys(obj, self,
                            "{\"degree\": [p, q], \"knots_u\": [...], \"knots_v\": [...], "
                            "\"poles\": [[[x, y, z, w], ...], ...]}",
                            keys, 4, it, err);
    if (st)
        return st;
    const cJSON *jd = it[0], *jku = it[1], *jkv = it[2], *jp = it[3], *jper = it[4];
    int deg[2] = {0, 0}, per[2] = {0, 0};
    nj_path(path, sizeof path, field, "degree");
    if (!cJSON_IsArray(jd) || cJSON_GetArraySize(jd) != 2)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected [p, q] with integers 1..%d", path,
                             C2B_NURBS_MAX_DEGREE);
    if ((st = nj_degree(jd->child, path, "[p, q]", &deg[0], err)) ||
        (st = nj_degree(jd->child->next, path, "[p, q]", &deg[1], err)))
        return st;
    if (jper) {
        nj_path(path, sizeof path, field, "periodic");
        if (!cJSON_IsArray(jper) || cJSON_GetArraySize(jper) != 2)
            return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected [bool, bool] (u, v)", path);
        if ((st = nj_bool(jper->child, path, "[bool, bool] (u, v)", &per[0], err)) ||
            (st = nj_bool(jper->child->next, path, "[bool, bool] (u, v)", &per[1], err)))
            return st;
    }

    /* poles: nu rows of nv [x, y, z, w] */
    nj_path(path, sizeof path, field, "poles");
    if (!cJSON_IsArray(jp) || cJSON_GetArraySize(jp) < 1)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected rows of [x, y, z, w] (one per u pole)",
                             path);
    int nu = cJSON_GetArraySize(jp);
    if (!cJSON_IsArray(jp->child) || cJSON_GetArraySize(jp->child) < 1)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s[0]: expected rows of [x, y, z, w] (one per v pole)",
                             path);
    int nv = cJSON_GetArraySize(jp->child);
    if (nu > C2B_NURBS_MAX_POLES || nv > C2B_NURBS_MAX_POLES)
        return c2b_error_set(err, C2B_ERR_LIMIT, "%s: %d x %d poles exceed the limit of %d per direction",
                             path, nu, nv, C2B_NURBS_MAX_POLES);
    double *poles = malloc(4 * (size_t)nu * (size_t)nv * sizeof *poles);
    double *ku = NULL, *kv = NULL;
    int nku = 0, nkv = 0;
    if (!poles)
        return c2b_error_set(err, C2B_ERR_NOMEM, "%s: out of memory", path);
    int i = 0;
    for (const cJSON *row = jp->child; row; row = row->next, i++) {
        if (!cJSON_IsArray(row) || cJSON_GetArraySize(row) != nv) {
            char got[32];
            if (cJSON_IsArray(row))
                snprintf(got, sizeof got, "%d", cJSON_GetArraySize(row));
            else
                snprintf(got, sizeof got, "no array");
            st = c2b_error_set(err, C2B_ERR_SPEC,
                               "%s[%d]: expected %d rows of [x, y, z, w] (as in poles[0]), got %s",
                               nj_path(path, sizeof path, field, "poles"), i, nv, got);
            goto done;
        }
        int j = 0;
        for (const cJSON *x = row->child; x; x = x->next, j++) {
            nj_path(path, sizeof path, field, "poles[%d][%d]", i, j);
            if ((st = nj_pole(x, path, poles + 4 * ((size_t)i * (size_t)nv + (size_t)j), err)))
                goto done;
        }
    }
    if ((st = nj_numbers(jku, nj_path(path, sizeof path, field, "knots_u"), &ku, &nku, err)) ||
        (st = nj_knot_count(path, nku, deg[0], nu, per[0], err)))
        goto done;
    if ((st = nj_numbers(jkv, nj_path(path, sizeof path, field, "knots_v"), &kv, &nkv, err)) ||
        (st = nj_knot_count(path, nkv, deg[1], nv, per[1], err)))
        goto done;
    st = c2b_nurbs_surface_create_at(deg[0], deg[1], nu, nv, ku, kv, poles, per, field, out, err);
done:
    free(poles);
    free(ku);
    free(kv);
    return st;
}

c2b_status c2b_nurbs_curve_from_json(const cJSON *obj, const char *field, c2b_nurbs_curve **out,
                                     c2b_error *err)
{
    char path[NJ_PATH];
    const char *self = nj_self(field, "curve");
    if (!out)
        return c2b_error_set(err, C2B_ERR_ARG, "%s: NULL output pointer", self);
    *out = NULL;
    static const char *const keys[] = {"degree", "knots", "poles", "periodic", NULL};
    const cJSON *it[4];
    c2b_status st = c2b_json_keys(obj, self,
                            "{\"degree\": p, \"knots\": [...], \"poles\": [[x, y, z, w], ...]}",
                            keys, 3, it, err);
    if (st)
        return st;
    const cJSON *jd = it[0], *jk = it[1], *jp = it[2], *jper = it[3];
    int p = 0, per = 0;
    if ((st = nj_degree(jd, nj_path(path, sizeof path, field, "degree"), "an integer", &p, err)))
        return st;
    if (jper && (st = nj_bool(jper, nj_path(path, sizeof path, field, "periodic"), "true or false",
                              &per, err)))
        return st;
    nj_path(path, sizeof path, field, "poles");
    if (!cJSON_IsArray(jp) || cJSON_GetArraySize(jp) < 1)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s: expected rows of [x, y, z, w]", path);
    int n = cJSON_GetArraySize(jp);
    if (n > C2B_NURBS_MAX_POLES)
        return c2b_error_set(err, C2B_ERR_LIMIT, "%s: %d poles exceed the limit of %d", path, n,
                             C2B_NURBS_MAX_POLES);
    double *poles = malloc(4 * (size_t)n * sizeof *poles), *kn = NULL;
    int nk = 0;
    if (!poles)
        return c2b_error_set(err, C2B_ERR_NOMEM, "%s: out of memory", path);
    int i = 0;
    for (const cJSON *x = jp->child; x; x = x->next, i++) {
        nj_path(path, sizeof path, field, "poles[%d]", i);
        if ((st = nj_pole(x, path, poles + 4 * (size_t)i, err)))
            goto done;
    }
    if ((st = nj_numbers(jk, nj_path(path, sizeof path, field, "knots"), &kn, &nk, err)) ||
        (st = nj_knot_count(path, nk, p, n, per, err)))
        goto done;
    st = c2b_nurbs_curve_create_at(p, n, kn, poles, per, field, out, err);
done:
    free(poles);
    free(kn);
    return st;
}

/* ---- writers ------------------------------------------------------------------------- */

static cJSON *nj_pole_json(const double *P)
{
    return cJSON_CreateDoubleArray(P, 4);
}

cJSON *c2b_nurbs_surface_to_json(const c2b_nurbs_surface *s)
{
    if (!s)
        return NULL;
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    int deg[2] = {c2b_nurbs_surface_degree(s, 0), c2b_nurbs_surface_degree(s, 1)};
    int nu = c2b_nurbs_surface_npoles(s, 0), nv = c2b_nurbs_surface_npoles(s, 1);
    cJSON *jd = cJSON_CreateIntArray(deg, 2);
    if (!jd || !cJSON_AddItemToObject(o, "degree", jd))
        goto fail_item_d;
    {
        cJSON *ku = cJSON_CreateDoubleArray(c2b_nurbs_surface_knots(s, 0), c2b_nurbs_surface_nknots(s, 0));
        if (!ku || !cJSON_AddItemToObject(o, "knots_u", ku)) {
            cJSON_Delete(ku);
            goto fail;
        }
        cJSON *kv = cJSON_CreateDoubleArray(c2b_nurbs_surface_knots(s, 1), c2b_nurbs_surface_nknots(s, 1));
        if (!kv || !cJSON_AddItemToObject(o, "knots_v", kv)) {
            cJSON_Delete(kv);
            goto fail;
        }
        cJSON *rows = cJSON_CreateArray();
        if (!rows || !cJSON_AddItemToObject(o, "poles", rows)) {
            cJSON_Delete(rows);
            goto fail;
        }
        for (int i = 0; i < nu; i++) {
            cJSON *row = cJSON_CreateArray();
            if (!row || !cJSON_AddItemToArray(rows, row)) {
                cJSON_Delete(row);
                goto fail;
            }
            for (int j = 0; j < nv; j++) {
                double P[4];
                c2b_nurbs_surface_pole(s, i, j, P);
                cJSON *jp = nj_pole_json(P);
                if (!jp || !cJSON_AddItemToArray(row, jp)) {
                    cJSON_Delete(jp);
                    goto fail;
                }
            }
        }
        cJSON *per = cJSON_CreateArray();
        if (!per || !cJSON_AddItemToObject(o, "periodic", per)) {
            cJSON_Delete(per);
            goto fail;
        }
        for (int k = 0; k < 2; k++) {
            cJSON *b = cJSON_CreateBool(c2b_nurbs_surface_periodic(s, k));
            if (!b || !cJSON_AddItemToArray(per, b)) {
                cJSON_Delete(b);
                goto fail;
            }
        }
    }
    return o;
fail_item_d:
    cJSON_Delete(jd);
fail:
    cJSON_Delete(o);
    return NULL;
}

cJSON *c2b_nurbs_curve_to_json(const c2b_nurbs_curve *c)
{
    if (!c)
        return NULL;
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON *jd = cJSON_CreateNumber(c2b_nurbs_curve_degree(c));
    if (!jd || !cJSON_AddItemToObject(o, "degree", jd)) {
        cJSON_Delete(jd);
        goto fail;
    }
    cJSON *kn = cJSON_CreateDoubleArray(c2b_nurbs_curve_knots(c), c2b_nurbs_curve_nknots(c));
    if (!kn || !cJSON_AddItemToObject(o, "knots", kn)) {
        cJSON_Delete(kn);
        goto fail;
    }
    cJSON *rows = cJSON_CreateArray();
    if (!rows || !cJSON_AddItemToObject(o, "poles", rows)) {
        cJSON_Delete(rows);
        goto fail;
    }
    for (int i = 0; i < c2b_nurbs_curve_npoles(c); i++) {
        double P[4];
        c2b_nurbs_curve_pole(c, i, P);
        cJSON *jp = nj_pole_json(P);
        if (!jp || !cJSON_AddItemToArray(rows, jp)) {
            cJSON_Delete(jp);
            goto fail;
        }
    }
    cJSON *per = cJSON_CreateBool(c2b_nurbs_curve_periodic(c));
    if (!per || !cJSON_AddItemToObject(o, "periodic", per)) {
        cJSON_Delete(per);
        goto fail;
    }
    return o;
fail:
    cJSON_Delete(o);
    return NULL;
}

/* ---- exact printer ---------------------------------------------------------------------- */

typedef struct nj_out {
    char *buf;
    size_t len, pos;
} nj_out;

static void nj_put(nj_out *o, const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++, o->pos++)
        if (o->pos + 1 < o->len)
            o->buf[o->pos] = s[i];
}

static void nj_puts(nj_out *o, const char *s) { nj_put(o, s, strlen(s)); }

static void nj_number(nj_out *o, double x)
{
    char b[40];
    if (!isfinite(x)) {
        nj_puts(o, "null");
        return;
    }
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(b, sizeof b, "%.*g", prec, x);
        if (strtod(b, NULL) == x)
            break;
    }
    nj_puts(o, b);
}

static void nj_string(nj_out *o, const char *s)
{
    nj_puts(o, "\"");
    for (const unsigned char *p = (const unsigned char *)(s ? s : ""); *p; p++) {
        char b[8];
        switch (*p) {
        case '"': nj_puts(o, "\\\""); break;
        case '\\': nj_puts(o, "\\\\"); break;
        case '\b': nj_puts(o, "\\b"); break;
        case '\f': nj_puts(o, "\\f"); break;
        case '\n': nj_puts(o, "\\n"); break;
        case '\r': nj_puts(o, "\\r"); break;
        case '\t': nj_puts(o, "\\t"); break;
        default:
            if (*p < 0x20) {
                snprintf(b, sizeof b, "\\u%04x", *p);
                nj_puts(o, b);
            } else {
                nj_put(o, (const char *)p, 1);
            }
        }
    }
    nj_puts(o, "\"");
}

static void nj_indent(nj_out *o, int formatted, int depth)
{
    if (!formatted)
        return;
    nj_puts(o, "\n");
    for (int i = 0; i < depth; i++)
        nj_puts(o, "  ");
}

static void nj_item(nj_out *o, const cJSON *it, int formatted, int depth)
{
    if (!it) {
        nj_puts(o, "null");
        return;
    }
    if (cJSON_IsNumber(it)) {
        nj_number(o, it->valuedouble);
    } else if (cJSON_IsString(it)) {
        nj_string(o, it->valuestring);
    } else if (cJSON_IsTrue(it)) {
        nj_puts(o, "true");
    } else if (cJSON_IsFalse(it)) {
        nj_puts(o, "false");
    } else if (cJSON_IsRaw(it)) {
        nj_puts(o, it->valuestring ? it->valuestring : "");
    } else if (cJSON_IsArray(it) || cJSON_IsObject(it)) {
        int obj = cJSON_IsObject(it);
        /* arrays of scalars stay on one line */
        int flat = !obj;
        for (const cJSON *c = it->child; c && flat; c = c->next)
            if (cJSON_IsArray(c) || cJSON_IsObject(c))
                flat = 0;
        int sub = formatted && !flat;
        nj_puts(o, obj ? "{" : "[");
        for (const cJSON *c = it->child; c; c = c->next) {
            nj_indent(o, sub, depth + 1);
            if (obj) {
                nj_string(o, c->string);
                nj_puts(o, formatted ? ": " : ":");
            }
            nj_item(o, c, formatted, depth + 1);
            if (c->next)
                nj_puts(o, formatted && flat ? ", " : ",");
        }
        if (it->child)
            nj_indent(o, sub, depth);
        nj_puts(o, obj ? "}" : "]");
    } else {
        nj_puts(o, "null");
    }
}

size_t c2b_nurbs_json_print(const cJSON *item, int formatted, char *buf, size_t len)
{
    nj_out o = {buf, buf ? len : 0, 0};
    nj_item(&o, item, formatted, 0);
    if (o.len > 0)
        o.buf[o.pos < o.len ? o.pos : o.len - 1] = '\0';
    return o.pos;
}
