/*
 * Minimal test helpers: every check prints what it compared, so a failing run shows
 * the numbers. No assert(): checks stay active under NDEBUG.
 */
#ifndef C2B_TEST_UTIL_H
#define C2B_TEST_UTIL_H

#include <math.h>
#include <stdio.h>

static int t_failed = 0, t_passed = 0;

/* |got - want| <= atol + rtol * |want| */
static inline int check_close(const char *what, double got, double want, double rtol, double atol)
{
    double e = fabs(got - want);
    int ok = isfinite(got) && e <= atol + rtol * fabs(want);
    printf("%s %s: got %.17g want %.17g (abs err %.3g, tol %.3g)\n", ok ? "ok  " : "FAIL", what, got,
           want, e, atol + rtol * fabs(want));
    ok ? t_passed++ : t_failed++;
    return ok;
}

static inline int check_true(const char *what, int cond)
{
    printf("%s %s\n", cond ? "ok  " : "FAIL", what);
    cond ? t_passed++ : t_failed++;
    return cond;
}

/* value <= limit */
static inline int check_le(const char *what, double value, double limit)
{
    int ok = value <= limit;
    printf("%s %s: %.6g <= %.6g\n", ok ? "ok  " : "FAIL", what, value, limit);
    ok ? t_passed++ : t_failed++;
    return ok;
}

static inline int test_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, t_passed, t_failed);
    return t_failed != 0 || t_passed == 0;
}

#endif
