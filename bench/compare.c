/*
 * bench/compare: the papers' own solvers beside C2Blend's exact closed form (issue 6).
 * Prints markdown tables; with --markdown FILE also writes them (atomically) to FILE,
 * which is how docs/RESULTS.md is produced:
 *   build/bench/compare --markdown docs/RESULTS.md      (or: make results)
 * Tables:
 *  1. thesis Table 3 (eqs. 127-129, t = 0.1) and Table 1 (eqs. 87-88, t = 0.2) analogues:
 *     thesis-approx at M = 10, 15, 20 against the exact closed form, errors E1-E4
 *     (thesis section 3.3.2.1) on 101 x 101 vertices, times at 51^2 .. 201^2 vertices;
 *  2. seed 001 section 3: pseudo-Navier (M = N = 3, 49 points), the Fourier-series method
 *     (eqs. 20-21) and the pseudo-spectral method (eqs. 22-23) against the closed form,
 *     error eq. 24 on 100 x 100 points;
 *  3. speed and accuracy ratios exact vs thesis-approx M = 20 against an independent
 *     Chebyshev-collocation reference (tests/oracle), and frames per second of a
 *     time-dependent blend with 64 modes at 101^2.
 * Times are medians of repeated runs (wall clock, CLOCK_MONOTONIC), solve + evaluation.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <time.h>

#include "approx_examples.h"
#include "c2b_atomic.h"
#include <lapacke.h>

typedef struct out {
    FILE *md; /* may be NULL */
} out;

static void emit(out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    if (o->md) {
        va_start(ap, fmt);
        vfprintf(o->md, fmt, ap);
        va_end(ap);
    }
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmpd);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

static int g_reps = 9;

/* Creates the blend of pb g_reps times; the median time (s) goes to *secs and the last
 * blend to *out (NULL on failure; the caller destroys it). Returns the last status. */
static c2b_status timed_blend_create(const c2b_problem *pb, c2b_blend **out, double *secs,
                                     c2b_error *err)
{
    double t[64];
    c2b_status st = C2B_OK;
    *out = NULL;
    for (int r = 0; r < g_reps; r++) {
        c2b_blend_destroy(*out);
        *out = NULL;
        double t0 = now();
        st = c2b_blend_create(pb, out, err);
        t[r] = now() - t0;
    }
    *secs = median(t, g_reps);
    return st;
}

/* median time (s) of: create + evaluate an n x n grid, for the exact blend (M = 0) or
 * thesis-approx with M terms */
static double time_solve(const c2b_problem *pb, const ex_thesis *x, int M, int n)
{
    double *u = malloc(sizeof(double) * n), *v = malloc(sizeof(double) * n);
    double *buf = malloc(sizeof(double) * 3 * (size_t)n * n), t[64];
    ex_linspace((size_t)n, 0, 1, u);
    ex_linspace((size_t)n, 0, 1, v);
    for (int r = 0; r < g_reps; r++) {
        double t0 = now();
        if (M == 0) {
            c2b_blend *b = NULL;
            c2b_blend_create(pb, &b, NULL);
            c2b_blend_eval_grid(b, (size_t)n, u, (size_t)n, v, 0, buf, NULL);
            c2b_blend_destroy(b);
        } else {
            c2b_approx_options o = c2b_approx_options_default();
            o.M = M;
            c2b_approx *a = NULL;
            c2b_approx_create(x->shape, &x->dom, &x->vd, x->t, &o, &a, NULL);
            c2b_approx_eval_grid(a, (size_t)n, u, (size_t)n, v, 0, buf, NULL);
            c2b_approx_destroy(a);
        }
        t[r] = now() - t0;
    }
    free(u);
    free(v);
    free(buf);
    return median(t, g_reps);
}

/* The thesis' published Table 3 / Table 1 values: rows E1..E4 (Table 1 lists AME, AAE,
 * RME, RAE = E1, E2, E3, E4), then times at 51^2..201^2 (Table 1: one time). */
static const double pub3[4][3] = {{4.35e-2, 3.17e-3, 2.22e-5}, {1.82e-2, 1.31e-3, 1.10e-5},
                                  {1.11e-2, 8.06e-4, 5.64e-6}, {4.63e-3, 3.34e-4, 2.80e-6}};
