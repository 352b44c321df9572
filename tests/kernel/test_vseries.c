/*
 * Boundary data to modes: exact structures are recognised exactly, band-limited
 * periodic data are exact, and the reported truncation error is honest (the true
 * error at fresh points, computed from the function itself, never exceeds it by much).
 */
#include <string.h>

#include "c2b_blend.h"
#include "c2b_constants.h"
#include "c2b_vseries.h"
#include "test_util.h"

typedef double (*fn1)(double);
static double fpoly(double v) { return 1.5 - 2 * v + 0.25 * v * v * v * v * v; }
static double fexp(double v) { return 3 * exp(2.5 * v) - cosh(2.5 * v); }
static double fcos(double v) { return cos(3.7 * v + 0.3); }
static double fband(double v)
{
    return 0.3 + cos(2 * C2B_PI * v) - 0.5 * sin(6 * C2B_PI * v) + 1e-3 * cos(80 * C2B_PI * v);
}
static double fsmooth(double v) { return exp(cos(3 * v)); }
static double fsmooth_vv(double v)
{
    double c = cos(3 * v), s = sin(3 * v);
    return exp(c) * (9 * s * s - 9 * c);
}

static double call(void *ctx, double v, double t)
{
    (void)t;
    return ((fn1)ctx)(v);
}

static double call_vv(void *ctx, double v, double t)
{
    (void)ctx;
    (void)t;
    return fsmooth_vv(v);
}

/* Largest |series - f| over 997 fresh points. */
static double true_error(const c2b_vseries *s, const c2b_vdomain *d, fn1 f)
{
    double e = 0;
    for (int i = 0; i <= 996; i++) {
        double v = d->v0 + (d->v1 - d->v0) * (i + 0.5 * sqrt(2.0) - 0.7) / 996.0, y;
        if (v < d->v0 || v > d->v1)
            continue;
        c2b_vseries_eval(s, d, v, 0, &y);
        e = fmax(e, fabs(y - f(v)));
    }
    return e;
}

static void project(const char *name, fn1 f, c2b_vt_fn vv, c2b_vdomain d, c2b_vmethod want,
                    double max_true)
{
    c2b_vseries s;
    memset(&s, 0, sizeof s);
    c2b_error err;
    c2b_status st = c2b_vseries_project(&d, call, vv, (void *)f, 0.0, NULL, &s, &err);
    char what[160];
    snprintf(what, sizeof what, "%s: projected", name);
    if (!check_true(what, st == C2B_OK)) {
        printf("     %s\n", err.msg);
        return;
    }
    snprintf(what, sizeof what, "%s: method %s (got %s, %d terms, %d samples)", name,
             c2b_vmethod_name(want), c2b_vmethod_name(s.method), s.n, s.n_samples);
    check_true(what, s.method == want);
    double te = true_error(&s, &d, f);
    snprintf(what, sizeof what, "%s: true error at fresh points", name);
    check_le(what, te, max_true);
    snprintf(what, sizeof what, "%s: reported error %.3g is honest (true <= 10 x reported + 1e-14 scale)",
             name, s.err_abs);
    check_true(what, te <= 10 * s.err_abs + 1e-14 * s.scale);
    c2b_vseries_clear(&s);
}

static void test_structures(void)
{
    c2b_vdomain open = {-0.5, 1.7, 0}, per = {0, 1, 1};
    project("quintic polynomial (open)", fpoly, NULL, open, C2B_VM_POLY, 1e-13);
    project("quintic polynomial (periodic)", fpoly, NULL, per, C2B_VM_POLY, 1e-13);
    project("3 exp(2.5v) - cosh(2.5v): f''=6.25 f", fexp, NULL, open, C2B_VM_MODE, 1e-12);
    project("cos(3.7v + 0.3): f''=-13.69 f", fcos, NULL, open, C2B_VM_MODE, 1e-13);
    project("band-limited periodic, harmonics 0..40", fband, NULL, per, C2B_VM_FFT, 1e-14);
    c2b_vdomain open2 = {0, 2, 0};
    /* cubic + DST: coefficients decay like k^-5, so 16385 samples give ~1e-11 */
    project("exp(cos 3v), open, exact v''", fsmooth, call_vv, open2, C2B_VM_DST, 1e-11);
    project("exp(cos 3v), open, finite-difference v''", fsmooth, NULL, open2, C2B_VM_DST, 1e-9);
    c2b_vdomain per2 = {0, 2 * C2B_PI / 3, 1};
    project("exp(cos 3v), periodic", fsmooth, NULL, per2, C2B_VM_FFT, 1e-13);
}

