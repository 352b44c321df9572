/* Seed 000 ODE surfaces whose curves are samples ("curves" with {"samples": ...}).
 *
 * The curves are cuts P(u_k, v) of an analytic reference surface. Each case is solved
 * twice from specs: with every curve an expression (the reference, solved from the
 * exact functions) and with some or all curves sampled uniformly in v (the samples are
 * computed here in C from the same formulas, not by the kernel). The two surfaces must
 * agree to a bound derived from the truncation errors the kernel reports, and the
 * difference must shrink at the rate of the sampled-data representation as the sample
 * count doubles, until it reaches the reference's own truncation error: geometrically
 * for periodic data (FFT), with order 4 at least for open data (an end polynomial
 * matching the second and, once the samples resolve them, fourth derivatives at the
 * ends, estimated from the samples, plus a DST-I sine series).
 *
 * The bound: an ODE surface's u-curves are independent, so per component
 * S(u, v) = sum_p H_p(u) d_p(v) with the transfer functions H_p of the shape
 * parameters (data d_p = c1..c6) and
 *     |S_samples - S_expressions| <= sum_p |H_p(u)| max_p |dd_p| <= K(u) (T_s + T_e),
 * where T_s and T_e are the largest truncation errors the two blends report for their
 * data (c2b_blend_truncation_error(); for data the blend gets as callbacks, the sampled
 * curves' error is c2b_odesurf_truncation_error()). H_p comes from the independent
 * Chebyshev collocation oracle. */
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_blend.h"
#include "c2b_constants.h"
#include "c2b_odesurf.h"
#include "c2b_spec.h"
#include "cheb_bvp.h"
#include "approx_examples.h"
#include "test_util.h"

/* ---- the reference surface, as C and as libmatheval text ---- */

/* slots: c1 (u = 0), c4 (u = 1), controls cb2, cb3, cb5, cb6 */
static const double U_SLOT[6] = {0, 1, 0.1, 0.2, 0.8, 0.9};
static const double SHAPE[3] = {1, 3, 1}; /* rho, eta, lambda (seed 000 fig. 4b) */

/* periodic on [0, 1]: not trigonometric polynomials, so samples truncate; the Fourier
 * coefficients of 1/(1.5 + sin) decay like 0.382^k */
static double P_per(int c, double u, double v)
{
    double w = 2 * C2B_PI * v;
    switch (c) {
    case 0: return (1 + 0.3 * u + 0.2 * u * u) * cos(w) / (1.5 + sin(w));
    case 1: return (1 + 0.5 * u - 0.3 * u * u) * sin(w) / (1.5 + cos(w)) - 0.2 * u * u;
    default: return 2 * u - u * u * u + 0.1 * (1 + u * u) * exp(cos(w));
    }
}
static const char *const E_PER[3] = {"(1 + 0.3*%.17g + 0.2*%.17g^2)*cos(2*pi*v)/(1.5 + sin(2*pi*v))",
                                     "(1 + 0.5*%.17g - 0.3*%.17g^2)*sin(2*pi*v)/(1.5 + cos(2*pi*v)) - 0.2*%.17g^2",
                                     "2*%.17g - %.17g^3 + 0.1*(1 + %.17g^2)*exp(cos(2*pi*v))"};

/* open on [0.5, 2] (v_range not normalised): neither polynomials nor single modes */
#define OV0 0.5
#define OV1 2.0
static double P_open(int c, double u, double v)
{
    switch (c) {
    case 0: return (1 + 0.3 * u + 0.2 * u * u) * cos(3 * v) * exp(0.4 * v);
    case 1: return (1 + 0.5 * u - 0.3 * u * u) / (1.5 + v) - 0.2 * u * u;
    default: return 2 * u - u * u * u + 0.1 * sin(2.3 * v + u);
    }
}
static const char *const E_OPEN[3] = {"(1 + 0.3*%.17g + 0.2*%.17g^2)*cos(3*v)*exp(0.4*v)",
                                      "(1 + 0.5*%.17g - 0.3*%.17g^2)/(1.5 + v) - 0.2*%.17g^2",
                                      "2*%.17g - %.17g^3 + 0.1*sin(2.3*v + %.17g)"};