static const double pub3t[4][4] = {{35, 60, 98, 47}, {69, 112, 197, 109}, {118, 184, 288, 187}, {183, 269, 394, 339}};
static const double pub1[4][3] = {{4.55e-2, 4.85e-3, 6.40e-5}, {1.71e-2, 1.65e-3, 1.79e-5},
                                  {2.11e-2, 2.25e-3, 2.97e-5}, {7.95e-3, 7.65e-4, 8.31e-6}};
static const double pub1t[4] = {28.84, 59.87, 108.22, 14.88};

#define NE 101

static int thesis_table(out *o, int which)
{
    static const char *files[2] = {"thesis_eq127_129.json", "thesis_eq087_088.json"};
    ex_thesis x;
    ex_thesis_init(&x, which);
    c2b_spec *sp = ex_spec(files[which], NULL, NULL);
    c2b_blend *b = NULL;
    c2b_error err;
    if (!sp || c2b_blend_create(c2b_spec_problem(sp), &b, &err)) {
        fprintf(stderr, "compare: %s does not solve\n", files[which]);
        return 1;
    }
    static double u[NE], v[NE], ref[NE * NE * 3], app[3][NE * NE * 3];
    ex_linspace(NE, 0, 1, u);
    ex_linspace(NE, 0, 1, v);
    c2b_blend_eval_grid(b, NE, u, NE, v, 0, ref, &err);
    double e[3][5];
    static const int Ms[3] = {10, 15, 20};
    for (int k = 0; k < 3; k++) {
        c2b_approx_options op = c2b_approx_options_default();
        op.M = Ms[k];
        c2b_approx *a = NULL;
        if (c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &op, &a, &err)) {
            fprintf(stderr, "compare: %s\n", err.msg);
            return 1;
        }
        c2b_approx_eval_grid(a, NE, u, NE, v, 0, app[k], &err);
        ex_thesis_errors(NE, NE, app[k], ref, e[k]);
        c2b_approx_destroy(a);
    }
    const double(*pub)[3] = which ? pub1 : pub3;
    emit(o, "\n### %s analogue: %s at t = %.1f\n\n", which ? "Thesis Table 1" : "Thesis Table 3",
         which ? "eqs. 87-88 (two elliptic cylinders)" : "eqs. 127-129 (two elliptic cones)", x.t);
    emit(o, "thesis-approx (%s, I = J = 100) against C2Blend's exact closed form; errors on 101 x 101 "
            "vertices, D = %.4f (largest distance between two points of equal u). Published values in "
            "brackets.\n\n",
         "section 3.4.1, eq. 120", e[0][4]);
    emit(o, "| | M = 10 | M = 15 | M = 20 | exact (CFS) |\n|---|---|---|---|---|\n");
    static const char *names[4] = {"E1 (abs. max)", "E2 (abs. mean)", "E3 (rel. max)", "E4 (rel. mean)"};
    for (int r = 0; r < 4; r++) {
        emit(o, "| %s |", names[r]);
        for (int k = 0; k < 3; k++)
            emit(o, " %.3g (%.3g) |", e[k][r], pub[r][k]);
        emit(o, " 0 (0) |\n");
    }
    static const int ns[4] = {51, 101, 151, 201};
    for (int r = 0; r < 4; r++) {
        emit(o, "| T (ms), %dx%d |", ns[r], ns[r]);
        for (int k = 0; k <= 3; k++) {
            double tm = 1e3 * time_solve(c2b_spec_problem(sp), &x, k < 3 ? Ms[k] : 0, ns[r]);
            if (which == 0)
                emit(o, " %.3g (%.0f) |", tm, pub3t[r][k]);
            else if (r == 1)
                emit(o, " %.3g (%.2f) |", tm, pub1t[k]);
            else
                emit(o, " %.3g (—) |", tm);
        }
        emit(o, "\n");
    }
    emit(o, "\nConvergence from M = 10 to M = 20: E4 falls %.3gx here, %.0fx in the thesis.\n",
         e[0][3] / e[2][3], pub[3][0] / pub[3][2]);
    /* A check that needs no reference: for any surface R, max|S15 - S20| <= E1(15) +
     * E1(20) (triangle inequality), so the published E1 bound how far apart this
     * method's M = 15 and M = 20 surfaces may be, whatever reference the thesis used. */
    double d[5];
    ex_thesis_errors(NE, NE, app[1], app[2], d);
    emit(o, "Without any reference: the M = 15 and M = 20 surfaces here lie up to %.3g apart "
            "(mean %.3g). Whatever the reference, the published E1 allow at most %.3g (E1(15) + "
            "E1(20)), and the published E2 a mean of at most %.3g.\n",
         d[0], d[1], pub[0][1] + pub[0][2], pub[1][1] + pub[1][2]);
    c2b_blend_destroy(b);
    c2b_spec_destroy(sp);
    return 0;
}

