/*
 * Mode solver tests. Expected values come from hand-derived closed forms (Hermite
 * bases), from the independent Chebyshev collocation oracle in tests/oracle, and from
 * the clamped-beam eigenvalue cos(l) cosh(l) = 1 for resonance.
 */
#include <complex.h>
#include <string.h>

#include "c2b_constants.h"
#include "c2b_mode.h"
#include "cheb_bvp.h"
#include "test_util.h"

static const double US[] = {0.0, 0.1, 0.37, 0.5, 0.83, 1.0};
#define NU (int)(sizeof US / sizeof *US)

/* Derivative q of sum_i c[i] u^i (hand-written, independent of c2b_poly). */
static double mono(const double *c, int deg, int q, double u)
{
    double s = 0;
    for (int i = deg; i >= q; i--) {
        double f = 1;
        for (int j = 0; j < q; j++)
            f *= i - j;
        s = s * u + f * c[i];
    }
    return s;
}

static c2b_mode *make(c2b_continuity cont, const double *shape, double beta)
{
    c2b_operator op;
    c2b_error err;
    if (c2b_operator_init(&op, cont, shape, c2b_continuity_nshape(cont), &err)) {
        printf("operator: %s\n", err.msg);
        return NULL;
    }
    c2b_mode *m = NULL;
    if (c2b_mode_create(&op, beta, NULL, &m, &err))
        printf("mode: %s\n", err.msg);
    return m;
}

/* A beta = 0 mode against a Hermite basis given by monomial coefficients. */
static void hermite_case(const char *name, c2b_continuity cont, const double *shape,
                         const double (*basis)[6], int deg, const double *d)
{
    int m2 = 2 * c2b_continuity_n(cont);
    c2b_mode *m = make(cont, shape, 0.0);
    char what[96];
    snprintf(what, sizeof what, "%s: beta=0 mode created", name);
    if (!check_true(what, m != NULL))
        return;
    for (int k = 0; k < NU; k++) {
        double G[4];
        c2b_mode_eval(m, d, US[k], 3, G);
        for (int q = 0; q <= 3; q++) {
            double want = 0;
            for (int j = 0; j < m2; j++)
                want += d[j] * mono(basis[j], deg, q, US[k]);
            snprintf(what, sizeof what, "%s G^(%d)(%.2f)", name, q, US[k]);
            check_close(what, G[q], want, 1e-12, 1e-12);
        }
    }
    c2b_mode_destroy(m);
}

static void test_hermite(void)
{
    /* Thesis eq. (18), expanded by hand into monomials. */
    static const double quintic[6][6] = {
        {1, 0, 0, -10, 15, -6},   {0, 1, 0, -6, 8, -3},    {0, 0, 0.5, -1.5, 1.5, -0.5},
        {0, 0, 0, 10, -15, 6},    {0, 0, 0, -4, 7, -3},    {0, 0, 0, 0.5, -1, 0.5}};
    /* Cubic Hermite: h00, h10, h01, h11. */
    static const double cubic[4][6] = {{1, 0, -3, 2}, {0, 1, -2, 1}, {0, 0, 3, -2}, {0, 0, -1, 1}};
    const double s4[4] = {1, 1, 1, 1}, s3[3] = {1, 1, 1};
    const double d6[6] = {0.3, -1.0, 2.0, 1.5, 0.7, -3.0}, d4[4] = {1.0, -2.0, 0.5, 4.0};
    hermite_case("quintic Hermite (C2)", C2B_C2, s4, quintic, 5, d6);
    hermite_case("cubic Hermite (C1)", C2B_C1, s3, cubic, 3, d4);
}

/* Compare with the collocation oracle: c_k = a_k beta^k computed here. */
static void against_oracle(const char *name, c2b_continuity cont, const double *shape,
                           double beta, double rtol)
{
    int n = c2b_continuity_n(cont), m2 = 2 * n;
    double c[5] = {0}, bk = 1;
    for (int k = 0; k <= n; k++) {
        double a = k < c2b_continuity_nshape(cont) ? shape[k] : 0.0;
        c[k] = cont == C2B_ODE ? a : a * bk;
        bk *= beta;
    }
    c2b_mode *m = make(cont, shape, beta);
    char what[160];
    snprintf(what, sizeof what, "%s: mode created", name);
    if (!check_true(what, m != NULL))
        return;
    const double dall[8] = {0.7, -1.3, 2.1, -0.4, 1.1, 0.9, -2.5, 0.6};
    double d[8];
    memcpy(d, dall, sizeof d);
    double ref[NU * 4];
    if (oracle_cheb_bvp(n, c, -1, NULL, d, 0, NU, US, ref, NULL)) {
        check_true("oracle solved", 0);
        c2b_mode_destroy(m);
        return;
    }
    double scale = 0;
    for (int i = 0; i < NU * 4; i++)
        scale = fmax(scale, fabs(ref[i]));
    for (int k = 0; k < NU; k++) {
        double G[4];
        c2b_mode_eval(m, d, US[k], 3, G);
        for (int q = 0; q <= 3; q++) {
            snprintf(what, sizeof what, "%s: G^(%d)(%.2f) vs collocation", name, q, US[k]);
            check_close(what, G[q], ref[k * 4 + q], 0, rtol * scale);
        }
    }
    (void)m2;
    c2b_mode_destroy(m);
}