/* ---- a growing text buffer for the specs ---- */

typedef struct sbuf {
    char *p;
    size_t n, cap;
} sbuf;

static void put(sbuf *b, const char *fmt, ...)
{
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        size_t room = b->cap - b->n;
        int k = vsnprintf(b->p ? b->p + b->n : NULL, b->p ? room : 0, fmt, ap);
        va_end(ap);
        if (k < 0)
            exit(2);
        if (b->p && (size_t)k < room) {
            b->n += (size_t)k;
            return;
        }
        b->cap = 2 * (b->cap + (size_t)k + 64);
        b->p = realloc(b->p, b->cap);
        if (!b->p)
            exit(2);
    }
}

/* A case: which curves are sampled (count, 0 = expression). */
typedef struct ocase {
    int periodic;
    int controls;   /* approach 2 (eqs. 3-7), else approach 1 (eq. 24) */
    int nsamp[6];   /* per slot */
} ocase;

static double P(const ocase *k, int c, double u, double v)
{
    return k->periodic ? P_per(c, u, v) : P_open(c, u, v);
}

static void put_curve(sbuf *b, const ocase *k, int slot)
{
    double u = U_SLOT[slot];
    int n = k->nsamp[slot];
    if (!n) {
        const char *const *E = k->periodic ? E_PER : E_OPEN;
        put(b, "[");
        for (int c = 0; c < 3; c++) {
            put(b, "%s\"", c ? ", " : "");
            put(b, E[c], u, u, u, u, u); /* as many as a formula uses; the rest are ignored */
            put(b, "\"");
        }
        put(b, "]");
        return;
    }
    double v0 = k->periodic ? 0 : OV0, v1 = k->periodic ? 1 : OV1;
    int iv = k->periodic ? n : n - 1;
    put(b, "{\"samples\": [");
    for (int i = 0; i < n; i++) {
        double v = v0 + (v1 - v0) * i / iv;
        put(b, "%s[%.17g, %.17g, %.17g]", i ? ", " : "", P(k, 0, u, v), P(k, 1, u, v), P(k, 2, u, v));
    }
    put(b, "]}");
}

static char *make_json(const ocase *k)
{
    sbuf b = {NULL, 0, 0};
    put(&b, "{\"continuity\": \"ODE\", \"shape\": [%g, %g, %g], \"periodic\": %s, \"v_range\": [%g, %g], ", SHAPE[0],
        SHAPE[1], SHAPE[2], k->periodic ? "true" : "false", k->periodic ? 0.0 : OV0, k->periodic ? 1.0 : OV1);
    put(&b, "\"curves\": {\"c1\": ");
    put_curve(&b, k, 0);
    put(&b, ", \"c4\": ");
    put_curve(&b, k, 1);
    if (k->controls) {
        put(&b, ", \"controls\": [");
        for (int q = 0; q < 4; q++) {
            put(&b, "%s{\"u\": %g, \"curve\": ", q ? ", " : "", U_SLOT[2 + q]);
            put_curve(&b, k, 2 + q);
            put(&b, "}");
        }
        put(&b, "]");
    } else {
        put(&b, ", \"w\": [0.5, -1.0, 0.8, 2.0]");
    }
    put(&b, "}}");
    return b.p;
}

/* ---- the same surface through the C API (c2b_odesurf_input with sampled curves) ---- */

typedef struct pctx {
    const ocase *k;
    int c;
    double u;
} pctx;

static double pfn(void *ctx, double v, double t)
{
    (void)t;
    const pctx *p = ctx;
    return P(p->k, p->c, p->u, v);
}

typedef struct capi {
    pctx ctx[6][3];
    double *samples[6];
    c2b_odesurf *os;
    c2b_blend *b;
} capi;

