/* libFuzzer target: the sampled-data path (boundary {"samples": ...} rows).
 * Input bytes: [continuity][flags][n][shape bytes x 5] then raw doubles, used as the
 * samples of every boundary datum (x, y, z interleaved, stride 3), NaN and Inf included.
 * Builds the problem directly (as c2b_spec.c does for sample rows), creates the blend
 * (c2b_vseries_project_samples: FFT or end polynomial + DST, leave-half-out error) and evaluates. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_blend.h"
#include "c2b_problem.h"

#define FUZZ_MAX_SAMPLES 128 /* more samples only add modes: slower, not new paths */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 8)
        return 0;
    c2b_problem pb = c2b_problem_default();
    static const c2b_continuity conts[4] = {C2B_C1, C2B_C2, C2B_C3, C2B_ODE};
    pb.continuity = conts[data[0] & 3];
    int flags = data[1];
    pb.dom.periodic = flags & 1;
    pb.dom.v0 = 0.0;
    pb.dom.v1 = (flags & 2) ? 6.283185307179586 : 1.0;
    int n = 1 + data[2] % FUZZ_MAX_SAMPLES; /* samples per datum (may be too few) */
    int ns = c2b_continuity_nshape(pb.continuity);
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int k = 0; k < ns && k < 5; k++) {
            int8_t s = (int8_t)data[3 + k];
            /* mostly positive parameters, sometimes zero or negative (resonance) */
            pb.shape[c][k] = (flags & 4) ? s / 16.0 : 0.25 + (uint8_t)s / 32.0;
        }
    data += 8;
    size -= 8;
    size_t nd = size / sizeof(double);
    if (nd == 0)
        return 0;
    int nc = c2b_continuity_n(pb.continuity);
    size_t total = (size_t)n * 3;
    double *buf = malloc(total * sizeof *buf);
    if (!buf)
        return 0;
    for (size_t i = 0; i < total; i++) /* repeat the input to fill every sample */
        memcpy(&buf[i], data + (i % nd) * sizeof(double), sizeof(double));
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int side = 0; side < 2; side++)
            for (int p = 0; p < nc; p++) {
                c2b_bfunc *bf = &pb.data[c][side][p];
                bf->samples = buf + c;
                bf->n_samples = n;
                bf->stride = 3;
                bf->label = "fuzz.samples";
            }
    c2b_error err;
    c2b_error_clear(&err);
    c2b_blend *b = NULL;
    if (c2b_blend_create(&pb, &b, &err) == C2B_OK) {
        double u[3] = {0.0, 0.5, 1.0}, v[3];
        for (int i = 0; i < 3; i++)
            v[i] = pb.dom.v0 + 0.5 * i * (pb.dom.v1 - pb.dom.v0);
        double out[3 * 3 * 10 * 3];
        (void)c2b_blend_eval_grid(b, 3, u, 3, v, 3, out, &err);
        double res[8], scale[8];
        (void)c2b_blend_boundary_residual(b, 5, res, scale, &err);
        c2b_blend_destroy(b);
    } else if (b || !err.msg[0]) {
        __builtin_trap();
    }
    free(buf);
    return 0;
}