static void test_against_collocation(void)
{
    const double b4 = -4 * C2B_PI * C2B_PI;
    double s1[4] = {1, 1, 1, 1}, s2[4] = {-1.8, 1, 1, 1}, s3[4] = {1, -7, 1, 1};
    against_oracle("C2 (1,1,1,1) beta=-4pi^2", C2B_C2, s1, b4, 1e-9);
    against_oracle("C2 (-1.8,1,1,1) beta=-4pi^2", C2B_C2, s2, b4, 1e-9);
    against_oracle("C2 (1,-7,1,1) beta=-4pi^2", C2B_C2, s3, b4, 1e-9);
    against_oracle("C2 (1,1,1,1) beta=-16pi^2", C2B_C2, s1, 4 * b4, 1e-9);
    against_oracle("C2 (1,1,1,1) beta=+4 (exponential mode)", C2B_C2, s1, 4.0, 1e-9);
    double s4[4] = {2.0, -0.5, 3.0, 0.0}; /* rho = 0: double zero root */
    against_oracle("C2 (2,-0.5,3,0) rho=0", C2B_C2, s4, b4, 1e-9);
    double c1[3] = {1, 1, 1};
    against_oracle("C1 (1,1,1) beta=-4pi^2", C2B_C1, c1, b4, 1e-9);
    double c3[5] = {1, 1, 1, 1, 1};
    against_oracle("C3 (1,1,1,1,1) beta=-4pi^2", C2B_C3, c3, b4, 1e-9);
    double ode[3] = {1, 1, 1};
    against_oracle("ODE (rho,eta,lambda)=(1,1,1)", C2B_ODE, ode, b4, 1e-9);
    double ode2[3] = {1, -3, 0.5};
    against_oracle("ODE (1,-3,0.5)", C2B_ODE, ode2, 0.0, 1e-9);
}

/* Seed 001's b=1, c=2, d=1 has 4bd = c^2: double roots. */
static void test_repeated_roots(void)
{
    double s[3] = {1, 2, 1};
    c2b_mode *m = make(C2B_C1, s, -4 * C2B_PI * C2B_PI);
    if (m) {
        check_true("4bd=c^2: exponents grouped into repeated-root clusters",
                   c2b_mode_repeated_clusters(m) == 2);
        c2b_mode_destroy(m);
    }
    against_oracle("C1 (1,2,1) repeated roots beta=-4pi^2", C2B_C1, s, -4 * C2B_PI * C2B_PI, 1e-9);
    against_oracle("C1 (1,2,1) repeated roots beta=+9", C2B_C1, s, 9.0, 1e-9);
    double s2[4] = {1, 3, 3, 1}; /* (w+1)^3: triple root */
    against_oracle("C2 (1,3,3,1) triple root beta=-4pi^2", C2B_C2, s2, -4 * C2B_PI * C2B_PI, 1e-9);
}

/* Roots w = -1 +- eps with beta = -100 give exponent pairs about 10 eps apart: both
 * sides of the cluster tolerance (1.0) and far inside it. */
static void test_near_repeated(void)
{
    static const double eps[] = {0.099, 0.101, 1e-3, 1e-6, 1e-9, 1e-12};
    int clusters[6];
    for (int i = 0; i < 6; i++) {
        double s[3] = {1, 2, 1 - eps[i] * eps[i]};
        c2b_mode *m = make(C2B_C1, s, -100.0);
        clusters[i] = m ? c2b_mode_repeated_clusters(m) : -1;
        c2b_mode_destroy(m);
        char name[96];
        snprintf(name, sizeof name, "C1 near-repeated eps=%g", eps[i]);
        against_oracle(name, C2B_C1, s, -100.0, 1e-9);
    }
    check_true("eps=0.099 is clustered and eps=0.101 is not (tolerance straddled)",
               clusters[0] > clusters[1]);
}

