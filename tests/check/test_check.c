/*
 * Continuity report: thesis Table 4 (eqs. 130-131, cylinders of radius 1 and 0.8),
 * the C1 column's qualitative claim, G2 of NURBS and time-dependent blends, and the
 * proof that the check can fail (the C1 blend's curvature jump).
 */
#include <string.h>

#include "c2b_check.h"
#include "test_util.h"

static int run(const char *dir, const char *name, double t, int use_t, c2b_check_side r[2])
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.json", dir, name);
    c2b_spec *s = NULL;
    c2b_blend *b = NULL;
    c2b_error err;
    c2b_problem pb;
    int ok = c2b_spec_load(path, &s, &err) == C2B_OK;
    if (ok) {
        pb = *c2b_spec_problem(s);
        if (use_t)
            pb.time = t;
        ok = c2b_blend_create(&pb, &b, &err) == C2B_OK && c2b_check_run(b, s, NULL, r, &err) == C2B_OK;
    }
    if (!ok)
        printf("     %s: %s\n", name, err.msg);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
    return ok;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 2;
    const char *ex = argv[1];
    c2b_check_side r[2];
    /* Table 4, C2 column: blend = primaries = (1.0, 0.0) at u = 0 and (1.25, 0.0) at u = 1. */
    if (check_true("thesis eqs. 130-131 (C2) checked", run(ex, "thesis_eq130_131", 0, 0, r))) {
        static const double want[2][2] = {{1.0, 0.0}, {1.25, 0.0}};
        for (int side = 0; side < 2; side++) {
            char what[128];
            for (int k = 0; k < 2; k++) {
                snprintf(what, sizeof what, "Table 4 C2: blend u=%d %s", side, k ? "k_min" : "k_max");
                check_close(what, r[side].table_blend[k], want[side][k], 1e-12, 1e-12);
                snprintf(what, sizeof what, "Table 4 C2: primary u=%d %s", side, k ? "k_min" : "k_max");
                check_close(what, r[side].table_primary[k], want[side][k], 1e-12, 1e-12);
            }
            snprintf(what, sizeof what, "C2 blend u=%d: verdict G2 and C2", side);
            check_true(what, !strcmp(r[side].verdict, "G2") && !strcmp(r[side].parametric_verdict, "C2"));
            snprintf(what, sizeof what, "C2 blend u=%d: normal angle (rad)", side);
            check_le(what, r[side].g1.max, 1e-12);
            snprintf(what, sizeof what, "C2 blend u=%d: cross curvature jump (relative)", side);
            check_le(what, r[side].g2_rel.max, 1e-12);
        }
    }
    /* Table 4, C1 column: k_max kept, k_min far from 0: the check detects the jump. */
    if (check_true("thesis eqs. 130-131 (C1) checked", run(ex, "thesis_eq130_131_c1", 0, 0, r))) {
        static const double kmax[2] = {1.0, 1.25};
        for (int side = 0; side < 2; side++) {
            char what[128];
            snprintf(what, sizeof what, "Table 4 C1: blend u=%d keeps k_max", side);
            check_close(what, r[side].table_blend[0], kmax[side], 1e-12, 1e-12);
            snprintf(what, sizeof what, "Table 4 C1: blend u=%d k_min far from 0 (|k_min| > 0.5): %g", side,
                     r[side].table_blend[1]);
            check_true(what, fabs(r[side].table_blend[1]) > 0.5);
            snprintf(what, sizeof what, "C1 blend u=%d: verdict G1 (the check fails G2)", side);
            check_true(what, !strcmp(r[side].verdict, "G1") && !strcmp(r[side].parametric_verdict, "C1"));
        }
    }
    /* NURBS primaries and a time-dependent blend away from its spec time. */
    static const char *const g2[] = {"nurbs_cubic_quartic", "thesis_eq127_129", "thesis_eq134_135",
                                     "thesis_eq132_133"};
    for (int i = 0; i < 4; i++) {
        char what[160];
        snprintf(what, sizeof what, "%s at t=0.7 checked", g2[i]);
        if (!check_true(what, run(ex, g2[i], 0.7, 1, r)))
            continue;
        for (int side = 0; side < 2; side++) {
            snprintf(what, sizeof what, "%s u=%d: verdict %s (g0 %.2g, g1 %.2g rad, g2 %.2g rel)", g2[i], side,
                     r[side].verdict, r[side].g0.max, r[side].g1.max, r[side].g2_rel.max);
            check_true(what, !strcmp(r[side].verdict, "G2"));
        }
    }
    /* Explicit boundary data have no primary surface to compare with. */
    c2b_spec *s = NULL;
    c2b_blend *b = NULL;
    c2b_error err;
    const char *J = "{\"boundary\": {\"u0\": [[\"v\", \"0\", \"0\"], [\"0\", \"0\", \"1\"], [\"0\", \"0\", \"0\"]],"
                    " \"u1\": [[\"v\", \"0\", \"1\"], [\"0\", \"0\", \"1\"], [\"0\", \"0\", \"0\"]]}}";
    c2b_spec_parse(J, strlen(J), &s, &err);
    c2b_blend_create(c2b_spec_problem(s), &b, &err);
    check_true("boundary-data spec: check refuses with a message",
               c2b_check_run(b, s, NULL, r, &err) == C2B_ERR_ARG && strstr(err.msg, "explicit boundary data"));
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
    return test_summary("test_check");
}