static int capi_solve(const ocase *k, capi *a)
{
    c2b_odesurf_input in;
    c2b_error err;
    memset(&in, 0, sizeof in);
    memset(a, 0, sizeof *a);
    in.approach = k->controls ? C2B_ODESURF_CONTROLS : C2B_ODESURF_MULTIPLES;
    double w[4] = {0.5, -1.0, 0.8, 2.0};
    memcpy(in.w, w, sizeof w);
    for (int q = 0; q < 4; q++)
        in.uc[q] = U_SLOT[2 + q];
    memcpy(in.shape, SHAPE, sizeof SHAPE);
    in.dom.v0 = k->periodic ? 0 : OV0, in.dom.v1 = k->periodic ? 1 : OV1, in.dom.periodic = k->periodic;
    for (int slot = 0; slot < 6; slot++) {
        c2b_curve *cv = slot == 0 ? &in.c1 : slot == 1 ? &in.c4 : &in.control[slot - 2];
        int n = k->nsamp[slot];
        if (!n) {
            for (int c = 0; c < 3; c++) {
                a->ctx[slot][c] = (pctx){k, c, U_SLOT[slot]};
                cv->fn[c] = pfn, cv->ctx[c] = &a->ctx[slot][c];
            }
            continue;
        }
        a->samples[slot] = malloc((size_t)n * 3 * sizeof(double));
        int iv = k->periodic ? n : n - 1;
        for (int i = 0; i < n; i++)
            for (int c = 0; c < 3; c++)
                a->samples[slot][3 * i + c] = P(k, c, U_SLOT[slot], in.dom.v0 + (in.dom.v1 - in.dom.v0) * i / iv);
        cv->samples = a->samples[slot], cv->n_samples = n;
    }
    if (c2b_odesurf_create(&in, &a->os, &err) || c2b_blend_create(c2b_odesurf_problem(a->os), &a->b, &err)) {
        printf("  C API failed: %s\n", err.msg);
        return 0;
    }
    return 1;
}

static void capi_free(capi *a)
{
    c2b_blend_destroy(a->b);
    c2b_odesurf_destroy(a->os);
    for (int s = 0; s < 6; s++)
        free(a->samples[s]);
}

/* ---- solving specs and comparing ---- */

#define NU 11
#define NVE 401 /* dense in v: the open-range error peaks in the first and last intervals */

typedef struct solved {
    c2b_spec *sp;
    c2b_blend *b;
    double T; /* truncation of the data reported by the blend */
} solved;

static int solve_json(const char *js, solved *out)
{
    c2b_error err;
    memset(out, 0, sizeof *out);
    if (c2b_spec_parse(js, strlen(js), &out->sp, &err) || c2b_blend_create(c2b_spec_problem(out->sp), &out->b, &err)) {
        printf("  spec failed: %s\n", err.msg);
        return 0;
    }
    out->T = c2b_blend_truncation_error(out->b);
    return 1;
}

static int solve(const ocase *k, solved *out)
{
    char *js = make_json(k);
    int ok = solve_json(js, out);
    free(js);
    return ok;
}

static void unsolve(solved *s)
{
    c2b_blend_destroy(s->b);
    c2b_spec_destroy(s->sp);
}

/* K(u_i) = sum_p |H_p(u_i)|, from the collocation oracle (unit data d = e_p) */
static int transfer_sum(const double *u, double *K)
{
    double cc[4] = {SHAPE[0], SHAPE[1], SHAPE[2], 0}, g[NU * 4];
    for (int i = 0; i < NU; i++)
        K[i] = 0;
    for (int p = 0; p < 6; p++) {
        double d[6] = {0};
        d[p] = 1;
        if (oracle_cheb_bvp(3, cc, -1, NULL, d, 0, NU, u, g, NULL))
            return 0;
        for (int i = 0; i < NU; i++)
            K[i] += fabs(g[4 * i]);
    }
    return 1;
}

/* max |S_a - S_b| over u x v, and the largest ratio |S_a - S_b| / (K(u) T) */
static void compare(const c2b_blend *a, const c2b_blend *b, double T, double *dmax, double *ratio)
{
    static double u[NU], v[NVE], K[NU], sa[NU * NVE * 3], sb[NU * NVE * 3];
    c2b_error err;
    c2b_vdomain dom = c2b_blend_domain(a);
    for (int i = 0; i < NU; i++)
        u[i] = i / (NU - 1.0);
    for (int j = 0; j < NVE; j++)
        v[j] = dom.v0 + (dom.v1 - dom.v0) * (j + 0.5) / NVE;
    if (!transfer_sum(u, K) || c2b_blend_eval_grid(a, NU, u, NVE, v, 0, sa, &err) ||
        c2b_blend_eval_grid(b, NU, u, NVE, v, 0, sb, &err)) {
        *dmax = *ratio = INFINITY;
        return;
    }
    *dmax = 0, *ratio = 0;
    for (int i = 0; i < NU; i++)
        for (int j = 0; j < NVE; j++)
            for (int c = 0; c < 3; c++) {
                double d = fabs(sa[(i * NVE + j) * 3 + c] - sb[(i * NVE + j) * 3 + c]);
                *dmax = fmax(*dmax, d);
                *ratio = fmax(*ratio, d / (K[i] * T));
            }
}