/* Samples of exp(cos 3v) on the open range [0, 2]: the reported error of n samples,
 * even and odd n, bounds the true error between samples (fresh points). */
static void test_sample_error_estimate(void)
{
    c2b_vdomain d = {0, 2, 0};
    static const int counts[] = {32, 33, 64};
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        int n = counts[c];
        double smp[64];
        for (int i = 0; i < n; i++)
            smp[i] = fsmooth(2.0 * i / (n - 1));
        c2b_vseries s;
        memset(&s, 0, sizeof s);
        c2b_error err;
        char what[160];
        snprintf(what, sizeof what, "%d samples (open range): expanded", n);
        if (!check_true(what, c2b_vseries_project_samples(&d, smp, 1, n, NULL, &s, &err) == C2B_OK))
            continue;
        double te = true_error(&s, &d, fsmooth);
        snprintf(what, sizeof what, "%d samples (open range): reported error %.3g bounds the true %.3g",
                 n, s.err_abs, te);
        check_true(what, te > 1e-9 && te <= s.err_abs);
        c2b_vseries_clear(&s);
    }
}

static void test_bad_samples(void)
{
    double s[8] = {0, 1, 2, NAN, 4, 5, 6, 7};
    c2b_vdomain d = {0, 1, 0};
    c2b_vseries out;
    memset(&out, 0, sizeof out);
    c2b_error err;
    check_true("NaN sample rejected, index named",
               c2b_vseries_project_samples(&d, s, 1, 8, NULL, &out, &err) == C2B_ERR_SPEC &&
                   strstr(err.msg, "sample 3"));
    check_true("too few samples rejected", c2b_vseries_project_samples(&d, s, 1, 3, NULL, &out, &err) ==
                                               C2B_ERR_SPEC);
    c2b_vseries_clear(&out);
}

/* High-frequency boundary data: k = 200 on a closed trimline, end to end. */
static double hf(void *ctx, double v, double t)
{
    (void)ctx;
    (void)t;
    return cos(400 * C2B_PI * v) + 0.5 * sin(2 * C2B_PI * v);
}

static void test_k200_blend(void)
{
    c2b_problem pb = c2b_problem_default();
    pb.dom.periodic = 1;
    for (int c = 0; c < 3; c++) {
        pb.data[c][0][0].fn = hf;
        pb.data[c][0][0].label = "k200";
    }
    c2b_blend *b = NULL;
    c2b_error err;
    if (!check_true("k=200 blend created", c2b_blend_create(&pb, &b, &err) == C2B_OK)) {
        printf("     %s\n", err.msg);
        return;
    }
    double res[6], sc[6];
    c2b_blend_boundary_residual(b, 1001, res, sc, NULL);
    check_le("k=200: S(0,v) reproduced (abs, 1001 points)", res[0], 1e-12);
    check_le("k=200: S_u(0,v) = 0 reproduced relative to the mode scale 400 pi", res[1], 1e-12 * 400 * C2B_PI);
    check_le("k=200: S_uu(0,v) = 0 reproduced relative to (400 pi)^2", res[2], 1e-12 * pow(400 * C2B_PI, 2));
    check_le("k=200: condition estimate", c2b_blend_max_condition(b), 1e3);
    double u = 0.5, v = 0.0, o[3];
    c2b_blend_eval(b, 1, &u, &v, 0, o, NULL);
    check_true("k=200: finite in the interior", isfinite(o[0]));
    c2b_blend_destroy(b);
}

int main(void)
{
    test_structures();
    test_sample_error_estimate();
    test_bad_samples();
    test_k200_blend();
    return test_summary("test_vseries");
}