#define NS 100

static int seed001_table(out *o)
{
    c2b_error err;
    c2b_spec *full = ex_spec("seed001_eq17.json", NULL, NULL);
    c2b_spec *grp1 = ex_spec("seed001_eq17.json", "\"a2\": 0.000102", "\"a2\": 0.0");
    c2b_blend *bf = NULL, *b1 = NULL;
    if (!full || !grp1 || c2b_blend_create(c2b_spec_problem(full), &bf, &err) ||
        c2b_blend_create(c2b_spec_problem(grp1), &b1, &err)) {
        fprintf(stderr, "compare: seed001_eq17.json does not solve\n");
        return 1;
    }
    ex_seed001 ex;
    ex_seed001_init(&ex);
    static double u[NS], v[NS], ref[NS * NS * 3], part[NS * NS * 3], app[NS * NS * 3];
    ex_linspace(NS, 0, 1, u);
    ex_linspace(NS, 0, 2 * C2B_PI, v);
    c2b_blend_eval_grid(bf, NS, u, NS, v, 0, ref, &err);
    c2b_blend_eval_grid(b1, NS, u, NS, v, 0, part, &err);
    emit(o, "\n### Seed 001, section 3: pseudo-Navier, Fourier series and pseudo-spectral against the closed form (eqs. 17-23)\n\n");
    emit(o, "x = closed form of the first-group data (a0 + a1 v, -r cos v) + pseudo-Navier for a2 e^v "
            "(eq. 18); reference: C2Blend's closed form of all of eq. 17 (eq. 19). Error eq. 24 on "
            "100 x 100 points (u_i = i/99, v_j = 2 pi j/99). Shape b = 1, c = 18, d = 81. The Fourier-series "
            "rows solve the N-term Fourier series of the data (eq. 20) mode by mode; the pseudo-spectral rows add "
            "the remainder of eq. 22 (docs/APPROX.md).\n\n");
    emit(o, "| method | settings | E (eq. 24), ours | E, seed 001 | solve time (us), ours |\n|---|---|---|---|---|\n");
    struct { int M, N, ci, grid; const char *what; double pub; } cases[] = {
        {3, 3, 6, C2B_NAVIER_GRID_INTERIOR, "M = N = 3, 7 x 7 interior points", 6.637916e-4},
        {3, 3, 6, C2B_NAVIER_GRID_CLOSED, "M = N = 3, 7 x 7 points incl. boundary", 6.637916e-4},
        {6, 6, 20, C2B_NAVIER_GRID_INTERIOR, "M = N = 6, 21 x 21 interior points", NAN},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        c2b_navier_options op = c2b_navier_options_default();
        op.M = cases[k].M, op.N = cases[k].N, op.ci = op.cj = cases[k].ci, op.grid = cases[k].grid;
        c2b_navier *nv = NULL;
        double t[64];
        c2b_status st = C2B_OK;
        for (int r = 0; r < g_reps; r++) {
            c2b_navier_destroy(nv);
            nv = NULL;
            double t0 = now();
            st = c2b_navier_create(ex.shape, &ex.dom, &ex.vd, 0, &op, &nv, &err);
            t[r] = now() - t0;
        }
        char pub[32] = "—";
        if (!isnan(cases[k].pub))
            snprintf(pub, sizeof pub, "%.6e", cases[k].pub);
        if (st) {
            emit(o, "| pseudo-Navier | %s | fails: %s | %s | — |\n", cases[k].what, err.msg, pub);
            continue;
        }
        c2b_navier_eval_grid(nv, NS, u, NS, v, 0, app, &err);
        for (int i = 0; i < NS * NS * 3; i++)
            app[i] += part[i];
        emit(o, "| pseudo-Navier | %s | %.6e | %s | %.3g |\n", cases[k].what,
             ex_seed001_error(NS * NS, app, ref), pub, 1e6 * median(t, g_reps));
        c2b_navier_destroy(nv);
    }
    double t_full;
    c2b_blend *bfull = NULL;
    timed_blend_create(c2b_spec_problem(full), &bfull, &t_full, &err);
    c2b_blend_destroy(bfull);
    emit(o, "| closed form (C2Blend) | all of eq. 17 | 0 (reference) | 0 | %.3g |\n", 1e6 * t_full);
    static const int NF[2] = {20, 100};
    static const double pubF[2] = {6.565263e-2, 6.513351e-2};
    for (int k = 0; k < 2; k++) {
        static ex_fourier_problem fq;
        ex_fourier_init(&fq, NF[k]);
        c2b_blend *bq = NULL;
        double tq;
        if (timed_blend_create(&fq.pb, &bq, &tq, &err)) {
            emit(o, "| Fourier series (eqs. 20-21) | N = %d | fails: %s | %.6e | — |\n", NF[k], err.msg, pubF[k]);
            continue;
        }
        c2b_blend_eval_grid(bq, NS, u, NS, v, 0, app, &err);
        emit(o, "| Fourier series (eqs. 20-21, modes solved exactly) | N = %d | %.6e | %.6e | %.3g |\n", NF[k],
             ex_seed001_error(NS * NS, app, ref), pubF[k], 1e6 * tq);
        c2b_blend_destroy(bq);
    }
    /* pseudo-spectral (eqs. 22-23): the N-term Fourier solution plus the remainder
     * r1 e^{wu} + r2 u e^{wu} + r3 e^{-wu} + r4 u e^{-wu} that restores S and S_u at u = 0, 1
     * at every v; w = a (N + 1) with a = 3 (Bloor and Wilson's choice; seed 001 gives no w) */
    static const int NP[2] = {2, 5};
    static const double pubP[2] = {5.845711e-2, 6.294766e-2};
    for (int k = 0; k < 2; k++) {
        static ex_fourier_problem fq;
        ex_fourier_init(&fq, NP[k]);
        c2b_blend *bq = NULL;
        if (c2b_blend_create(&fq.pb, &bq, &err)) {
            emit(o, "| pseudo-spectral (eqs. 22-23) | N = %d | fails: %s | %.6e | — |\n", NP[k], err.msg, pubP[k]);
            continue;
        }
        double w = 3.0 * (NP[k] + 1), ub[2] = {0, 1};
        static double db[2 * NS * 3 * 3], dt[2 * NS * 3 * 3];
        c2b_blend_eval_grid(bq, 2, ub, NS, v, 1, db, &err);  /* Fourier solution at the ends */
        c2b_blend_eval_grid(bf, 2, ub, NS, v, 1, dt, &err);  /* the true data (closed form meets them) */
        c2b_blend_eval_grid(bq, NS, u, NS, v, 0, app, &err);
        for (int j = 0; j < NS; j++)
            for (int c = 0; c < 3; c++) {
                /* rows: R(0), R_u(0), R(1), R_u(1); unknowns r1..r4 */
                double ew = exp(w), em = exp(-w);
                double A[16] = {1, 0, 1, 0, w, 1, -w, 1, ew, ew, em, em, w * ew, ew + w * ew, -w * em, em - w * em};
                double rhs[4];
                for (int side = 0; side < 2; side++)
                    for (int p = 0; p < 2; p++) {
                        size_t idx = (((size_t)side * NS + j) * 3 + (p ? 1 : 0)) * 3 + c;
                        rhs[2 * side + p] = dt[idx] - db[idx];
                    }
                lapack_int piv[4];
                if (LAPACKE_dgesv(LAPACK_ROW_MAJOR, 4, 1, A, 4, piv, rhs, 1))
                    return 1;
                for (int i = 0; i < NS; i++) {
                    double eu = exp(w * u[i]), ed = exp(-w * u[i]);
                    app[((size_t)i * NS + j) * 3 + c] += rhs[0] * eu + rhs[1] * u[i] * eu + rhs[2] * ed + rhs[3] * u[i] * ed;
                }
            }
        emit(o, "| pseudo-spectral (eqs. 22-23, w = 3 (N + 1)) | N = %d | %.6e | %.6e | — |\n", NP[k],
             ex_seed001_error(NS * NS, app, ref), pubP[k]);
        c2b_blend_destroy(bq);
    }
    c2b_blend_destroy(bf);
    c2b_blend_destroy(b1);
    c2b_spec_destroy(full);
    c2b_spec_destroy(grp1);
    return 0;
}

