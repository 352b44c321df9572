/* libFuzzer target: the NURBS JSON reader (c2b_nurbs_json.h), surfaces and curves, and
 * what a reader's result is used for next: evaluation with derivatives, the JSON writer
 * and the exact printer. Input: JSON text of one NURBS object. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "c2b_nurbs.h"
#include "c2b_nurbs_json.h"

#define FUZZ_MAX_BYTES 16384

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void use_surface(const c2b_nurbs_surface *s)
{
    double dom[4];
    c2b_nurbs_surface_domain(s, dom);
    double out[10 * 3];
    for (int i = 0; i <= 4; i++) {
        double u = dom[0] + 0.25 * i * (dom[1] - dom[0]);
        double v = dom[2] + 0.25 * i * (dom[3] - dom[2]);
        (void)c2b_nurbs_surface_eval(s, u, v, 3, out, NULL);
    }
    cJSON *j = c2b_nurbs_surface_to_json(s);
    if (j) {
        size_t need = c2b_nurbs_json_print(j, 0, NULL, 0);
        char *buf = malloc(need + 1);
        if (buf) {
            c2b_nurbs_json_print(j, 1, buf, need + 1);
            free(buf);
        }
        cJSON_Delete(j);
    }
}

static void use_curve(const c2b_nurbs_curve *c)
{
    double t0, t1, out[4 * 3];
    c2b_nurbs_curve_domain(c, &t0, &t1);
    for (int i = 0; i <= 4; i++)
        (void)c2b_nurbs_curve_eval(c, t0 + 0.25 * i * (t1 - t0), 3, out, NULL);
    cJSON *j = c2b_nurbs_curve_to_json(c);
    cJSON_Delete(j);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > FUZZ_MAX_BYTES)
        return 0;
    cJSON *root = cJSON_ParseWithLength((const char *)data, size);
    if (!root)
        return 0;
    /* the reader is also reached through specs: {"nurbs": {...}} inside primaries */
    const cJSON *obj = cJSON_GetObjectItemCaseSensitive(root, "nurbs");
    if (!obj)
        obj = root;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_nurbs_surface *s = NULL;
    if (c2b_nurbs_surface_from_json(obj, "nurbs", &s, &err) == C2B_OK) {
        use_surface(s);
        c2b_nurbs_surface_destroy(s);
    } else if (s || !err.msg[0]) {
        __builtin_trap();
    }
    c2b_nurbs_curve *c = NULL;
    if (c2b_nurbs_curve_from_json(obj, "curve", &c, &err) == C2B_OK) {
        use_curve(c);
        c2b_nurbs_curve_destroy(c);
    } else if (c) {
        __builtin_trap();
    }
    cJSON_Delete(root);
    return 0;
}
