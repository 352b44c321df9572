/*
 * Blend tests. Independent evidence only:
 *  - boundary constraints against hand-derived primary derivatives;
 *  - the PDE residual from finite differences (Richardson-extrapolated) of the
 *    evaluated third derivatives;
 *  - the ODE class against per-v collocation (tests/oracle);
 *  - sampled vs analytic data, time invariance, thesis Figure 2's qualitative sequence.
 */
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "c2b_blend.h"
#include "c2b_constants.h"
#include "c2b_spec.h"
#include "cheb_bvp.h"
#include "test_util.h"

static c2b_spec *spec_from(const char *json)
{
    c2b_spec *s = NULL;
    c2b_error err;
    if (c2b_spec_parse(json, strlen(json), &s, &err)) {
        printf("spec error: %s\n", err.msg);
        return NULL;
    }
    return s;
}

static c2b_blend *blend_from(const c2b_spec *s, double t)
{
    c2b_problem pb = *c2b_spec_problem(s);
    pb.time = t;
    c2b_blend *b = NULL;
    c2b_error err;
    if (c2b_blend_create(&pb, &b, &err))
        printf("blend error: %s\n", err.msg);
    return b;
}

/* Parse, build at time t and report; on failure the spec is freed and NULL returned. */
static c2b_blend *open_blend(const char *json, double t, const char *what, c2b_spec **spec)
{
    *spec = spec_from(json);
    c2b_blend *b = *spec ? blend_from(*spec, t) : NULL;
    if (!check_true(what, b != NULL)) {
        c2b_spec_destroy(*spec);
        *spec = NULL;
    }
    return b;
}


/* All 10 derivative entries at one point. */
static void eval10(const c2b_blend *b, double u, double v, double *o)
{
    c2b_blend_eval(b, 1, &u, &v, 3, o, NULL);
}

/* Third-order central difference of entry e along u (dir 0) or v (dir 1). */
static double d3(const c2b_blend *b, double u, double v, int e, int c, int dir, double h)
{
    static const double w[4] = {-0.5, 1.0, -1.0, 0.5};
    static const double off[4] = {-2, -1, 1, 2};
    double s = 0, o[30];
    for (int k = 0; k < 4; k++) {
        eval10(b, u + (dir == 0 ? off[k] * h : 0), v + (dir == 1 ? off[k] * h : 0), o);
        s += w[k] * o[e * 3 + c];
    }
    return s / (h * h * h);
}

/* d3 with one Richardson step: error O(h^4). */
static double d3r(const c2b_blend *b, double u, double v, int e, int c, int dir, double h)
{
    return (4 * d3(b, u, v, e, c, dir, h / 2) - d3(b, u, v, e, c, dir, h)) / 3;
}

/* C2 residual gamma S_u6 + eta S_u4v2 + lambda S_u2v4 + rho S_v6 - F at (u, v), worst
 * component, relative to the largest term over all components (a component whose
 * terms vanish exactly only contributes rounding noise). Entries: Suuu=6, Suuv=7,
 * Suvv=8, Svvv=9. */
static double c2_residual(const c2b_blend *b, const double *shape, double u, double v,
                          const double *F, double h)
{
    double sum[3], big = 0;
    for (int c = 0; c < 3; c++) {
        double t0 = shape[0] * d3r(b, u, v, 6, c, 0, h); /* d^3/du^3 S_uuu */
        double t1 = shape[1] * d3r(b, u, v, 8, c, 0, h); /* d^3/du^3 S_uvv = S_u4v2 */
        double t2 = shape[2] * d3r(b, u, v, 7, c, 1, h); /* d^3/dv^3 S_uuv = S_u2v4 */
        double t3 = shape[3] * d3r(b, u, v, 9, c, 1, h); /* d^3/dv^3 S_vvv */
        double f = F ? F[c] : 0.0;
        sum[c] = t0 + t1 + t2 + t3 - f;
        big = fmax(big, fmax(fmax(fabs(t0), fabs(t1)), fmax(fabs(t2), fabs(t3))));
        big = fmax(big, fabs(f));
    }
    double worst = 0;
    for (int c = 0; c < 3; c++)
        worst = fmax(worst, fabs(sum[c]));
    return big > 0 ? worst / big : 0.0;
}