static void name_case(const ocase *k, char *buf, size_t n)
{
    int ns = 0, ne = 0, nlo = 1 << 30, nhi = 0;
    for (int s = 0; s < (k->controls ? 6 : 2); s++) {
        if (!k->nsamp[s]) {
            ne++;
            continue;
        }
        ns++;
        nlo = k->nsamp[s] < nlo ? k->nsamp[s] : nlo;
        nhi = k->nsamp[s] > nhi ? k->nsamp[s] : nhi;
    }
    char cnt[32];
    if (nlo == nhi)
        snprintf(cnt, sizeof cnt, "n = %d", nlo);
    else
        snprintf(cnt, sizeof cnt, "n = %d and %d", nlo, nhi);
    snprintf(buf, n, "%s, %s: %d sampled (%s), %d expressions", k->periodic ? "periodic" : "open",
             k->controls ? "controls" : "w multiples", ns, cnt, ne);
}

/* ---- bad input ---- */

/* {"samples": [...]} with n points on a circle; row `bad` (if >= 0) replaced by text */
static void put_ring(sbuf *b, int n, int bad, const char *text)
{
    put(b, "{\"samples\": [");
    for (int i = 0; i < n; i++) {
        if (i == bad)
            put(b, "%s%s", i ? ", " : "", text);
        else
            put(b, "%s[%.6f, %.6f, 0]", i ? ", " : "", cos(2 * C2B_PI * i / n), sin(2 * C2B_PI * i / n));
    }
    put(b, "]}");
}

static int expect_spec_error(const char *what, const char *js, c2b_status code, const char *frag)
{
    c2b_spec *sp = NULL;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_status st = c2b_spec_parse(js, strlen(js), &sp, &err);
    printf("  -> %s\n", st ? err.msg : "(accepted)");
    c2b_spec_destroy(sp);
    char lab[256];
    snprintf(lab, sizeof lab, "%s: message names '%s'", what, frag);
    return check_true(lab, st == code && strstr(err.msg, frag) != NULL);
}

static const char *EXPR_CURVE = "[\"cos(2*pi*v)\", \"sin(2*pi*v)\", \"1\"]";

/* a controls spec whose curve `slot` is `curve` (the others valid samples or expressions) */
static char *spec_with(int periodic, int slot, const char *curve)
{
    sbuf b = {NULL, 0, 0};
    int n = periodic ? 8 : 9;
    put(&b, "{\"continuity\": \"ODE\", \"periodic\": %s, \"curves\": {\"c1\": ", periodic ? "true" : "false");
    slot == 0 ? put(&b, "%s", curve) : put_ring(&b, n, -1, NULL);
    put(&b, ", \"c4\": ");
    slot == 1 ? put(&b, "%s", curve) : put(&b, "%s", EXPR_CURVE);
    put(&b, ", \"controls\": [");
    for (int q = 0; q < 4; q++) {
        put(&b, "%s{\"u\": %g, \"curve\": ", q ? ", " : "", U_SLOT[2 + q]);
        if (slot == 2 + q)
            put(&b, "%s", curve);
        else if (q % 2)
            put(&b, "%s", EXPR_CURVE);
        else
            put_ring(&b, n, -1, NULL);
        put(&b, "}");
    }
    put(&b, "]}}");
    return b.p;
}