static void test_high_frequency(void)
{
    double s[4] = {1, 1, 1, 1};
    static const int ks[] = {50, 200, 2000};
    for (int i = 0; i < 3; i++) {
        double w = 2 * C2B_PI * ks[i], beta = -w * w;
        c2b_mode *m = make(C2B_C2, s, beta);
        char what[128];
        snprintf(what, sizeof what, "k=%d: mode created without overflow", ks[i]);
        if (!check_true(what, m != NULL))
            continue;
        snprintf(what, sizeof what, "k=%d: condition estimate", ks[i]);
        check_le(what, c2b_mode_condition(m), 1e3);
        const double d[6] = {1.0, -2.0, 3.0, 0.5, 4.0, -1.0};
        double G0[4], G1[4], Gm[4];
        c2b_mode_eval(m, d, 0.0, 3, G0);
        c2b_mode_eval(m, d, 1.0, 3, G1);
        c2b_mode_eval(m, d, 0.5, 3, Gm);
        for (int p = 0; p < 3; p++) {
            double nat = pow(w, p) * 4.0; /* natural scale of the p-th derivative */
            snprintf(what, sizeof what, "k=%d: G^(%d)(0) = datum", ks[i], p);
            check_close(what, G0[p], d[p], 0, 1e-12 * nat);
            snprintf(what, sizeof what, "k=%d: G^(%d)(1) = datum", ks[i], p);
            check_close(what, G1[p], d[3 + p], 0, 1e-12 * nat);
        }
        /* Boundary layers of width ~1/(0.7 w): the middle is exponentially small. */
        snprintf(what, sizeof what, "k=%d: |G(0.5)| decays like exp(-0.35 w)", ks[i]);
        check_le(what, fabs(Gm[0]), 100 * exp(-0.35 * w));
        c2b_mode_destroy(m);
    }
}

/* C1 with c = 0: b G'''' + d beta^2 G = 0. With beta = -4 pi^2 and
 * d = -l^4 / (16 pi^4), G'''' = l^4 G: clamped-clamped beam, singular when
 * cos(l) cosh(l) = 1, first root l = 4.730040744862704. */
static void test_resonance(void)
{
    const double l = 4.730040744862704, beta = -4 * C2B_PI * C2B_PI;
    const double d0 = -pow(l, 4) / (16 * pow(C2B_PI, 4));
    c2b_operator op;
    c2b_error err;
    static const double rel[] = {0.0, 1e-13, -1e-13, 1e-3, -1e-3};
    for (int i = 0; i < 5; i++) {
        double s[3] = {1, 0, d0 * (1 + rel[i])};
        c2b_operator_init(&op, C2B_C1, s, 3, &err);
        c2b_mode *m = NULL;
        c2b_status st = c2b_mode_create(&op, beta, NULL, &m, &err);
        char what[160];
        if (fabs(rel[i]) < 1e-9) {
            snprintf(what, sizeof what, "resonant d*(1%+g): C2B_ERR_NUMERIC", rel[i]);
            check_true(what, st == C2B_ERR_NUMERIC && m == NULL);
            snprintf(what, sizeof what, "resonant d*(1%+g): message names beta and shape", rel[i]);
            check_true(what, strstr(err.msg, "resonant") && strstr(err.msg, "beta=-39.47") &&
                                 strstr(err.msg, "d=-0.3211"));
            printf("     message: %s\n", err.msg);
        } else {
            snprintf(what, sizeof what, "near-resonant d*(1%+g) solves", rel[i]);
            check_true(what, st == C2B_OK);
            char name[96];
            snprintf(name, sizeof name, "near-resonant d*(1%+g)", rel[i]);
            against_oracle(name, C2B_C1, s, beta, 1e-6);
        }
        c2b_mode_destroy(m);
    }
    /* Independent confirmation that the exact value is singular. */
    double c[3] = {1, 0, d0 * beta * beta}, dd[4] = {1, 0, 0, 0}, out[4], cond = 0;
    double u = 0.5;
    int rc = oracle_cheb_bvp(2, c, -1, NULL, dd, 0, 1, &u, out, &cond);
    check_true("collocation confirms the clamped-beam resonance (cond > 1e10)", rc != 0 || cond > 1e10);
}

static void test_bad_operator(void)
{
    c2b_operator op;
    c2b_error err;
    double s[4] = {0, 1, 1, 1};
    check_true("gamma = 0 rejected", c2b_operator_init(&op, C2B_C2, s, 4, &err) == C2B_ERR_SPEC &&
                                         strstr(err.msg, "gamma"));
    double s2[4] = {1, NAN, 1, 1};
    check_true("NaN eta rejected", c2b_operator_init(&op, C2B_C2, s2, 4, &err) == C2B_ERR_SPEC &&
                                       strstr(err.msg, "eta"));
    check_true("wrong count rejected", c2b_operator_init(&op, C2B_C2, s, 3, &err) == C2B_ERR_SPEC);
    double s3[4] = {1, 1, 1, 1};
    c2b_operator_init(&op, C2B_C2, s3, 4, &err);
    /* w^3 + w^2 + w + 1 = (w + 1)(w^2 + 1) */
    int found[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        found[0] |= cabs(op.w[i] + 1) < 1e-14;
        found[1] |= cabs(op.w[i] - I) < 1e-14;
        found[2] |= cabs(op.w[i] + I) < 1e-14;
    }
    check_true("roots of w^3+w^2+w+1 are -1, i, -i", found[0] && found[1] && found[2]);
}

int main(void)
{
    test_hermite();
    test_against_collocation();
    test_repeated_roots();
    test_near_repeated();
    test_high_frequency();
    test_resonance();
    test_bad_operator();
    return test_summary("test_mode");
}