static const char *THESIS_EQ2_4 =
    "{\"continuity\": \"C2\", \"shape\": [1, 1, 1, 1], \"v_range\": [0, 1], \"periodic\": true,"
    " \"constants\": {\"a\": 1.6, \"b\": 1.0, \"c\": 0.8, \"d\": 0.6, \"h1\": 2.0, \"h2\": 3.0, \"h3\": 5.0},"
    " \"primaries\": ["
    "  {\"surface\": [\"a*exp(t)*sin(2*pi*v)\", \"b*exp(-t)*cos(2*pi*v)\", \"h1+h2*u^2\"], \"trim_u\": 0.2, \"direction\": -1},"
    "  {\"surface\": [\"c*exp(-t)*sin(2*pi*v)\", \"d*exp(t)*cos(2*pi*v)\", \"-h3*u^3\"], \"trim_u\": 0.3, \"direction\": 1}]}";

/* Thesis eq. (4): the boundary constraints of the eq. (2)-(3) example. */
static void test_thesis_eq4(void)
{
    c2b_spec *s = spec_from(THESIS_EQ2_4);
    if (!check_true("thesis eq. 2-4 spec parses", s != NULL))
        return;
    const double a = 1.6, bb = 1.0, c = 0.8, d = 0.6, h1 = 2, h2 = 3, h3 = 5;
    for (int ti = 0; ti < 2; ti++) {
        double t = ti ? 0.3 : 0.0;
        c2b_blend *b = blend_from(s, t);
        if (!check_true("blend created", b != NULL))
            continue;
        for (int k = 0; k < 7; k++) {
            double v = k / 7.0 + 0.03, sv = sin(2 * C2B_PI * v), cv = cos(2 * C2B_PI * v);
            double o0[30], o1[30];
            eval10(b, 0.0, v, o0);
            eval10(b, 1.0, v, o1);
            /* u = 0: [a e^t sin, b e^-t cos, h1 + 0.04 h2], S_u = [0, 0, -0.4 h2], S_uu = [0, 0, 2 h2] */
            double want0[3][3] = {{a * exp(t) * sv, bb * exp(-t) * cv, h1 + 0.04 * h2},
                                  {0, 0, -0.4 * h2}, {0, 0, 2 * h2}};
            double want1[3][3] = {{c * exp(-t) * sv, d * exp(t) * cv, -0.027 * h3},
                                  {0, 0, -0.27 * h3}, {0, 0, -1.8 * h3}};
            static const int entry[3] = {0, 1, 3}; /* S, S_u, S_uu */
            for (int p = 0; p < 3; p++)
                for (int cc = 0; cc < 3; cc++) {
                    char what[128];
                    snprintf(what, sizeof what, "eq.4 t=%g v=%.3f u=0 d^%d/du^%d %c", t, v, p, p, "xyz"[cc]);
                    check_close(what, o0[entry[p] * 3 + cc], want0[p][cc], 1e-12, 1e-12 * 10);
                    snprintf(what, sizeof what, "eq.4 t=%g v=%.3f u=1 d^%d/du^%d %c", t, v, p, p, "xyz"[cc]);
                    check_close(what, o1[entry[p] * 3 + cc], want1[p][cc], 1e-12, 1e-12 * 10);
                }
        }
        /* PDE residual in the interior. */
        double shape[4] = {1, 1, 1, 1}, worst = 0;
        for (int k = 0; k < 5; k++)
            worst = fmax(worst, c2_residual(b, shape, 0.15 + 0.17 * k, 0.11 + 0.19 * k, NULL, 2e-3));
        check_le("eq.2-4 PDE residual (finite differences, relative)", worst, 1e-6);
        c2b_blend_destroy(b);
    }
    c2b_spec_destroy(s);
}

/* Time: a moved frame equals a fresh blend at that time; static primaries give
 * bit-identical surfaces at every t. */
