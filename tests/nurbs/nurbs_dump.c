/*
 * nurbs_dump: evaluate NURBS given as JSON and print every derivative, for the
 * cross-check against OpenCASCADE (test_occt.py).
 *
 * Input (file named by argv[1]), one of
 *   {"surface": {...}, "params": [[u, v], ...], "du": 3, "dv": 3, "ops": [...]}
 *   {"curve": {...}, "params": [t, ...], "d": 3, "ops": [...]}
 * "ops" (optional) is applied first: {"insert": [dir, t, times]} or {"elevate": [dir, times]}
 * (dir ignored for curves).
 * Output (stdout): {"derivs": [[[x, y, z], ...], ...], "result": {...}}: per parameter the
 * table SKL[a][b] at index a * (dv + 1) + b (curves: C^(k) at index k), each number with
 * %.17g; "result" is the (modified) object in the c2b_nurbs_json format.
 * Exit 0 on success, 2 with a message on stderr on failure.
 */
#include <stdio.h>
#include <stdlib.h>

#include "c2b_nurbs.h"
#include "c2b_nurbs_json.h"

static int fail(const char *what, const c2b_error *err)
{
    fprintf(stderr, "nurbs_dump: %s%s%s\n", what, err ? ": " : "", err ? err->msg : "");
    return 2;
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    while (buf) {
        size_t got = fread(buf + len, 1, cap - len - 1, f);
        len += got;
        if (got == 0)
            break;
        if (len + 1 == cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    fclose(f);
    if (buf)
        buf[len] = '\0';
    return buf;
}

static int get_int(const cJSON *o, const char *key, int dflt)
{
    const cJSON *j = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsNumber(j) ? (int)j->valuedouble : dflt;
}

static void print_vec(const double *v, int first)
{
    printf("%s[%.17g, %.17g, %.17g]", first ? "" : ", ", v[0], v[1], v[2]);
}

static int apply_ops(const cJSON *ops, c2b_nurbs_surface *s, c2b_nurbs_curve *c, c2b_error *err)
{
    for (const cJSON *op = ops ? ops->child : NULL; op; op = op->next) {
        const cJSON *ins = cJSON_GetObjectItemCaseSensitive(op, "insert");
        const cJSON *ele = cJSON_GetObjectItemCaseSensitive(op, "elevate");
        c2b_status st;
        if (cJSON_GetArraySize(ins) == 3) {
            int dir = (int)cJSON_GetArrayItem(ins, 0)->valuedouble;
            double t = cJSON_GetArrayItem(ins, 1)->valuedouble;
            int times = (int)cJSON_GetArrayItem(ins, 2)->valuedouble;
            st = s ? c2b_nurbs_surface_insert_knot(s, dir, t, times, err)
                   : c2b_nurbs_curve_insert_knot(c, t, times, err);
        } else if (cJSON_GetArraySize(ele) == 2) {
            int dir = (int)cJSON_GetArrayItem(ele, 0)->valuedouble;
            int times = (int)cJSON_GetArrayItem(ele, 1)->valuedouble;
            st = s ? c2b_nurbs_surface_elevate(s, dir, times, err)
                   : c2b_nurbs_curve_elevate(c, times, err);
        } else {
            return fail("bad op", NULL);
        }
        if (st)
            return fail("op failed", err);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: nurbs_dump input.json\n");
        return 2;
    }
    char *text = read_file(argv[1]);
    if (!text)
        return fail("cannot read the input file", NULL);
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (!root)
        return fail("malformed JSON", NULL);
    c2b_error err;
    c2b_error_clear(&err);
    c2b_nurbs_surface *s = NULL;
    c2b_nurbs_curve *c = NULL;
    const cJSON *js = cJSON_GetObjectItemCaseSensitive(root, "surface");
    const cJSON *jc = cJSON_GetObjectItemCaseSensitive(root, "curve");
    int rc = 0;
    if (js ? c2b_nurbs_surface_from_json(js, "surface", &s, &err)
           : c2b_nurbs_curve_from_json(jc, "curve", &c, &err)) {
        rc = fail("invalid input", &err);
        goto done;
    }
    if ((rc = apply_ops(cJSON_GetObjectItemCaseSensitive(root, "ops"), s, c, &err)))
        goto done;
    int du = get_int(root, "du", 0), dv = get_int(root, "dv", 0), d = get_int(root, "d", 0);
    const cJSON *params = cJSON_GetObjectItemCaseSensitive(root, "params");
    printf("{\"derivs\": [");
    int first = 1;
    for (const cJSON *pp = params ? params->child : NULL; pp; pp = pp->next) {
        double buf[(C2B_NURBS_MAX_DERIV + 1) * (C2B_NURBS_MAX_DERIV + 1) * 3];
        int cnt;
        c2b_status st;
        if (s) {
            st = c2b_nurbs_surface_derivs(s, cJSON_GetArrayItem(pp, 0)->valuedouble,
                                          cJSON_GetArrayItem(pp, 1)->valuedouble, du, dv, buf, &err);
            cnt = (du + 1) * (dv + 1);
        } else {
            st = c2b_nurbs_curve_eval(c, pp->valuedouble, d, buf, &err);
            cnt = d + 1;
        }
        if (st) {
            printf("]}\n");
            rc = fail("evaluation failed", &err);
            goto done;
        }
        printf("%s[", first ? "" : ",\n ");
        for (int k = 0; k < cnt; k++)
            print_vec(buf + 3 * k, k == 0);
        printf("]");
        first = 0;
    }
    cJSON *res = s ? c2b_nurbs_surface_to_json(s) : c2b_nurbs_curve_to_json(c);
    char *out = res ? cJSON_PrintUnformatted(res) : NULL;
    printf("],\n \"result\": %s}\n", out ? out : "null");
    free(out);
    cJSON_Delete(res);
done:
    c2b_nurbs_surface_destroy(s);
    c2b_nurbs_curve_destroy(c);
    cJSON_Delete(root);
    return rc;
}
