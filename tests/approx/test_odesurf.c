/* Seed 000 ODE surfaces: control curves (eqs. 3-7), w-multiples (eq. 24), the ODE itself
 * against the collocation oracle, and the patch-to-patch C2 joins of section 5. */
#include <math.h>
#include <string.h>

#include "c2b_blend.h"
#include "c2b_constants.h"
#include "c2b_odesurf.h"
#include "cheb_bvp.h"
#include "test_util.h"

/* reference surface P(u, v), sampled at fixed u to make curves */
static double P(int c, double u, double v)
{
    double w = 2 * C2B_PI * v;
    switch (c) {
    case 0: return cos(w) * (1 + 0.3 * u + 0.2 * u * u) + 0.1 * u * u * u;
    case 1: return sin(w) * (1 + 0.5 * u) - 0.2 * u * u;
    default: return 2 * u - u * u * u + 0.1 * sin(w);
    }
}
typedef struct at { int c; double u; } at;
static at ats[8][3];
static double pfn(void *ctx, double v, double t)
{
    (void)t;
    const at *a = ctx;
    return P(a->c, a->u, v);
}
static c2b_curve curve_at(int slot, double u)
{
    c2b_curve k;
    memset(&k, 0, sizeof k);
    for (int c = 0; c < 3; c++) {
        ats[slot][c].c = c, ats[slot][c].u = u;
        k.fn[c] = pfn, k.ctx[c] = &ats[slot][c];
    }
    return k;
}

/* a second family for the v-join: f(v) + kappa (v - 1)^3 on the second patch */
typedef struct vcurve { int c; double u, kappa; } vcurve;
static double vfn(void *ctx, double v, double t)
{
    (void)t;
    const vcurve *k = ctx;
    double s = v - 1;
    return 0.4 * sin(1.3 * v + k->c) * (1 + k->u) + k->u * v * v + k->kappa * s * s * s;
}

#define NV 41

static c2b_blend *make(c2b_odesurf **os, const c2b_odesurf_input *in)
{
    c2b_error err;
    c2b_blend *b = NULL;
    if (c2b_odesurf_create(in, os, &err) || c2b_blend_create(c2b_odesurf_problem(*os), &b, &err)) {
        printf("  %s\n", err.msg);
        return NULL;
    }
    return b;
}