/* Time-dependent data with 64 modes: sum_{k=1..64} cos(k t + phase) / k^2 sin(2 pi k v + phase).
 * The t-factors are cached per frame and sin(k x) runs by the angle-addition recurrence,
 * so the frame time measures the kernel, not 128 libm calls per sample. */
typedef struct tdat { double scale, phase, t_cached, amp[64]; } tdat;
static double tdat_fn(void *ctx, double v, double t)
{
    tdat *d = ctx;
    if (t != d->t_cached) {
        for (int k = 1; k <= 64; k++)
            d->amp[k - 1] = d->scale * cos(k * t + d->phase) / ((double)k * k);
        d->t_cached = t;
    }
    double x = 2 * C2B_PI * v, c1 = cos(x), s1 = sin(x), sk = 0, ck = 1, s = 0;
    double cp = cos(d->phase), sp = sin(d->phase);
    for (int k = 1; k <= 64; k++) {
        double sn = sk * c1 + ck * s1, cn = ck * c1 - sk * s1;
        sk = sn, ck = cn;
        s += d->amp[k - 1] * (sk * cp + ck * sp); /* sin(k x + phase) */
    }
    return s;
}

static int ratios_table(out *o)
{
    ex_thesis x;
    ex_thesis_init(&x, 0);
    c2b_spec *sp = ex_spec("thesis_eq127_129.json", NULL, NULL);
    c2b_blend *b = NULL;
    c2b_approx *a = NULL;
    c2b_approx_options op = c2b_approx_options_default();
    c2b_error err;
    if (!sp || c2b_blend_create(c2b_spec_problem(sp), &b, &err) ||
        c2b_approx_create(x.shape, &x.dom, &x.vd, x.t, &op, &a, &err)) {
        fprintf(stderr, "compare: ratios: cannot solve\n");
        return 1;
    }
    static double u[NE], v[NE], orc[NE * NE * 3], ex[NE * NE * 3], ap[NE * NE * 3];
    ex_linspace(NE, 0, 1, u);
    ex_linspace(NE, 0, 1, v);
    if (ex_oracle_surface(&x, NE, u, v, orc)) {
        fprintf(stderr, "compare: oracle failed\n");
        return 1;
    }
    c2b_blend_eval_grid(b, NE, u, NE, v, 0, ex, &err);
    c2b_approx_eval_grid(a, NE, u, NE, v, 0, ap, &err);
    double ee[5], ea[5];
    ex_thesis_errors(NE, NE, ex, orc, ee);
    ex_thesis_errors(NE, NE, ap, orc, ea);
    double te = time_solve(c2b_spec_problem(sp), &x, 0, NE), ta = time_solve(NULL, &x, 20, NE);
    emit(o, "\n### Exact closed form against thesis-approx (M = 20), eqs. 127-129 at t = 0.1, 101 x 101 vertices\n\n");
    emit(o, "Reference: an independent Chebyshev-collocation solution of each mode ODE (tests/oracle). "
            "Time = solve + evaluation, median of %d runs.\n\n", g_reps);
    emit(o, "| | exact (C2Blend) | thesis-approx M = 20 | ratio | target |\n|---|---|---|---|---|\n");
    emit(o, "| E1 against the oracle | %.3g | %.3g | %.3g | >= 1e4 |\n", ee[0], ea[0], ea[0] / fmax(ee[0], 1e-300));
    emit(o, "| E4 against the oracle | %.3g | %.3g | %.3g | >= 1e4 |\n", ee[3], ea[3], ea[3] / fmax(ee[3], 1e-300));
    emit(o, "| time (ms) | %.3g | %.3g | %.3g | >= 10 |\n", 1e3 * te, 1e3 * ta, ta / te);
    c2b_blend_destroy(b);
    c2b_approx_destroy(a);
    c2b_spec_destroy(sp);

    /* frames per second: 64 time-dependent modes per datum, 101^2 evaluation */
    c2b_problem pb = c2b_problem_default();
    pb.dom.v0 = 0, pb.dom.v1 = 1, pb.dom.periodic = 1;
    static tdat td[3][2];
    for (int c = 0; c < 3; c++)
        for (int side = 0; side < 2; side++) {
            td[c][side].scale = side ? 0.8 : 1.0;
            td[c][side].phase = 0.3 * c + side;
            td[c][side].t_cached = NAN;
            c2b_bfunc f = {tdat_fn, NULL, &td[c][side], 1, NULL, 0, 0, "fps datum"};
            pb.data[c][side][0] = f;
        }
    c2b_blend *bt = NULL;
    if (c2b_blend_create(&pb, &bt, &err)) {
        fprintf(stderr, "compare: fps blend: %s\n", err.msg);
        return 1;
    }
    int frames = 60;
    double *t = malloc(sizeof(double) * frames);
    for (int f = 0; f < frames; f++) {
        double t0 = now();
        c2b_blend_set_time(bt, 0.01 * (f + 1), &err);
        c2b_blend_eval_grid(bt, NE, u, NE, v, 0, ex, &err);
        t[f] = now() - t0;
    }
    double mt = median(t, frames);
    emit(o, "| frames per second, time-dependent blend, 64 modes in each of x, y, z at both trimlines, "
            "101 x 101 | %.0f (%.3g ms per frame: re-projection + evaluation) | — | — | >= 60 |\n",
         1.0 / mt, 1e3 * mt);
    free(t);
    c2b_blend_destroy(bt);
    return 0;
}

