/*
 * Kernel benchmarks. Prints medians and ratios against a peer measured in the same
 * run; it asserts nothing about time (run with `ctest -L bench -V` or directly).
 *
 *   1. one mode's solve (exponents + boundary system + condition) vs the Chebyshev
 *      collocation oracle solving the same mode;
 *   2. thesis eqs. 127-128 blend on a 201x201 grid, separable grid evaluation vs
 *      point-by-point evaluation of the same points (the thesis reports 339 ms for
 *      its closed form);
 *   3. a new time frame of the same blend at 101x101 (re-projection + evaluation) vs
 *      building the blend afresh at that time.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "c2b_blend.h"
#include "c2b_constants.h"
#include "c2b_fit.h"
#include "c2b_mode.h"
#include "c2b_spec.h"
#include "cheb_bvp.h"

static double now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmp);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

#define REPS 31

static void bench_mode(void)
{
    double shape[4] = {1, 1, 1, 1};
    c2b_operator op;
    double t[REPS], tp[REPS];
    double t0 = now();
    for (int i = 0; i < 1000; i++)
        c2b_operator_init(&op, C2B_C2, shape, 4, NULL);
    double t_op = (now() - t0) / 1000;
    const int inner = 2000;
    for (int r = 0; r < REPS; r++) {
        t0 = now();
        for (int i = 0; i < inner; i++) {
            double k = 1 + (i % 64);
            c2b_mode *m = NULL;
            c2b_mode_create(&op, -4 * C2B_PI * C2B_PI * k * k, NULL, &m, NULL);
            c2b_mode_destroy(m);
        }
        t[r] = (now() - t0) / inner;
    }
    /* Peer: collocation of the same mode (k = 1), boundary data only. */
    double beta = -4 * C2B_PI * C2B_PI, c[4] = {1, beta, beta * beta, beta * beta * beta};
    double d[6] = {1, 0, 0, 0.5, 0, 0}, u = 0.5, out[4];
    for (int r = 0; r < REPS; r++) {
        t0 = now();
        oracle_cheb_bvp(3, c, -1, NULL, d, 32, 1, &u, out, NULL);
        tp[r] = now() - t0;
    }
    double ours = median(t, REPS), peer = median(tp, REPS);
    printf("| one C2 mode solve (exponents + 6x6 system + condition), k = 1..64 | %.3f us | "
           "target <= 2 us |\n", 1e6 * ours);
    printf("| characteristic roots (once per shape set, LAPACK dgeev) | %.3f us | |\n", 1e6 * t_op);
    printf("| peer: Chebyshev collocation of the same mode (N = 32) | %.1f us | ratio %.0fx |\n",
           1e6 * peer, peer / ours);
}

static c2b_spec *load(const char *path)
{
    c2b_spec *s = NULL;
    c2b_error err;
    if (c2b_spec_load(path, &s, &err)) {
        fprintf(stderr, "bench: %s\n", err.msg);
        exit(2);
    }
    return s;
}

static void grid(size_t n, double v0, double v1, double *u, double *v)
{
    for (size_t i = 0; i < n; i++) {
        u[i] = (double)i / (double)(n - 1);
        v[i] = v0 + (v1 - v0) * (double)i / (double)(n - 1);
    }
}

static void bench_grid(const char *spec_path)
{
    c2b_spec *s = load(spec_path);
    c2b_problem pb = *c2b_spec_problem(s);
    c2b_blend *b = NULL;
    c2b_blend_create(&pb, &b, NULL);
    enum { N = 201 };
    double *u = malloc(N * sizeof *u), *v = malloc(N * sizeof *v);
    double *out = malloc((size_t)N * N * 3 * sizeof *out);
    double *pu = malloc((size_t)N * N * sizeof *pu), *pv = malloc((size_t)N * N * sizeof *pv);
    grid(N, pb.dom.v0, pb.dom.v1, u, v);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            pu[i * N + j] = u[i];
            pv[i * N + j] = v[j];
        }
    double t[REPS], tp[REPS];
    for (int r = 0; r < REPS; r++) {
        double t0 = now();
        c2b_blend_eval_grid(b, N, u, N, v, 0, out, NULL);
        t[r] = now() - t0;
    }
    for (int r = 0; r < 7; r++) {
        double t0 = now();
        c2b_blend_eval(b, (size_t)N * N, pu, pv, 0, out, NULL);
        tp[r] = now() - t0;
    }
    double ours = median(t, REPS), peer = median(tp, 7);
    printf("| thesis eqs. 127-128 blend, 201x201 grid (separable) | %.3f ms | target <= 1 ms; "
           "thesis closed form 339 ms (%.0fx) |\n", 1e3 * ours, 0.339 / ours);
    printf("| peer: the same 40401 points evaluated one by one | %.3f ms | ratio %.1fx |\n",
           1e3 * peer, peer / ours);

    /* New time frame at 101x101 vs a fresh blend at that time. */
    enum { M = 101 };
    double *out2 = malloc((size_t)M * M * 3 * sizeof *out2);
    grid(M, pb.dom.v0, pb.dom.v1, u, v);
    for (int r = 0; r < REPS; r++) {
        double t0 = now();
        c2b_blend_set_time(b, 0.01 * (r + 1), NULL);
        c2b_blend_eval_grid(b, M, u, M, v, 0, out2, NULL);
        t[r] = now() - t0;
    }
    for (int r = 0; r < REPS; r++) {
        double t0 = now();
        c2b_problem p2 = pb;
        p2.time = 0.01 * (r + 1);
        c2b_blend *b2 = NULL;
        c2b_blend_create(&p2, &b2, NULL);
        c2b_blend_eval_grid(b2, M, u, M, v, 0, out2, NULL);
        c2b_blend_destroy(b2);
        tp[r] = now() - t0;
    }
    ours = median(t, REPS);
    peer = median(tp, REPS);
    printf("| new time frame, 101x101 (re-projection + evaluation) | %.3f ms | target <= 2 ms; "
           "%.0f frames/s |\n", 1e3 * ours, 1 / ours);
    printf("| peer: fresh blend at that time + evaluation | %.3f ms | ratio %.1fx |\n", 1e3 * peer,
           peer / ours);
    /* B-spline fit at 1e-6 of the bounding-box diagonal, at the spec's time. */
    c2b_blend_set_time(b, pb.time, NULL);
    c2b_fit_options fo = c2b_fit_options_default();
    c2b_fit_report rep;
    for (int r = 0; r < 15; r++) {
        c2b_nurbs_surface *fs = NULL;
        double t0 = now();
        c2b_fit_blend(b, &fo, &fs, &rep, NULL);
        t[r] = now() - t0;
        c2b_nurbs_surface_destroy(fs);
    }
    printf("| B-spline fit at tolerance 1e-6 (%d x %d poles, deviation %.2g) | %.2f ms | target <= 20 ms |\n",
           rep.npoles[0], rep.npoles[1], rep.deviation / rep.bbox_diagonal, 1e3 * median(t, 15));
    free(u);
    free(v);
    free(out);
    free(out2);
    free(pu);
    free(pv);
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
}

int main(int argc, char **argv)
{
    const char *spec = argc > 1 ? argv[1] : "examples/thesis_eq127_129.json";
    printf("C2Blend kernel benchmark (medians of %d runs; one core)\n\n", REPS);
    printf("| what | time | target / ratio |\n|---|---|---|\n");
    bench_mode();
    bench_grid(spec);
    return 0;
}