int main(void)
{
    c2b_error err;
    /* ---- approach 2: control curves ---- */
    c2b_odesurf_input in;
    memset(&in, 0, sizeof in);
    in.approach = C2B_ODESURF_CONTROLS;
    in.c1 = curve_at(0, 0), in.c4 = curve_at(1, 1);
    double uc[4] = {0.1, 0.2, 0.8, 0.9};
    for (int k = 0; k < 4; k++)
        in.control[k] = curve_at(2 + k, uc[k]), in.uc[k] = uc[k];
    in.shape[0] = 1, in.shape[1] = 3, in.shape[2] = 1; /* seed 000 fig. 4b */
    in.dom.v0 = 0, in.dom.v1 = 1, in.dom.periodic = 1;
    c2b_odesurf *os = NULL;
    c2b_blend *b = make(&os, &in);
    if (!check_true("ODE surface with four control curves", b != NULL))
        return 1;
    double v[NV], ub[2] = {0, 1}, d[2 * NV * 6 * 3];
    for (int j = 0; j < NV; j++)
        v[j] = (double)j / (NV - 1);
    c2b_blend_eval_grid(b, 2, ub, NV, v, 2, d, &err);
    double worst[6] = {0};
    for (int j = 0; j < NV; j++)
        for (int c = 0; c < 3; c++) {
            /* eqs. 3-7 written out from the reference surface */
            double c1 = P(c, 0, v[j]), c4 = P(c, 1, v[j]);
            double b2 = P(c, .1, v[j]), b3 = P(c, .2, v[j]), b5 = P(c, .8, v[j]), b6 = P(c, .9, v[j]);
            double want[6] = {c1, (b2 - c1) / .1, (.1 * b3 - .2 * b2 + .1 * c1) / (.01 * .1), c4,
                              (c4 - b6) / .1, (.1 * c4 + .1 * b5 - .2 * b6) / (.01 * .1)};
            static const int ent[3] = {0, 1, 3};
            for (int l = 0; l < 6; l++) {
                double got = d[(((l / 3) * NV + j) * 6 + ent[l % 3]) * 3 + c];
                worst[l] = fmax(worst[l], fabs(got - want[l]) / fmax(1, fabs(want[l])));
            }
        }
    static const char *lab[6] = {"S(0,v) = c1", "S_u(0,v) = eq. 3", "S_uu(0,v) = eq. 4",
                                 "S(1,v) = c4", "S_u(1,v) = eq. 5", "S_uu(1,v) = eq. 6"};
    for (int l = 0; l < 6; l++)
        check_le(lab[l], worst[l], 1e-12);
    /* every u-curve solves eq. 2: compare with the Chebyshev collocation oracle at v = 0.3 */
    {
        double vv = 0.3, us[11], s[11 * 3], cc[4] = {in.shape[0], in.shape[1], in.shape[2], 0}, g[11 * 4], e = 0;
        for (int i = 0; i < 11; i++)
            us[i] = i / 10.0;
        c2b_blend_eval_grid(b, 11, us, 1, &vv, 0, s, &err);
        for (int c = 0; c < 3; c++) {
            double c1 = P(c, 0, vv), c4 = P(c, 1, vv), b2 = P(c, .1, vv), b3 = P(c, .2, vv), b5 = P(c, .8, vv),
                   b6 = P(c, .9, vv);
            double dd[6] = {c1, (b2 - c1) / .1, (.1 * b3 - .2 * b2 + .1 * c1) / (.001), c4, (c4 - b6) / .1,
                            (.1 * c4 + .1 * b5 - .2 * b6) / (.001)};
            if (oracle_cheb_bvp(3, cc, -1, NULL, dd, 0, 11, us, g, NULL))
                return 1;
            for (int i = 0; i < 11; i++)
                e = fmax(e, fabs(s[3 * i + c] - g[4 * i]));
        }
        check_le("u-curves solve rho S6 + eta S4 + lambda S2 = 0 (oracle, v = 0.3)", e, 1e-10);
    }
    /* eq. 3's error against the true P_u(0, v) is the forward-difference error, here
     * 0.2 cos(2 pi v) h + 0.1 h^2 for the x component: first order in h */
    {
        double errs[2], want[2];
        for (int k = 0; k < 2; k++) {
            double h = k ? 0.025 : 0.05;
            c2b_odesurf_input in2 = in;
            double u2[4] = {h, 2 * h, 1 - 2 * h, 1 - h};
            for (int q = 0; q < 4; q++)
                in2.control[q] = curve_at(2 + q, u2[q]), in2.uc[q] = u2[q];
            c2b_odesurf *o2 = NULL;
            c2b_blend *b2 = make(&o2, &in2);
            double dd[2 * 6 * 3], vv = 0.3;
            c2b_blend_eval_grid(b2, 2, ub, 1, &vv, 2, dd, &err);
            /* exact P_u(0, v) of the x component: 0.3 cos(2 pi v) */
            errs[k] = dd[1 * 3 + 0] - 0.3 * cos(2 * C2B_PI * vv);
            want[k] = 0.2 * cos(2 * C2B_PI * vv) * h + 0.1 * h * h;
            c2b_blend_destroy(b2);
            c2b_odesurf_destroy(o2);
        }
        check_close("eq. 3 error at h = 0.05 is the forward-difference error", errs[0], want[0], 1e-10, 1e-13);
        check_close("eq. 3 error at h = 0.025 is the forward-difference error", errs[1], want[1], 1e-10, 1e-13);
    }
    c2b_blend_destroy(b);
    c2b_odesurf_destroy(os);

    /* ---- approach 1 and the u-join (section 5.1, eqs. 23-25) ---- */
    c2b_odesurf_input A;
    memset(&A, 0, sizeof A);
    A.approach = C2B_ODESURF_MULTIPLES;
    A.c1 = curve_at(0, 0), A.c4 = curve_at(1, 1);
    double wA[4] = {0.5, -1.0, 0.8, 2.0};
    memcpy(A.w, wA, sizeof wA);
    A.shape[0] = 1, A.shape[1] = 1, A.shape[2] = 1;
    A.dom = in.dom;
    c2b_odesurf_input B = A;
    B.c1 = A.c4, B.c4 = curve_at(6, 2.0);
    B.w[0] = A.w[2], B.w[1] = A.w[3], B.w[2] = -0.3, B.w[3] = 1.5;
    B.shape[0] = 0.1, B.shape[1] = 0.1, B.shape[2] = 3; /* different shape, as in fig. 6b */
    c2b_odesurf *oa = NULL, *ob = NULL;
    c2b_blend *ba = make(&oa, &A), *bb = make(&ob, &B);
    if (!check_true("two patches, approach 1", ba && bb))
        return 1;
    double da[NV * 6 * 3], db[NV * 6 * 3], one = 1, zero = 0, ju[3] = {0};
    c2b_blend_eval_grid(ba, 1, &one, NV, v, 2, da, &err);
    c2b_blend_eval_grid(bb, 1, &zero, NV, v, 2, db, &err);
    double w1 = 0;
    for (int j = 0; j < NV; j++)
        for (int c = 0; c < 3; c++) {
            static const int ent[3] = {0, 1, 3};
            for (int p = 0; p < 3; p++)
                ju[p] = fmax(ju[p], fabs(da[(j * 6 + ent[p]) * 3 + c] - db[(j * 6 + ent[p]) * 3 + c]));
            /* eq. 24: S_u(0, v) = w1 c1(v) on patch A */
            w1 = fmax(w1, 0);
        }
    check_le("u-join: S equal across the shared curve", ju[0], 1e-12);
    check_le("u-join: S_u equal (C1)", ju[1], 1e-12);
    check_le("u-join: S_uu equal (C2)", ju[2], 1e-12);
    {
        double d0[NV * 6 * 3], e = 0;
        c2b_blend_eval_grid(ba, 1, &zero, NV, v, 2, d0, &err);
        for (int j = 0; j < NV; j++)
            for (int c = 0; c < 3; c++) {
                e = fmax(e, fabs(d0[(j * 6 + 1) * 3 + c] - wA[0] * P(c, 0, v[j])));
                e = fmax(e, fabs(d0[(j * 6 + 3) * 3 + c] - wA[1] * P(c, 0, v[j])));
            }
        check_le("eq. 24: S_u(0,v) = w1 c1, S_uu(0,v) = w2 c1", e, 1e-12);
    }
    c2b_blend_destroy(ba);
    c2b_blend_destroy(bb);
    c2b_odesurf_destroy(oa);
    c2b_odesurf_destroy(ob);

    /* ---- the v-join (section 5.2): patch A on v in [0, 1], patch B on [1, 2]; B's curves
     * agree with A's up to the second v-derivative at v = 1 (they differ by kappa (v-1)^3) ---- */
    for (int same = 1; same >= 0; same--) {
        static vcurve vc[2][2][3];
        c2b_odesurf_input P2[2];
        for (int pt = 0; pt < 2; pt++) {
            memset(&P2[pt], 0, sizeof P2[pt]);
            P2[pt].approach = C2B_ODESURF_MULTIPLES;
            for (int side = 0; side < 2; side++)
                for (int c = 0; c < 3; c++) {
                    vc[pt][side][c].c = c, vc[pt][side][c].u = side, vc[pt][side][c].kappa = pt ? 0.7 : 0;
                    c2b_curve *k = side ? &P2[pt].c4 : &P2[pt].c1;
                    k->fn[c] = vfn, k->ctx[c] = &vc[pt][side][c];
                }
            double w[4] = {0.5, -1.0, 0.8, 2.0};
            memcpy(P2[pt].w, w, sizeof w);
            P2[pt].shape[0] = 1, P2[pt].shape[1] = 1, P2[pt].shape[2] = 1;
            if (pt && !same)
                P2[pt].shape[1] = 4; /* xi differ: the join must fail */
            P2[pt].dom.v0 = pt, P2[pt].dom.v1 = pt + 1, P2[pt].dom.periodic = 0;
        }
        c2b_odesurf *o0 = NULL, *o1 = NULL;
        c2b_blend *b0 = make(&o0, &P2[0]), *b1 = make(&o1, &P2[1]);
        if (!check_true("two patches side by side in v", b0 && b1))
            return 1;
        double us[11], e0[11 * 6 * 3], e1[11 * 6 * 3], jv[3] = {0}, vj = 1.0;
        for (int i = 0; i < 11; i++)
            us[i] = i / 10.0;
        c2b_blend_eval_grid(b0, 11, us, 1, &vj, 2, e0, &err);
        c2b_blend_eval_grid(b1, 11, us, 1, &vj, 2, e1, &err);
        static const int ent[3] = {0, 2, 5}; /* S, S_v, S_vv */
        for (int i = 0; i < 11; i++)
            for (int c = 0; c < 3; c++)
                for (int p = 0; p < 3; p++)
                    jv[p] = fmax(jv[p], fabs(e0[(i * 6 + ent[p]) * 3 + c] - e1[(i * 6 + ent[p]) * 3 + c]));
        if (same) {
            check_le("v-join, equal shape: S equal along v = 1", jv[0], 1e-10);
            /* exact in the paper's analytic form (eq. 26); here S_v and S_vv at the end
             * of an open v-range carry the truncation of the kernel's end polynomial +
             * sine series (5e-11 and 1.1e-9; 1.3e-9 and 2.9e-6 while the end polynomial
             * was a cubic) */
            check_le("v-join, equal shape: S_v equal (C1)", jv[1], 1e-9);
            check_le("v-join, equal shape: S_vv equal (C2)", jv[2], 1e-8);
        } else {
            printf("  v-join with different eta: |dS| %.3g |dS_v| %.3g |dS_vv| %.3g\n", jv[0], jv[1], jv[2]);
            check_le("v-join, different eta: S_vv differs (section 5.2 needs equal xi)", 1e-4, jv[2]);
        }
        c2b_blend_destroy(b0);
        c2b_blend_destroy(b1);
        c2b_odesurf_destroy(o0);
        c2b_odesurf_destroy(o1);
    }
    /* bad input names the field */
    in.uc[1] = 0.05;
    check_true("u3 < u2 rejected naming controls[1].u",
               c2b_odesurf_create(&in, &os, &err) == C2B_ERR_SPEC && strstr(err.msg, "controls[1].u"));
    return test_summary("test_odesurf");
}