static void bad_specs(void)
{
    struct {
        const char *what;
        int periodic, slot, n, bad;
        const char *row;  /* replaces row `bad` of an n-point ring; NULL: `curve` below */
        const char *curve;
        const char *frag;
    } cases[] = {
        {"row of 2 numbers", 1, 4, 8, 5, "[1, 2]", NULL, "curves.controls[2].curve.samples[5]: expected an array of 3 numbers"},
        {"row of 4 numbers", 0, 0, 9, 2, "[1, 2, 3, 4]", NULL, "curves.c1.samples[2]: expected an array of 3 numbers"},
        {"row not an array", 1, 5, 8, 0, "7", NULL, "curves.controls[3].curve.samples[0]: expected an array of 3 numbers"},
        {"infinite value", 1, 1, 8, 3, "[0, 1e999, 0]", NULL, "curves.c4.samples[3][1]: must be finite"},
        {"string value", 0, 3, 9, 2, "[\"x\", 0, 0]", NULL, "curves.controls[1].curve.samples[2][0]: expected a number"},
        {"too few (periodic)", 1, 0, 3, -1, NULL, NULL, "curves.c1.samples: 3 samples given, at least 4 are needed (periodic curve)"},
        {"too few (open)", 0, 2, 6, -1, NULL, NULL, "curves.controls[0].curve.samples: 6 samples given, at least 7 are needed (open curve)"},
        {"samples not an array", 1, 1, 0, -1, NULL, "{\"samples\": 5}", "curves.c4.samples: expected an array of [x, y, z]"},
        {"unknown key beside samples", 1, 0, 0, -1, NULL, "{\"samples\": [[1,0,0],[0,1,0],[-1,0,0],[0,-1,0]], \"step\": 1}",
         "curves.c1: unknown key 'step' (allowed: samples)"},
        {"curve neither expressions nor samples", 0, 1, 0, -1, NULL, "\"cos(v)\"",
         "curves.c4: expected 3 expressions [x, y, z] in v and t, or {\"samples\""},
        {"two expressions", 0, 5, 0, -1, NULL, "[\"v\", \"1\"]", "curves.controls[3].curve: expected 3 expressions"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sbuf c = {NULL, 0, 0};
        if (cases[i].curve)
            put(&c, "%s", cases[i].curve);
        else
            put_ring(&c, cases[i].n, cases[i].bad, cases[i].row);
        char *js = spec_with(cases[i].periodic, cases[i].slot, c.p);
        expect_spec_error(cases[i].what, js, C2B_ERR_SPEC, cases[i].frag);
        free(js);
        free(c.p);
    }
}

static void bad_capi(void)
{
    c2b_odesurf_input in;
    c2b_odesurf *os = NULL;
    c2b_error err;
    static double ring[17 * 3];
    for (int i = 0; i < 17; i++)
        ring[3 * i] = cos(2 * C2B_PI * i / 17), ring[3 * i + 1] = sin(2 * C2B_PI * i / 17), ring[3 * i + 2] = 0;
    pctx pc = {NULL, 0, 0};
    memset(&in, 0, sizeof in);
    in.approach = C2B_ODESURF_CONTROLS;
    in.dom.v0 = 0, in.dom.v1 = 1, in.dom.periodic = 0;
    memcpy(in.shape, SHAPE, sizeof SHAPE);
    for (int q = 0; q < 4; q++)
        in.uc[q] = U_SLOT[2 + q];
    in.c1.samples = ring, in.c1.n_samples = 17;
    in.c4.samples = ring, in.c4.n_samples = 9;
    for (int q = 0; q < 4; q++)
        in.control[q].samples = ring, in.control[q].n_samples = 7 + 2 * q;
    c2b_status st = c2b_odesurf_create(&in, &os, &err);
    check_true("C API: curves of 17, 9, 7, 9, 11, 13 samples are accepted", st == C2B_OK);
    c2b_odesurf_destroy(os);

    c2b_odesurf_input b = in;
    b.c1.fn[1] = pfn, b.c1.ctx[1] = &pc;
    st = c2b_odesurf_create(&b, &os, &err);
    printf("  -> %s\n", err.msg);
    check_true("C API: functions and samples in one curve rejected, naming curves.c1",
               st == C2B_ERR_SPEC && strstr(err.msg, "curves.c1: give functions or samples, not both"));
    b = in;
    b.control[1].n_samples = 5;
    st = c2b_odesurf_create(&b, &os, &err);
    printf("  -> %s\n", err.msg);
    check_true("C API: too few samples named",
               st == C2B_ERR_SPEC &&
                   strstr(err.msg, "curves.controls[1].curve.samples (component x): 5 samples given, at least 7"));
    static double nan_ring[17 * 3];
    memcpy(nan_ring, ring, sizeof ring);
    nan_ring[3 * 3 + 1] = NAN;
    b = in;
    b.c4.samples = nan_ring;
    st = c2b_odesurf_create(&b, &os, &err);
    printf("  -> %s\n", err.msg);
    check_true("C API: non-finite sample named",
               st == C2B_ERR_SPEC && strstr(err.msg, "curves.c4.samples (component y): sample 3 is not finite"));
    c2b_tolerances tol = c2b_tolerances_default();
    tol.max_samples = 4;
    b = in;
    b.tol = &tol;
    st = c2b_odesurf_create(&b, &os, &err);
    printf("  -> %s\n", err.msg);
    check_true("C API: more than 4 max_samples samples is a limit",
               st == C2B_ERR_LIMIT && strstr(err.msg, "curves.c1.samples (component x): 17 samples given, the limit is 16"));
    b = in;
    b.c4.samples = NULL;
    st = c2b_odesurf_create(&b, &os, &err);
    check_true("C API: a curve with neither functions nor samples is missing",
               st == C2B_ERR_SPEC && strstr(err.msg, "curves.c4: missing boundary curve"));
    b = in;
    b.approach = C2B_ODESURF_MULTIPLES;
    b.control[0].samples = nan_ring; /* approach 1 does not use the controls */
    st = c2b_odesurf_create(&b, &os, &err);
    check_true("C API: approach 1 ignores control curves", st == C2B_OK);
    c2b_odesurf_destroy(os);
}

int main(void)
{
    c2b_error err;
    /* Samples of the analytic curves against the expressions. The periodic data's
     * slowest Fourier coefficients decay like r^k, r = 1.5 - sqrt(1.25) (1/(1.5 + sin),
     * 1/(1.5 + cos)), so n samples alias r^(n/2): doubling n divides the error by
     * r^(-n/2). The open data converge with order 4 at least. */
    const double r = 1.5 - sqrt(1.25);
    static const struct {
        int periodic, controls, uneven;
        int mask[6]; /* 1: sampled, 0: expression; slots c1, c4, cb2, cb3, cb5, cb6 */
    } fam[] = {
        {1, 0, 0, {1, 1, 0, 0, 0, 0}}, /* all sampled */
        {1, 1, 0, {1, 1, 1, 1, 1, 1}},
        {0, 0, 0, {1, 1, 0, 0, 0, 0}},
        {0, 1, 0, {1, 1, 1, 1, 1, 1}},
        {1, 1, 0, {0, 1, 1, 0, 0, 1}}, /* mixed: data of samples, of expressions, of both */
        {0, 1, 0, {1, 0, 1, 1, 0, 1}},
        {0, 0, 0, {1, 0, 0, 0, 0, 0}},
        {1, 1, 1, {1, 1, 1, 1, 1, 1}}, /* all sampled, counts n and 2n */
    };
    double worst_ratio = 0, worst_capi = 0;
    for (size_t f = 0; f < sizeof fam / sizeof fam[0]; f++) {
        ocase ref = {fam[f].periodic, fam[f].controls, {0}};
        solved e;
        if (!check_true("expression reference solves", solve(&ref, &e)))
            continue;
        int levels = fam[f].periodic ? 3 : 5;
        double dprev = 0;
        for (int lev = 0; lev < levels; lev++) {
            ocase k = ref;
            int n = 16 << lev;
            for (int s = 0; s < 6; s++)
                k.nsamp[s] = fam[f].mask[s] ? (n << (fam[f].uneven && s % 2)) + !fam[f].periodic : 0;
            char what[160];
            name_case(&k, what, sizeof what);
            solved sm;
            capi a;
            memset(&a, 0, sizeof a);
            int ok = solve(&k, &sm);
            if (!check_true(what, ok && capi_solve(&k, &a))) {
                if (ok)
                    unsolve(&sm);
                capi_free(&a);
                continue;
            }
            /* T_s: the blend's own measure for data it gets as samples, the curves' for
             * data it gets as callbacks */
            double Tc = c2b_odesurf_truncation_error(a.os), Ts = fmax(sm.T, Tc), d, ratio, dc, rc;
            compare(sm.b, e.b, Ts + e.T, &d, &ratio);
            compare(sm.b, a.b, 1e-12, &dc, &rc);
            char lab[256];
            snprintf(lab, sizeof lab, "%s: |S_samples - S_expressions| <= K(u) (T_s + T_e)", what);
            printf("  |dS| %.3e, T_s %.3e (blend %.3e, curves %.3e), T_e %.3e\n", d, Ts, sm.T, Tc, e.T);
            check_le(lab, ratio, 1.0);
            worst_ratio = fmax(worst_ratio, ratio);
            worst_capi = fmax(worst_capi, dc);
            /* near T_e the reference is not more exact: its own error, a quarter of d at
             * most, leaves the order measured */
            if (dprev > 0 && d > 4 * e.T) {
                double rate = log2(dprev / d);
                if (k.periodic) {
                    double want = (n / 4) * log2(1 / r); /* r^(-n_prev/2), n_prev = n/2 */
                    snprintf(lab, sizeof lab, "%s: error / doubling is %.1f bits (r^(-%d/2) predicts %.1f)", what, rate,
                             n / 2, want);
                    check_le(lab, 0.9 * want, rate);
                } else {
                    snprintf(lab, sizeof lab, "%s: order %.2f as n doubles (4 at least expected)", what, rate);
                    check_le(lab, 3.5, rate);
                }
            }
            dprev = d;
            capi_free(&a);
            unsolve(&sm);
        }
        unsolve(&e);
    }
    printf("  largest |dS| / (K (T_s + T_e)) over all cases: %.3g\n", worst_ratio);
    check_le("C API with the same samples gives the spec's surface", worst_capi, 1e-12);

    /* the example: seed000_controls.json with its curves digitised (32 samples) or kept
     * as expressions; its curves are trigonometric polynomials of degree 1, so 32
     * samples represent them exactly and the surfaces agree to rounding */
    {
        char *je = ex_read("seed000_controls.json"), *js = ex_read("seed000_samples.json");
        solved e, sm;
        if (check_true("seed000_samples.json and seed000_controls.json solve",
                       je && js && solve_json(je, &e) && solve_json(js, &sm))) {
            double d, ratio;
            compare(sm.b, e.b, sm.T + e.T, &d, &ratio);
            printf("  |dS| %.3e, T_s %.3e, T_e %.3e\n", d, sm.T, e.T);
            check_le("seed000_samples.json = seed000_controls.json within K (T_s + T_e)", ratio, 1.0);
            check_le("... and to rounding (exact trigonometric data)", d, 1e-13);
            unsolve(&e);
            unsolve(&sm);
        }
        free(je);
        free(js);
    }

    /* a time-dependent expression curve beside sampled ones: only its data are
     * re-projected; set_time matches a fresh spec at that time */
    {
        const char *fmt = "{\"continuity\": \"ODE\", \"periodic\": true, \"time\": %g, \"curves\": {"
                          "\"c1\": [\"(1+t)*cos(2*pi*v)\", \"sin(2*pi*v)\", \"0\"], "
                          "\"c4\": {\"samples\": [[0.5, 0, 2], [0, 0.5, 2], [-0.5, 0, 2], [0, -0.5, 2]]}, "
                          "\"w\": [0.5, -1, 0.8, 2]}}";
        char j0[512], j1[512];
        snprintf(j0, sizeof j0, fmt, 0.0);
        snprintf(j1, sizeof j1, fmt, 0.7);
        solved a, b;
        if (check_true("time-dependent expression + samples solve", solve_json(j0, &a) && solve_json(j1, &b))) {
            double d, ratio;
            check_true("set_time", !c2b_blend_set_time(a.b, 0.7, &err));
            compare(a.b, b.b, 1e-13, &d, &ratio);
            check_le("set_time(0.7) = spec at t = 0.7", d, 1e-13);
            unsolve(&a);
            unsolve(&b);
        }
    }

    bad_specs();
    bad_capi();
    return test_summary("test_odesurf_samples");
}
