/* Spec fields of the papers' solvers: "solver", "M", "N", "collocation", "approach",
 * "curves". The spec path (symbolic v-derivatives by libmatheval) must agree with the
 * direct API fed closed-form derivatives; bad fields are named. */
#include "approx_examples.h"
#include "c2b_surface.h"
#include "test_util.h"

#define NG 21

static c2b_status parse(const char *json, c2b_spec **s, c2b_error *err)
{
    return c2b_spec_parse(json, strlen(json), s, err);
}

int main(void)
{
    c2b_error err;
    double u[NG], v[NG];
    ex_linspace(NG, 0, 1, u);
    /* thesis-approx from a spec against the direct API */
    {
        c2b_spec *sp = ex_spec("thesis_eq127_129_approx.json", NULL, NULL);
        c2b_surface *sf = NULL;
        ex_linspace(NG, 0, 1, v);
        if (!check_true("thesis_eq127_129_approx.json solves", sp && !c2b_surface_create(sp, 0.1, &sf, &err)))
            return 1;
        ex_thesis x;
        ex_thesis_init(&x, 0);
        c2b_approx *a = NULL;
        c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, NULL, &a, &err);
        static double p[NG * NG * 6 * 3], q[NG * NG * 6 * 3];
        c2b_surface_eval_grid(sf, NG, u, NG, v, 2, p, &err);
        c2b_approx_eval_grid(a, NG, u, NG, v, 2, q, &err);
        double e = 0;
        for (int i = 0; i < NG * NG * 6 * 3; i++)
            e = fmax(e, fabs(p[i] - q[i]) / fmax(1, fabs(q[i])));
        check_le("spec (symbolic derivatives) = API (closed-form derivatives)", e, 1e-9);
        c2b_approx_destroy(a);
        c2b_surface_destroy(sf);
        c2b_spec_destroy(sp);
    }
    /* "group2": "closed": the spec's group 2 data take their closed form, as through the API */
    {
        c2b_spec *sp = ex_spec("thesis_eq127_129_approx.json", "\"M\": 20,", "\"M\": 20, \"group2\": \"closed\",");
        c2b_surface *sf = NULL;
        ex_linspace(NG, 0, 1, v);
        if (check_true("\"group2\": \"closed\" solves", sp && !c2b_surface_create(sp, 0.1, &sf, &err))) {
            ex_thesis x;
            ex_thesis_init(&x, 0);
            static double p[NG * NG * 3], q[NG * NG * 3];
            c2b_surface_eval_grid(sf, NG, u, NG, v, 0, p, &err);
            double e = 0, scale = 0;
            if (check_true("oracle surface", !ex_oracle_surface(&x, NG, u, v, q))) {
                for (int i = 0; i < NG * NG * 3; i++)
                    e = fmax(e, fabs(p[i] - q[i])), scale = fmax(scale, fabs(q[i]));
                check_le("spec with \"group2\": \"closed\" equals the collocation oracle", e, 1e-9 * scale);
            }
        }
        c2b_surface_destroy(sf);
        c2b_spec_destroy(sp);
    }
    /* pseudo-navier from a spec */
    {
        c2b_spec *sp = ex_spec("seed001_eq17_navier.json", NULL, NULL);
        c2b_surface *sf = NULL;
        ex_linspace(NG, 0, 2 * C2B_PI, v);
        if (!check_true("seed001_eq17_navier.json solves", sp && !c2b_surface_create(sp, 0, &sf, &err)))
            return 1;
        ex_seed001 ex;
        ex_seed001_init(&ex);
        c2b_navier *nv = NULL;
        c2b_navier_create(ex.shape, &ex.dom, &ex.vd, 0, NULL, &nv, &err);
        static double p[NG * NG * 3], q[NG * NG * 3];
        c2b_surface_eval_grid(sf, NG, u, NG, v, 0, p, &err);
        c2b_navier_eval_grid(nv, NG, u, NG, v, 0, q, &err);
        double e = 0;
        for (int i = 0; i < NG * NG * 3; i++)
            e = fmax(e, fabs(p[i] - q[i]));
        check_le("pseudo-navier: spec = API", e, 1e-13);
        c2b_navier_destroy(nv);
        c2b_surface_destroy(sf);
        c2b_spec_destroy(sp);
    }
    /* seed 000 control curves from a spec: eqs. 3-6 at v = 0.1 (x and z written out) */
    {
        c2b_spec *sp = ex_spec("seed000_controls.json", NULL, NULL);
        c2b_surface *sf = NULL;
        if (!check_true("seed000_controls.json solves", sp && !c2b_surface_create(sp, 0, &sf, &err)))
            return 1;
        double ub[2] = {0, 1}, vv = 0.1, d[2 * 6 * 3], cs = cos(2 * C2B_PI * vv);
        c2b_surface_eval_grid(sf, 2, ub, 1, &vv, 2, d, &err);
        check_close("x: S_u(0) = (cb2 - c1)/u2", d[1 * 3 + 0], (1.05 * cs - cs) / 0.1, 1e-12, 1e-13);
        check_close("z: S_uu(0) = eq. 4", d[3 * 3 + 2], (0.1 * 0.5 - 0.2 * 0.25 + 0.1 * 0) / (0.01 * 0.1), 1e-12, 1e-12);
        check_close("z: S_u(1) = (c4 - cb6)/(1 - u6)", d[(6 + 1) * 3 + 2], (2 - 1.8) / 0.1, 1e-12, 1e-12);
        check_close("z: S_uu(1) = eq. 6", d[(6 + 3) * 3 + 2], (0.1 * 2 + 0.1 * 1.6 - 0.2 * 1.8) / (0.01 * 0.1), 1e-12, 1e-11);
        c2b_surface_destroy(sf);
        c2b_spec_destroy(sp);
    }
    /* general (group 3) data are differentiated symbolically up to order 6:
     * f = v sin(2 pi v), f^(k) = v s^(k) + k s^(k-1) with s = sin(2 pi v) */
    {
        c2b_spec *sp = NULL;
        const char *j = "{\"solver\": \"thesis-approx\", \"boundary\": {\"u0\": [[\"v*sin(2*pi*v)\",\"0\",\"0\"], [\"0\",\"0\",\"0\"], [\"0\",\"0\",\"0\"]], "
                        "\"u1\": [[\"0\",\"0\",\"1\"], [\"0\",\"0\",\"0\"], [\"0\",\"0\",\"0\"]]}}";
        c2b_vdata vd;
        c2b_error_clear(&err);
        int okp = !parse(j, &sp, &err) && !c2b_spec_vdata(sp, 6, &vd, &err);
        if (!okp)
            printf("  %s\n", err.msg);
        if (check_true("group-3 spec parses", okp)) {
            const c2b_vdfunc *f = &vd.f[0][0][0];
            double w = 2 * C2B_PI, vv = 0.3;
            for (int k = 0; k <= 6; k++) {
                double sk = pow(w, k) * sin(w * vv + k * C2B_PI / 2);
                double sk1 = k ? pow(w, k - 1) * sin(w * vv + (k - 1) * C2B_PI / 2) : 0;
                char what[64];
                snprintf(what, sizeof what, "d^%d/dv^%d of v sin(2 pi v)", k, k);
                check_close(what, f->fn(f->ctx, k, vv, 0), vv * sk + k * sk1, 1e-12, 1e-12);
            }
            c2b_surface *sf = NULL;
            check_true("group-3 thesis-approx solves", !c2b_surface_create(sp, 0, &sf, &err));
            c2b_surface_destroy(sf);
        }
        c2b_spec_destroy(sp);
    }
    /* the variable decomposition (thesis eq. 59) keeps constants exact: data K + F(v)
     * give g_l K + (the approximation of F alone), and the quintic Hermite basis sums to
     * 1, so decomposition(K + F) - differential(F) = K everywhere. Without the split,
     * the sine series also has to absorb K, and the error against the closed form grows. */
    {
        static const char *fmt =
            "{\"solver\": \"thesis-approx\", \"M\": 20, %s \"periodic\": true, \"v_range\": [0, 1], "
            "\"boundary\": {\"u0\": [[\"%ssin(2*pi*v)\", \"%scos(2*pi*v)\", \"0\"], [\"0\",\"0\",\"0\"], [\"0\",\"0\",\"0\"]], "
            "\"u1\": [[\"%s0.5*sin(2*pi*v)\", \"%s0.5*cos(2*pi*v)\", \"1\"], [\"0\",\"0\",\"0\"], [\"0\",\"0\",\"0\"]]}}";
        char jd[1024], jf[1024], jw[1024], je[1024];
        snprintf(jd, sizeof jd, fmt, "\"approach\": \"decomposition\",", "2+", "1+", "2+", "1+");
        snprintf(jf, sizeof jf, fmt, "", "", "", "", "");
        snprintf(jw, sizeof jw, fmt, "", "2+", "1+", "2+", "1+");
        /* the closed form of the same data (no "solver") */
        snprintf(je, sizeof je, "%s", jw);
        memmove(je + 1, strstr(je, "\"periodic\""), strlen(strstr(je, "\"periodic\"")) + 1);
        const char *js[4] = {jd, jf, jw, je};
        c2b_spec *sp[4] = {NULL};
        c2b_surface *sf[4] = {NULL};
        static double g[4][NG * NG * 3];
        int ok = 1;
        ex_linspace(NG, 0, 1, v);
        for (int k = 0; k < 4 && ok; k++) {
            ok = !parse(js[k], &sp[k], &err) && !c2b_surface_create(sp[k], 0, &sf[k], &err) &&
                 !c2b_surface_eval_grid(sf[k], NG, u, NG, v, 0, g[k], &err);
            if (!ok)
                printf("  %s\n", err.msg);
        }
        if (check_true("decomposition specs solve", ok)) {
            double dk = 0, e_dec = 0, e_whole = 0;
            static const double K[3] = {2, 1, 0};
            for (int i = 0; i < NG * NG * 3; i++) {
                dk = fmax(dk, fabs(g[0][i] - g[1][i] - K[i % 3]));
                e_dec = fmax(e_dec, fabs(g[0][i] - g[3][i]));
                e_whole = fmax(e_whole, fabs(g[2][i] - g[3][i]));
            }
            check_le("decomposition(K + F) - differential(F) = K (constant part exact)", dk, 1e-12);
            printf("  max error against the closed form: decomposition %.3e, undivided %.3e\n", e_dec, e_whole);
            check_le("the split is more accurate than the undivided datum (3x)", 3 * e_dec, e_whole);
        }
        for (int k = 0; k < 4; k++) {
            c2b_surface_destroy(sf[k]);
            c2b_spec_destroy(sp[k]);
        }
    }
    /* bad fields are named */
    struct { const char *json, *frag; } bad[] = {
        {"{\"solver\": \"foo\", \"boundary\": {\"u0\": [[\"0\",\"0\",\"0\"]], \"u1\": [[\"1\",\"0\",\"0\"]]}}", "solver: 'foo'"},
        {"{\"solver\": \"thesis-approx\", \"M\": 0, \"boundary\": {}}", "M: expected an integer"},
        {"{\"M\": 5, \"boundary\": {\"u0\": [[\"0\",\"0\",\"0\"]], \"u1\": [[\"1\",\"0\",\"0\"]]}}", "only valid with an approximate"},
        {"{\"solver\": \"pseudo-navier\", \"collocation\": [6], \"boundary\": {}}", "collocation"},
        {"{\"solver\": \"thesis-approx\", \"group2\": \"exact\", \"boundary\": {}}", "group2: expected \"series\" or \"closed\""},
        {"{\"solver\": \"pseudo-navier\", \"group2\": \"closed\", \"boundary\": {}}", "group2: only valid with \"solver\": \"thesis-approx\""},
        {"{\"continuity\": \"C2\", \"curves\": {\"c1\": [\"0\",\"0\",\"0\"], \"c4\": [\"1\",\"0\",\"0\"], \"w\": [0,0,0,0]}}", "curves: needs \"continuity\": \"ODE\""},
        {"{\"continuity\": \"ODE\", \"curves\": {\"c1\": [\"0\",\"0\",\"0\"], \"c4\": [\"1\",\"0\",\"0\"]}}", "exactly one of 'w'"},
        {"{\"continuity\": \"ODE\", \"curves\": {\"c1\": [\"0\",\"0\",\"0\"], \"c4\": [\"1\",\"0\",\"0\"], \"controls\": [{\"u\": 0.2, \"curve\": [\"0\",\"0\",\"0\"]}, {\"u\": 0.1, \"curve\": [\"0\",\"0\",\"0\"]}, {\"u\": 0.8, \"curve\": [\"1\",\"0\",\"0\"]}, {\"u\": 0.9, \"curve\": [\"1\",\"0\",\"0\"]}]}}", "controls[1].u"},
        {"{\"continuity\": \"ODE\", \"curves\": {\"c1\": [\"q\",\"0\",\"0\"], \"c4\": [\"1\",\"0\",\"0\"], \"w\": [0,0,0,0]}}", "curves.c1[0]"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        c2b_spec *sp = NULL;
        c2b_status st = parse(bad[k].json, &sp, &err);
        int ok = st == C2B_ERR_SPEC && strstr(err.msg, bad[k].frag);
        printf("  -> %s\n", st ? err.msg : "(accepted)");
        check_true(bad[k].frag, ok);
        c2b_spec_destroy(sp);
    }
    /* a solver that does not fit the continuity is named at solve time */
    {
        c2b_spec *sp = NULL;
        const char *j = "{\"continuity\": \"C1\", \"shape\": [1, 2, 1], \"solver\": \"thesis-approx\", "
                        "\"boundary\": {\"u0\": [[\"sin(v)\",\"0\",\"0\"], [\"0\",\"0\",\"0\"]], "
                        "\"u1\": [[\"0\",\"0\",\"1\"], [\"0\",\"0\",\"0\"]]}}";
        c2b_surface *sf = NULL;
        check_true("thesis-approx with C1 rejected naming solver",
                   !parse(j, &sp, &err) && c2b_surface_create(sp, 0, &sf, &err) == C2B_ERR_SPEC &&
                       strstr(err.msg, "solver: thesis-approx needs"));
        c2b_spec_destroy(sp);
    }
    return test_summary("test_spec_solvers");
}