static void machine(out *o)
{
    char model[256] = "unknown";
    FILE *fp = fopen("/proc/cpuinfo", "r");
    int ncpu = 0;
    if (fp) {
        char line[512];
        while (fgets(line, sizeof line, fp)) {
            if (!strncmp(line, "model name", 10)) {
                ncpu++;
                char *p = strchr(line, ':');
                if (p) {
                    snprintf(model, sizeof model, "%s", p + 2);
                    model[strcspn(model, "\n")] = 0;
                }
            }
        }
        fclose(fp);
    }
    emit(o, "Machine: %s, %d logical CPUs (shared with other jobs while measured); one thread. "
            "Times are medians of %d runs.\n", model, ncpu, g_reps);
}

int main(int argc, char **argv)
{
    const char *md = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--markdown") && i + 1 < argc)
            md = argv[++i];
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc)
            g_reps = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: compare [--markdown FILE] [--reps N]\n");
            return 2;
        }
    }
    if (g_reps < 1 || g_reps > 64) {
        fprintf(stderr, "compare: --reps needs 1..64\n");
        return 2;
    }
    out o = {NULL};
    c2b_atomic_file af;
    c2b_error err;
    if (md) {
        if (c2b_atomic_open(&af, md, &err)) {
            fprintf(stderr, "compare: %s\n", err.msg);
            return 2;
        }
        o.md = af.fp;
    }
    emit(&o, "# Results: the papers' solvers beside C2Blend\n\n"
             "Generated by `bench/compare --markdown docs/RESULTS.md` (`make results`); do not edit by hand. "
             "Method notes and the reasons for differences from the papers are in "
             "docs/APPROX.md.\n\n");
    machine(&o);
    int rc = thesis_table(&o, 0) || thesis_table(&o, 1) || seed001_table(&o) || ratios_table(&o);
    if (md) {
        if (rc) {
            c2b_atomic_abort(&af);
        } else if (c2b_atomic_commit(&af, &err)) {
            fprintf(stderr, "compare: %s\n", err.msg);
            return 2;
        }
    }
    return rc;
}
