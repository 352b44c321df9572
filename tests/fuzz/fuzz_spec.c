/* libFuzzer target: spec parser + expression front end (libmatheval) + blend creation.
 * Input: JSON text of a spec (README.md, "Spec format"). Every input must either be
 * rejected with a status and a message, or give a blend that evaluates finitely sized
 * output; a crash, a sanitizer report or a leak is a bug. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "c2b_blend.h"
#include "c2b_spec.h"

/* Keep single executions short: large specs only repeat what small ones test. */
#define FUZZ_MAX_BYTES 16384
#define FUZZ_MAX_SAMPLES 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > FUZZ_MAX_BYTES)
        return 0;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_spec *spec = NULL;
    if (c2b_spec_parse((const char *)data, size, &spec, &err) != C2B_OK) {
        if (spec || !err.msg[0])
            __builtin_trap(); /* a failure must leave no object and must say why */
        return 0;
    }
    c2b_problem pb = *c2b_spec_problem(spec);
    /* Fewer samples per projection keep one execution well under a second under the
     * sanitizers; the limits and error paths stay the same. */
    if (pb.tol.max_samples > FUZZ_MAX_SAMPLES)
        pb.tol.max_samples = FUZZ_MAX_SAMPLES;
    c2b_blend *b = NULL;
    if (c2b_blend_create(&pb, &b, &err) == C2B_OK) {
        double u[3] = {0.0, 0.5, 1.0}, v[3];
        c2b_vdomain dom = c2b_blend_domain(b);
        for (int i = 0; i < 3; i++)
            v[i] = dom.v0 + 0.5 * i * (dom.v1 - dom.v0);
        double out[3 * 3 * 10 * 3];
        (void)c2b_blend_eval_grid(b, 3, u, 3, v, 3, out, &err);
        double res[8], scale[8];
        (void)c2b_blend_boundary_residual(b, 5, res, scale, &err);
        char info[256];
        size_t need = 0;
        (void)c2b_blend_info_json(b, info, sizeof info, &need, &err);
        if (c2b_spec_has_primaries(spec)) {
            double d[18];
            (void)c2b_spec_primary_eval(spec, 0, -0.1, v[1], pb.time, 2, d, &err);
            (void)c2b_spec_primary_eval(spec, 1, 1.1, v[1], pb.time, 2, d, &err);
        }
        c2b_blend_destroy(b);
    } else if (b || !err.msg[0]) {
        __builtin_trap();
    }
    c2b_spec_destroy(spec);
    return 0;
}