static void test_time(void)
{
    c2b_spec *s = spec_from(THESIS_EQ2_4);
    c2b_blend *b = blend_from(s, 0.0), *fresh = blend_from(s, 0.25);
    if (!check_true("time blends created", b && fresh)) {
        c2b_blend_destroy(b);
        c2b_blend_destroy(fresh);
        c2b_spec_destroy(s);
        return;
    }
    c2b_error err;
    check_true("set_time(0.25)", c2b_blend_set_time(b, 0.25, &err) == C2B_OK);
    double u[4] = {0.1, 0.4, 0.6, 0.9}, v[4] = {0.05, 0.3, 0.55, 0.8}, o1[4 * 30], o2[4 * 30];
    c2b_blend_eval(b, 4, u, v, 3, o1, NULL);
    c2b_blend_eval(fresh, 4, u, v, 3, o2, NULL);
    double diff = 0;
    for (int i = 0; i < 4 * 30; i++)
        diff = fmax(diff, fabs(o1[i] - o2[i]));
    check_le("moved frame equals a fresh blend at t=0.25", diff, 1e-14);
    c2b_blend_destroy(b);
    c2b_blend_destroy(fresh);
    c2b_spec_destroy(s);

    static const char *STATIC =
        "{\"periodic\": true, \"constants\": {\"a\": 1.0, \"b\": 0.8},"
        " \"primaries\": [{\"surface\": [\"a*sin(2*pi*v)\", \"a*cos(2*pi*v)\", \"2+3*u^2\"], \"trim_u\": 0.2, \"direction\": -1},"
        "  {\"surface\": [\"b*sin(2*pi*v)+0.1*cos(6*pi*v)\", \"b*cos(2*pi*v)\", \"-5*u^3\"], \"trim_u\": 0.3}]}";
    s = spec_from(STATIC);
    b = blend_from(s, 0.0);
    if (!check_true("static blend created", b != NULL)) {
        c2b_spec_destroy(s);
        return;
    }
    c2b_blend_eval(b, 4, u, v, 3, o1, NULL);
    int identical = 1;
    static const double ts[] = {0.7, 3.0, -12.5};
    for (int k = 0; k < 3; k++) {
        c2b_blend_set_time(b, ts[k], NULL);
        c2b_blend_eval(b, 4, u, v, 3, o2, NULL);
        identical &= memcmp(o1, o2, sizeof o1) == 0;
    }
    check_true("static primaries: bit-identical surfaces at t = 0, 0.7, 3, -12.5", identical);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

/* Open trimlines with cubic v-variation: the exact polynomial recursion. */
static void test_open_cubic(void)
{
    static const char *J =
        "{\"v_range\": [0, 2], \"shape\": [1.3, -0.7, 2.0, 0.5],"
        " \"boundary\": {\"u0\": [[\"v\", \"0.5*v^3-v\", \"1+0.2*v^2\"], [\"0\", \"v^2\", \"1\"], [\"0.1*v^3\", \"0\", \"0\"]],"
        "              \"u1\": [[\"v+0.3\", \"2-v^3\", \"-1+v\"], [\"v^3\", \"0\", \"-1\"], [\"0\", \"1\", \"v^2\"]]}}";
    c2b_spec *s = NULL;
    c2b_blend *b = open_blend(J, 0, "open cubic blend created", &s);
    if (!b)
        return;
    /* Hand-written data at v = 1.3. */
    double v = 1.3, o0[30], o1[30];
    eval10(b, 0, v, o0);
    eval10(b, 1, v, o1);
    double w0[3][3] = {{v, 0.5 * v * v * v - v, 1 + 0.2 * v * v}, {0, v * v, 1}, {0.1 * v * v * v, 0, 0}};
    double w1[3][3] = {{v + 0.3, 2 - v * v * v, -1 + v}, {v * v * v, 0, -1}, {0, 1, v * v}};
    static const int entry[3] = {0, 1, 3};
    for (int p = 0; p < 3; p++)
        for (int c = 0; c < 3; c++) {
            char what[96];
            snprintf(what, sizeof what, "open cubic u=0 d^%d/du^%d %c", p, p, "xyz"[c]);
            check_close(what, o0[entry[p] * 3 + c], w0[p][c], 1e-12, 1e-12);
            snprintf(what, sizeof what, "open cubic u=1 d^%d/du^%d %c", p, p, "xyz"[c]);
            check_close(what, o1[entry[p] * 3 + c], w1[p][c], 1e-12, 1e-12);
        }
    double shape[4] = {1.3, -0.7, 2.0, 0.5}, worst = 0;
    for (int k = 0; k < 4; k++)
        worst = fmax(worst, c2_residual(b, shape, 0.2 + 0.2 * k, 0.3 + 0.4 * k, NULL, 1e-2));
    check_le("open cubic PDE residual (finite differences, relative)", worst, 1e-6);
    double trunc = c2b_blend_truncation_error(b);
    check_le("polynomial data represented exactly (truncation error)", trunc, 1e-12);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

/* Sampled data give the same blend as analytic data: exactly for band-limited
 * periodic data, within the reported truncation error for open data. */
static void test_sampled(void)
{
    enum { N = 48, NO = 257 };
    char *buf = malloc(400000);
    /* periodic: samples of the eq. 2-3 data at t = 0 */
    size_t k = (size_t)sprintf(buf, "{\"periodic\": true, \"boundary\": {");
    const double a = 1.6, bb = 1.0, c = 0.8, d = 0.6;
    for (int side = 0; side < 2; side++) {
        k += (size_t)sprintf(buf + k, "%s\"u%d\": [{\"samples\": [", side ? ", " : "", side);
        for (int i = 0; i < N; i++) {
            double v = (double)i / N, sv = sin(2 * C2B_PI * v), cv = cos(2 * C2B_PI * v);
            k += (size_t)sprintf(buf + k, "%s[%.17g, %.17g, %.17g]", i ? ", " : "",
                                 side ? c * sv : a * sv, side ? d * cv : bb * cv, side ? -0.135 : 2.12);
        }
        k += (size_t)sprintf(buf + k, "]}, [\"0\", \"0\", \"%s\"], [\"0\", \"0\", \"%s\"]]",
                             side ? "-1.35" : "-1.2", side ? "-9" : "6");
    }
    sprintf(buf + k, "}}");
    c2b_spec *ss = spec_from(buf);
    c2b_spec *sa = spec_from(THESIS_EQ2_4);
    c2b_blend *bs = ss ? blend_from(ss, 0) : NULL, *ba = sa ? blend_from(sa, 0) : NULL;
    if (check_true("sampled and analytic periodic blends created", bs && ba)) {
        double u[5] = {0, 0.2, 0.5, 0.77, 1}, v[5] = {0.01, 0.3, 0.5, 0.66, 0.9}, o1[5 * 30], o2[5 * 30];
        c2b_blend_eval(bs, 5, u, v, 3, o1, NULL);
        c2b_blend_eval(ba, 5, u, v, 3, o2, NULL);
        double diff = 0, scale = 0;
        for (int i = 0; i < 5 * 30; i++) {
            diff = fmax(diff, fabs(o1[i] - o2[i]));
            scale = fmax(scale, fabs(o2[i]));
        }
        check_le("periodic: 48 samples vs analytic (relative, all derivatives)", diff / scale, 1e-12);
    }
    c2b_blend_destroy(bs);
    c2b_blend_destroy(ba);
    c2b_spec_destroy(ss);
    c2b_spec_destroy(sa);

    /* open: exp(cos(v)) style data, not a mode or polynomial */
    k = (size_t)sprintf(buf, "{\"v_range\": [0, 1.5], \"boundary\": {");
    for (int side = 0; side < 2; side++) {
        k += (size_t)sprintf(buf + k, "%s\"u%d\": [{\"samples\": [", side ? ", " : "", side);
        for (int i = 0; i < NO; i++) {
            double v = 1.5 * i / (NO - 1);
            k += (size_t)sprintf(buf + k, "%s[%.17g, %.17g, %.17g]", i ? ", " : "",
                                 side ? 0.5 * exp(cos(2 * v)) : exp(cos(v)), v, side ? -1.0 : 1.0);
        }
        k += (size_t)sprintf(buf + k, "]}, [\"0\", \"0\", \"%s\"], [\"0\", \"0\", \"0\"]]", side ? "-1" : "1");
    }
    sprintf(buf + k, "}}");
    static const char *OPEN_A =
        "{\"v_range\": [0, 1.5], \"boundary\": {"
        " \"u0\": [[\"exp(cos(v))\", \"v\", \"1\"], [\"0\", \"0\", \"1\"], [\"0\", \"0\", \"0\"]],"
        " \"u1\": [[\"0.5*exp(cos(2*v))\", \"v\", \"-1\"], [\"0\", \"0\", \"-1\"], [\"0\", \"0\", \"0\"]]}}";
    ss = spec_from(buf);
    sa = spec_from(OPEN_A);
    bs = ss ? blend_from(ss, 0) : NULL;
    ba = sa ? blend_from(sa, 0) : NULL;
    if (check_true("sampled and analytic open blends created", bs && ba)) {
        double es = c2b_blend_truncation_error(bs), ea = c2b_blend_truncation_error(ba);
        printf("     open truncation error: sampled %.3g, analytic %.3g\n", es, ea);
        double u[5] = {0, 0.2, 0.5, 0.77, 1}, v[5] = {0.01, 0.3, 0.75, 1.1, 1.49}, o1[5 * 3], o2[5 * 3];
        c2b_blend_eval(bs, 5, u, v, 0, o1, NULL);
        c2b_blend_eval(ba, 5, u, v, 0, o2, NULL);
        double diff = 0;
        for (int i = 0; i < 5 * 3; i++)
            diff = fmax(diff, fabs(o1[i] - o2[i]));
        check_le("open: analytic truncation error reaches 1e-11 (end polynomial + DST)", ea, 1e-11);
        check_le("open: sampled vs analytic positions within 10x the reported sampled error", diff,
                 10 * es + 1e-12);
        check_le("open: 257 samples give 1e-7 (one-sided end derivatives)", es, 1e-7);
    }
    c2b_blend_destroy(bs);
    c2b_blend_destroy(ba);
    c2b_spec_destroy(ss);
    c2b_spec_destroy(sa);
    free(buf);
}

/* Force F = p(u) f(v): residual equals F, boundary data untouched. */
static void test_force(void)
{
    static const char *J =
        "{\"v_range\": [0, 6.283185307179586], \"periodic\": true,"
        " \"boundary\": {\"u0\": [[\"cos(v)\", \"sin(v)\", \"1\"], [\"0\", \"0\", \"-1\"], [\"0\", \"0\", \"0\"]],"
        "              \"u1\": [[\"2*cos(v)\", \"2*sin(v)\", \"0\"], [\"0\", \"0\", \"-1\"], [\"0\", \"0\", \"0\"]]},"
        " \"force\": [\"100*(1+u^2)*cos(v)\", \"100*(1+u^2)*sin(v)\", \"-50*u\"]}";
    c2b_spec *s = NULL;
    c2b_blend *b = open_blend(J, 0, "forced blend created", &s);
    if (!b)
        return;
    double shape[4] = {1, 1, 1, 1}, worst = 0;
    for (int k = 0; k < 4; k++) {
        double u = 0.2 + 0.2 * k, v = 0.4 + 1.3 * k;
        double F[3] = {100 * (1 + u * u) * cos(v), 100 * (1 + u * u) * sin(v), -50 * u};
        worst = fmax(worst, c2_residual(b, shape, u, v, F, 1e-2));
    }
    check_le("forced PDE residual (finite differences, relative)", worst, 1e-6);
    double o0[30], o1[30], v = 0.9;
    eval10(b, 0, v, o0);
    eval10(b, 1, v, o1);
    /* Data of size 1 against a force of size 200: 1e-13 relative to the force. */
    check_close("forced: S_x(0) = cos v", o0[0], cos(v), 0, 200e-13);
    check_close("forced: S_uu z(1) = 0", o1[3 * 3 + 2], 0.0, 0, 200e-13);
    check_close("forced: S_u y(1) = 0", o1[1 * 3 + 1], 0.0, 0, 200e-13);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);

    /* Sign of the response: the Green's function of (-1)^n D^{2n} with clamped ends is
     * positive, so under a positive radial load the order-4 (C1) blend bulges outward
     * (seed 001 fig. 3) and the order-6 (C2) blend moves inward. */
    static const char *const cont[2] = {"C1", "C2"};
    for (int k = 0; k < 2; k++) {
        char J2[1024], J3[1200];
        const char *rows = k ? ", [\"0\", \"0\", \"0\"]" : "";
        snprintf(J2, sizeof J2,
                 "{\"continuity\": \"%s\", \"v_range\": [0, 6.283185307179586], \"periodic\": true,"
                 " \"boundary\": {\"u0\": [[\"cos(v)\", \"sin(v)\", \"1\"], [\"0\", \"0\", \"-1\"]%s],"
                 " \"u1\": [[\"2*cos(v)\", \"2*sin(v)\", \"0\"], [\"0\", \"0\", \"-1\"]%s]}",
                 cont[k], rows, rows);
        snprintf(J3, sizeof J3, "%s, \"force\": [\"100*cos(v)\", \"100*sin(v)\", \"0\"]}", J2);
        strcat(J2, "}");
        c2b_spec *s0 = spec_from(J2), *s1 = spec_from(J3);
        c2b_blend *b0 = s0 ? blend_from(s0, 0) : NULL, *b1 = s1 ? blend_from(s1, 0) : NULL;
        if (check_true("force sign blends created", b0 && b1)) {
            double um = 0.5, vm = 0, p1[3], p0[3];
            c2b_blend_eval(b1, 1, &um, &vm, 0, p1, NULL);
            c2b_blend_eval(b0, 1, &um, &vm, 0, p0, NULL);
            printf("     %s mid-height radius: %.6f unforced, %.6f forced\n", cont[k], p0[0], p1[0]);
            check_true(k ? "C2: positive radial force moves the blend inward"
                         : "C1: positive radial force bulges the blend outward (seed 001 fig. 3)",
                       k ? p1[0] < p0[0] : p1[0] > p0[0]);
        }
        c2b_blend_destroy(b0);
        c2b_blend_destroy(b1);
        c2b_spec_destroy(s0);
        c2b_spec_destroy(s1);
    }
    return;
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

/* ODE class: each v solves rho G^(6) + eta G^(4) + lambda G'' = 0 independently;
 * compare with collocation on the data at that v. */
static void test_ode(void)
{
    static const char *J =
        "{\"continuity\": \"ODE\", \"shape\": [1, -2, 0.5], \"v_range\": [0, 1],"
        " \"boundary\": {\"u0\": [[\"exp(v)\", \"v^2\", \"sin(3*v)\"], [\"1\", \"v\", \"0\"], [\"0\", \"1\", \"v\"]],"
        "              \"u1\": [[\"1+v\", \"cos(v)\", \"2\"], [\"0\", \"-1\", \"1\"], [\"v^3\", \"0\", \"1\"]]}}";
    c2b_spec *s = NULL;
    c2b_blend *b = open_blend(J, 0, "ODE blend created", &s);
    if (!b)
        return;
    double v = 0.37;
    double data[3][6] = {{exp(v), 1, 0, 1 + v, 0, v * v * v},
                         {v * v, v, 1, cos(v), -1, 0},
                         {sin(3 * v), 0, v, 2, 1, 1}};
    double cc[4] = {1, -2, 0.5, 0}, us[3] = {0.25, 0.5, 0.8}, ref[3 * 4];
    for (int c = 0; c < 3; c++) {
        oracle_cheb_bvp(3, cc, -1, NULL, data[c], 0, 3, us, ref, NULL);
        for (int k = 0; k < 3; k++) {
            double o[30];
            eval10(b, us[k], v, o);
            char what[96];
            snprintf(what, sizeof what, "ODE %c(u=%.2f, v=%.2f) vs collocation", "xyz"[c], us[k], v);
            check_close(what, o[c], ref[k * 4], 1e-9, 1e-9);
            snprintf(what, sizeof what, "ODE %c_uu(u=%.2f, v=%.2f) vs collocation", "xyz"[c], us[k], v);
            check_close(what, o[9 + c], ref[k * 4 + 2], 1e-8, 1e-8);
        }
    }
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

/* Thesis Figure 2 (eqs. 55-57): with a=2.6, b=4.5, c=h3=5, d=h1=2, h2=3, u0=0.35,
 * u1=0.3 and eta=lambda=rho=1, gamma = 1 gives a concave (waisted) profile,
 * gamma = -1.5 a nearly straight middle, gamma = -1.8 a convex one. The profile is
 * the x-radius G_x(u), read off S_x at v = 1/4. */
static void test_figure2(void)
{
    static const double gammas[] = {1.0, -0.9, -1.1, -1.3, -1.5, -1.6, -1.7, -1.75, -1.8};
    double mid[9], curv[9], slope[9], var[9];
    for (int i = 0; i < 9; i++) {
        char J[1200];
        snprintf(J, sizeof J,
                 "{\"shape\": [%g, 1, 1, 1], \"periodic\": true,"
                 " \"constants\": {\"a\": 2.6, \"b\": 4.5, \"c\": 5, \"d\": 2, \"h1\": 2, \"h2\": 3, \"h3\": 5},"
                 " \"primaries\": [{\"surface\": [\"a*u*sin(2*pi*v)\", \"b*u*cos(2*pi*v)\", \"h1+h2*u^2\"], \"trim_u\": 0.35, \"direction\": -1},"
                 "  {\"surface\": [\"c*u*sin(2*pi*v)\", \"d*u*cos(2*pi*v)\", \"-h3*u^3\"], \"trim_u\": 0.3, \"direction\": 1}]}",
                 gammas[i]);
        c2b_spec *s = spec_from(J);
        c2b_blend *b = s ? blend_from(s, 0) : NULL;
        if (!b) {
            check_true("figure 2 blend created", 0);
            c2b_spec_destroy(s);
            return;
        }
        double o[30];
        eval10(b, 0.5, 0.25, o);
        mid[i] = o[0];
        slope[i] = o[3];
        curv[i] = o[9];
        double lo = 1e300, hi = -1e300, sum = 0;
        for (int k = 0; k <= 30; k++) {
            double uu = 0.35 + 0.01 * k, vq = 0.25, p[3];
            c2b_blend_eval(b, 1, &uu, &vq, 0, p, NULL);
            lo = fmin(lo, p[0]);
            hi = fmax(hi, p[0]);
            sum += p[0];
        }
        var[i] = (hi - lo) / (sum / 31);
        printf("     gamma=%5.2f: G_x(0.5)=%.6f G_x'(0.5)=%.6f G_x''(0.5)=%.6f middle variation %.3f\n", gammas[i], mid[i],
               slope[i], curv[i], var[i]);
        c2b_blend_destroy(b);
        c2b_spec_destroy(s);
    }
    check_true("gamma=1: concave profile (waist, G'' > 0 at mid-height)", curv[0] > 0);
    check_true("gamma=-1.8: convex profile (bulge, G'' < 0 at mid-height)", curv[8] < 0);
    /* Radius variation over the middle part u in [0.35, 0.65], relative to its mean. */
    check_true("concave -> convex transition (sign change of G'') between gamma -1.3 and -1.6",
               curv[3] > 0 && curv[5] < 0);
    check_true("gamma=-1.5: middle part nearly straight (radius varies < 15%, less than at 1 and -1.8)",
               var[4] < 0.15 && var[4] < var[0] && var[4] < var[8]);
    int mono = 1;
    for (int i = 1; i < 9; i++)
        mono &= mid[i] > mid[i - 1];
    check_true("mid-height radius grows monotonically as gamma goes 1 -> -1.8", mono);
}

/* Per-component shape parameters: each component solves its own PDE. */
static void test_per_component_shape(void)
{
    static const char *J =
        "{\"shape\": {\"x\": [1, 1, 1, 1], \"y\": [-1.8, 1, 1, 1], \"z\": [1, -7, 1, 1]}, \"periodic\": true,"
        " \"boundary\": {\"u0\": [[\"sin(2*pi*v)\", \"sin(2*pi*v)\", \"sin(2*pi*v)\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]],"
        "              \"u1\": [[\"2*sin(2*pi*v)\", \"2*sin(2*pi*v)\", \"2*sin(2*pi*v)\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]]}}";
    c2b_spec *s = NULL;
    c2b_blend *b = open_blend(J, 0, "per-component blend created", &s);
    if (!b)
        return;
    const double beta = -4 * C2B_PI * C2B_PI;
    double shapes[3][4] = {{1, 1, 1, 1}, {-1.8, 1, 1, 1}, {1, -7, 1, 1}};
    double d[6] = {1, 0, 0, 2, 0, 0}, u = 0.43, v = 0.25, o[30];
    eval10(b, u, v, o);
    for (int c = 0; c < 3; c++) {
        double cc[4] = {shapes[c][0], shapes[c][1] * beta, shapes[c][2] * beta * beta,
                        shapes[c][3] * beta * beta * beta}, ref[4];
        oracle_cheb_bvp(3, cc, -1, NULL, d, 0, 1, &u, ref, NULL);
        char what[96];
        snprintf(what, sizeof what, "per-component shape: %c vs collocation", "xyz"[c]);
        check_close(what, o[c], ref[0], 1e-9, 1e-9);
    }
    check_true("the three components differ", fabs(o[0] - o[1]) > 1e-3 && fabs(o[1] - o[2]) > 1e-3);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

/* Grid evaluation equals pointwise evaluation. */
static void test_grid(void)
{
    c2b_spec *s = spec_from(THESIS_EQ2_4);
    c2b_blend *b = s ? blend_from(s, 0.1) : NULL;
    if (!b) {
        c2b_spec_destroy(s);
        return;
    }
    double u[3] = {0, 0.3, 1}, v[4] = {0, 0.2, 0.7, 1}, g[12 * 30], p[30];
    c2b_blend_eval_grid(b, 3, u, 4, v, 3, g, NULL);
    double diff = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            eval10(b, u[i], v[j], p);
            for (int k = 0; k < 30; k++)
                diff = fmax(diff, fabs(p[k] - g[(i * 4 + j) * 30 + k]));
        }
    check_le("grid evaluation equals pointwise evaluation", diff, 1e-12);
    c2b_error err;
    check_true("order 4 rejected", c2b_blend_eval_grid(b, 3, u, 4, v, 4, g, &err) == C2B_ERR_ARG);
    check_true("absurd grid rejected with a limit error",
               c2b_blend_eval_grid(b, 100000, u, 100000, v, 0, g, &err) == C2B_ERR_LIMIT);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

/* Grid evaluation equals pointwise evaluation on a grid wider than its v-blocks (at most
 * 512 v's), with every derivative up to 3 and hundreds of modes: periodic samples of
 * kinked functions (|sin(v / 2)|, shifted per component: their Fourier coefficients
 * decay only as 1/m^2, so the expansion keeps every harmonic up to 256). */
static void test_grid_many_modes(void)
{
    enum { N = 512, NU = 37, NV = 701 };
    char *buf = malloc(200000);
    size_t k = (size_t)sprintf(buf, "{\"v_range\": [0, 6.283185307179586], \"periodic\": true, "
                                    "\"boundary\": {");
    for (int side = 0; side < 2; side++) {
        k += (size_t)sprintf(buf + k, "%s\"u%d\": [{\"samples\": [", side ? ", " : "", side);
        for (int i = 0; i < N; i++) {
            double v = 2 * C2B_PI * i / N;
            k += (size_t)sprintf(buf + k, "%s[%.17g, %.17g, %.17g]", i ? ", " : "",
                                 (2 + side) * cos(v) + 0.3 * fabs(sin(v / 2)),
                                 (2 - side) * sin(v) + 0.2 * fabs(sin((v - 1) / 2)),
                                 side + 0.1 * fabs(sin((v - 2) / 2)));
        }
        k += (size_t)sprintf(buf + k, "]}, [\"%s\", \"0\", \"1\"], [\"0\", \"sin(v)\", \"0\"]]",
                             side ? "cos(v)" : "0");
    }
    sprintf(buf + k, "}}");
    c2b_spec *s;
    c2b_blend *b = open_blend(buf, 0, "a blend of 512 kinked samples", &s);
    if (!b) {
        free(buf);
        return;
    }
    /* Modes of y (sines and cosines of 256 frequencies), from the blend's description. */
    size_t need = 0;
    int modes = -1;
    c2b_blend_info_json(b, buf, 1, &need, NULL);
    char *info = malloc(need + 1);
    if (info && !c2b_blend_info_json(b, info, need + 1, &need, NULL)) {
        cJSON *j = cJSON_Parse(info);
        cJSON *y = cJSON_GetArrayItem(cJSON_GetObjectItem(j, "components"), 1);
        modes = cJSON_GetArraySize(cJSON_GetObjectItem(y, "modes"));
        cJSON_Delete(j);
    }
    free(info);
    free(buf);
    check_true("y has over 500 modes", modes > 500);
    double u[NU], v[NV];
    for (int i = 0; i < NU; i++)
        u[i] = (double)i / (NU - 1);
    for (int j = 0; j < NV; j++)
        v[j] = 6.2 * j / (NV - 1) + 0.01;
    double *g = malloc((size_t)NU * NV * 30 * sizeof *g), p[30], diff = 0, scale = 0;
    if (check_true("grid evaluated", g && !c2b_blend_eval_grid(b, NU, u, NV, v, 3, g, NULL))) {
        for (int i = 0; i < NU; i++)
            for (int j = 0; j < NV; j++) {
                eval10(b, u[i], v[j], p);
                for (int e = 0; e < 30; e++) {
                    diff = fmax(diff, fabs(p[e] - g[((size_t)i * NV + j) * 30 + e]));
                    scale = fmax(scale, fabs(p[e]));
                }
            }
        check_le("37 x 701 grid equals pointwise evaluation (relative to the largest entry)",
                 diff / scale, 1e-13);
    }
    free(g);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

int main(void)
{
    test_thesis_eq4();
    test_time();
    test_open_cubic();
    test_sampled();
    test_force();
    test_ode();
    test_figure2();
    test_per_component_shape();
    test_grid();
    test_grid_many_modes();
    return test_summary("test_blend");
}
