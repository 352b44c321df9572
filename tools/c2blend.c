/*
 * c2blend: command-line front end of the C2Blend kernel.
 *
 *   c2blend eval SPEC [--u N --v M | --points FILE] [--t T] [--derivs]
 *   c2blend info SPEC [--t T]
 *   c2blend fit  SPEC [--t T] [--tol 1e-6] [--degree-v 3|5] [--max-poles N] -o OUT.json [--iges OUT.igs]
 *   c2blend mesh SPEC [--t T] [--n 64] [--with-primaries WIDTH] -o OUT.{obj,ply,off}
 *   c2blend check SPEC [--t T] [--samples N] [--table] [--tol-g0 R] [--tol-g1 RAD] [--tol-g2 R] [--tol-c R]
 *   c2blend profile SPEC [--t T] [--n 201] [--with-primaries WIDTH] [--at V1,V2,...]
 *
 * Exit codes: 0 success, 2 bad usage or bad spec, 3 numerical failure (resonant or
 * ill-conditioned mode), 4 out of memory. Errors go to stderr; stdout receives
 * nothing unless the whole result was computed.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "c2b_atomic.h"
#include "c2b_blend.h"
#include "c2b_check.h"
#include "c2b_curv.h"
#include "c2b_fit.h"
#include "c2b_iges.h"
#include "c2b_mesh.h"
#include "c2b_nurbs_json.h"
#include "c2b_spec.h"
#include "c2b_surface.h"

#define EXIT_USAGE 2
#define EXIT_NUMERIC 3
#define EXIT_NOMEM 4

static const char USAGE[] =
    "usage: c2blend eval SPEC [--u N --v M | --points FILE] [--t T] [--derivs]\n"
    "       c2blend info SPEC [--t T]\n"
    "       c2blend fit  SPEC [--t T] [--tol 1e-6] [--degree-v 3|5] [--max-poles N] -o OUT.json [--iges OUT.igs]\n"
    "       c2blend mesh SPEC [--t T] [--n 64] [--with-primaries WIDTH] -o OUT.{obj,ply,off}\n"
    "       c2blend check SPEC [--t T] [--samples N] [--table] [--tol-g0 R] [--tol-g1 RAD] [--tol-g2 R] [--tol-c R]\n"
    "       c2blend profile SPEC [--t T] [--n 201] [--with-primaries WIDTH] [--at V1,V2,...]\n"
    "SPEC is a JSON blend spec (see README.md), '-' for standard input. Specs with an approximate\n"
    "\"solver\" (thesis-approx, pseudo-navier; docs/APPROX.md) work with eval and info only.\n";

static int exit_code(c2b_status st)
{
    switch (st) {
    case C2B_OK: return 0;
    case C2B_ERR_NUMERIC: return EXIT_NUMERIC;
    case C2B_ERR_NOMEM: return EXIT_NOMEM;
    default: return EXIT_USAGE;
    }
}

static int fail(const c2b_error *err)
{
    fprintf(stderr, "c2blend: %s\n", err->msg);
    return exit_code(err->code);
}

static int usage_error(const char *msg, const char *arg)
{
    fprintf(stderr, "c2blend: %s%s%s\n%s", msg, arg ? " " : "", arg ? arg : "", USAGE);
    return EXIT_USAGE;
}

static int parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

static int parse_count(const char *s, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < 2)
        return -1;
    *out = v;
    return 0;
}

typedef struct options {
    const char *command, *spec, *points, *out, *iges, *at;
    long nu, nv, nmesh, degree_v, max_poles;
    double t, tol, width;
    int have_t, derivs, table;
    c2b_check_options check;
} options;

static int parse_long(const char *s, long lo, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo)
        return -1;
    *out = v;
    return 0;
}

/* Which command may take which option. */
static int allowed(const char *cmd, const char *opt)
{
    static const char *const table[][2] = {
        {"--u", "eval"},        {"--v", "eval"},        {"--points", "eval"},
        {"--derivs", "eval"},   {"--tol", "fit"},       {"--degree-v", "fit"},
        {"--max-poles", "fit"}, {"--iges", "fit"},      {"-o", "fit mesh"},
        {"--n", "mesh profile"}, {"--with-primaries", "mesh profile"}, {"--at", "profile"},
        {"--t", "eval info fit mesh check profile"},
        {"--samples", "check"}, {"--table", "check"}, {"--tol-g0", "check"}, {"--tol-g1", "check"},
        {"--tol-g2", "check"},  {"--tol-c", "check"}};
    for (size_t i = 0; i < sizeof table / sizeof *table; i++)
        if (!strcmp(table[i][0], opt))
            return strstr(table[i][1], cmd) != NULL;
    return 0;
}

static int parse_args(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    o->nu = o->nv = 11;
    o->nmesh = 0; /* not given: mesh uses 64, profile 201 */
    o->tol = 1e-6;
    o->degree_v = 5;
    o->max_poles = 400;
    o->check = c2b_check_options_default();
    if (argc < 3)
        return usage_error("missing command or spec", NULL);
    o->command = argv[1];
    o->spec = argv[2];
    int grid = 0;
    for (int i = 3; i < argc; i++) {
        const char *a = argv[i];
        int has_val = i + 1 < argc;
        if (!strncmp(a, "-", 1) && !allowed(o->command, a)) {
            return usage_error(strstr("--u --v --points --derivs --tol --degree-v --max-poles --iges -o --n "
                                      "--with-primaries --t --samples --table --tol-g0 --tol-g1 --tol-g2 "
                                      "--tol-c --at", a) ? "option not valid for this command:"
                                                    : "unknown option",
                               a);
        }
        if (!strcmp(a, "--derivs")) {
            o->derivs = 1;
        } else if (!strcmp(a, "--at")) {
            if (!has_val)
                return usage_error("--at", "needs comma-separated v values");
            o->at = argv[++i];
        } else if (!strcmp(a, "--table")) {
            o->table = 1;
        } else if (!strcmp(a, "--samples")) {
            long ns;
            if (!has_val || parse_long(argv[++i], 2, &ns) || ns > 1000000)
                return usage_error("--samples", "needs an integer in 2..1000000");
            o->check.samples = (int)ns;
        } else if (!strncmp(a, "--tol-", 6)) {
            double *dst = !strcmp(a, "--tol-g0") ? &o->check.g0_rel : !strcmp(a, "--tol-g1") ? &o->check.g1_rad
                          : !strcmp(a, "--tol-g2") ? &o->check.g2_rel : &o->check.c_rel;
            if (!has_val || parse_double(argv[++i], dst) || !(*dst > 0))
                return usage_error(a, "needs a positive number");
        } else if (!strcmp(a, "--u") || !strcmp(a, "--v")) {
            long *dst = a[2] == 'u' ? &o->nu : &o->nv;
            if (!has_val || parse_count(argv[++i], dst))
                return usage_error(a, "needs an integer >= 2");
            grid = 1;
        } else if (!strcmp(a, "--n")) {
            /* a clear limit, not an allocation failure or an int overflow downstream */
            if (!has_val || parse_long(argv[++i], 2, &o->nmesh) || o->nmesh > 100000)
                return usage_error("--n", "needs an integer in 2..100000");
        } else if (!strcmp(a, "--degree-v")) {
            if (!has_val || parse_long(argv[++i], 1, &o->degree_v) || (o->degree_v != 3 && o->degree_v != 5))
                return usage_error("--degree-v", "must be 3 or 5");
        } else if (!strcmp(a, "--max-poles")) {
            if (!has_val || parse_long(argv[++i], 16, &o->max_poles))
                return usage_error("--max-poles", "needs an integer >= 16");
        } else if (!strcmp(a, "--points")) {
            if (!has_val)
                return usage_error("--points needs a file name ('-' for stdin)", NULL);
            o->points = argv[++i];
        } else if (!strcmp(a, "-o") || !strcmp(a, "--iges")) {
            if (!has_val)
                return usage_error(a, "needs a file name");
            *(a[1] == 'o' ? &o->out : &o->iges) = argv[++i];
        } else if (!strcmp(a, "--t")) {
            if (!has_val || parse_double(argv[++i], &o->t))
                return usage_error("--t needs a finite number", NULL);
            o->have_t = 1;
        } else if (!strcmp(a, "--tol")) {
            if (!has_val || parse_double(argv[++i], &o->tol) || !(o->tol > 0 && o->tol < 1))
                return usage_error("--tol", "needs a number in (0, 1) (relative to the bounding-box diagonal)");
        } else if (!strcmp(a, "--with-primaries")) {
            if (!has_val || parse_double(argv[++i], &o->width) || !(o->width >= 0))
                return usage_error("--with-primaries", "needs a width >= 0");
        } else {
            return usage_error("unexpected argument", a);
        }
    }
    if (grid && o->points)
        return usage_error("give either --u/--v or --points, not both", NULL);
    if ((!strcmp(o->command, "fit") || !strcmp(o->command, "mesh")) && !o->out)
        return usage_error("missing -o OUTPUT", NULL);
    return 0;
}

/* Read "u v" pairs (space or comma separated, '#' comments) into growing arrays. */
static c2b_status read_points(const char *path, double **pu, double **pv, size_t *np,
                              c2b_error *err)
{
    FILE *f = strcmp(path, "-") ? fopen(path, "r") : stdin;
    if (!f)
        return c2b_error_set(err, C2B_ERR_IO, "--points %s: cannot open", path);
    size_t cap = 1024, n = 0;
    double *u = malloc(cap * sizeof *u), *v = malloc(cap * sizeof *v);
    char line[4096];
    long lineno = 0;
    c2b_status st = C2B_OK;
    while (!st && u && v && fgets(line, sizeof line, f)) {
        lineno++;
        for (char *p = line; *p; p++)
            if (*p == ',' || *p == ';')
                *p = ' ';
        char *p = line;
        while (*p == ' ' || *p == '\t')
            p++;
        if (*p == '#' || *p == '\n' || *p == '\r' || !*p)
            continue;
        char *e1, *e2;
        double a = strtod(p, &e1), b = strtod(e1, &e2);
        while (*e2 == ' ' || *e2 == '\t' || *e2 == '\r' || *e2 == '\n')
            e2++;
        if (e1 == p || e2 == e1 || *e2 || !isfinite(a) || !isfinite(b)) {
            st = c2b_error_set(err, C2B_ERR_SPEC, "--points %s line %ld: expected two finite numbers 'u v'",
                               path, lineno);
            break;
        }
        if (n == cap) {
            cap *= 2;
            double *nu2 = realloc(u, cap * sizeof *u);
            if (nu2)
                u = nu2;
            double *nv2 = nu2 ? realloc(v, cap * sizeof *v) : NULL;
            if (!nu2 || !nv2) {
                st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory reading points");
                break;
            }
            v = nv2;
        }
        u[n] = a;
        v[n] = b;
        n++;
    }
    if (!st && (!u || !v))
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory reading points");
    if (!st && ferror(f))
        st = c2b_error_set(err, C2B_ERR_IO, "--points %s: read error", path);
    if (f != stdin)
        fclose(f);
    if (st) {
        free(u);
        free(v);
        return st;
    }
    *pu = u;
    *pv = v;
    *np = n;
    return C2B_OK;
}

/* b is the exact blend; sf (non-NULL for an approximate "solver") replaces it. */
static int cmd_eval(const options *o, const c2b_blend *b, const c2b_surface *sf, const c2b_problem *pb)
{
    c2b_error err;
    c2b_error_clear(&err);
    int order = o->derivs ? (pb->continuity == C2B_C3 ? 3 : 2) : 0;
    if (sf && order > c2b_surface_max_order(sf))
        order = c2b_surface_max_order(sf);
    size_t nd = c2b_blend_deriv_count(order);
    double *u = NULL, *v = NULL, *out = NULL;
    size_t np = 0, nu = 0, nv = 0;
    c2b_status st = C2B_OK;
    if (o->points) {
        st = read_points(o->points, &u, &v, &np, &err);
    } else {
        nu = (size_t)o->nu;
        nv = (size_t)o->nv;
        if ((double)nu * (double)nv > (double)pb->tol.max_eval_points) {
            st = c2b_error_set(&err, C2B_ERR_LIMIT, "grid %zu x %zu exceeds the limit of %ld points",
                               nu, nv, pb->tol.max_eval_points);
        } else {
            u = malloc(nu * sizeof *u);
            v = malloc(nv * sizeof *v);
            if (!u || !v)
                st = c2b_error_set(&err, C2B_ERR_NOMEM, "out of memory");
            for (size_t i = 0; !st && i < nu; i++)
                u[i] = (double)i / (double)(nu - 1);
            for (size_t j = 0; !st && j < nv; j++)
                v[j] = pb->dom.v0 + (pb->dom.v1 - pb->dom.v0) * (double)j / (double)(nv - 1);
            np = nu * nv;
        }
    }
    if (!st) {
        out = malloc((np ? np : 1) * nd * 3 * sizeof *out);
        if (!out)
            st = c2b_error_set(&err, C2B_ERR_NOMEM, "out of memory for %zu points", np);
    }
    if (!st && sf)
        st = o->points ? c2b_surface_eval(sf, np, u, v, order, out, &err)
                       : c2b_surface_eval_grid(sf, nu, u, nv, v, order, out, &err);
    else if (!st)
        st = o->points ? c2b_blend_eval(b, np, u, v, order, out, &err)
                       : c2b_blend_eval_grid(b, nu, u, nv, v, order, out, &err);
    /* Never print numbers that are not finite. */
    for (size_t i = 0; !st && i < np * nd * 3; i++)
        if (!isfinite(out[i]))
            st = c2b_error_set(&err, C2B_ERR_NUMERIC, "evaluation produced a non-finite value at point %zu",
                               i / (nd * 3));
    if (st) {
        free(u);
        free(v);
        free(out);
        return fail(&err);
    }
    static const char *const dn[] = {"", "u", "v", "uu", "uv", "vv", "uuu", "uuv", "uvv", "vvv"};
    fputs("u,v,x,y,z", stdout);
    for (size_t d = 1; d < nd; d++)
        printf(",x%s,y%s,z%s", dn[d], dn[d], dn[d]);
    putchar('\n');
    for (size_t p = 0; p < np; p++) {
        double pu = o->points ? u[p] : u[p / nv], pv = o->points ? v[p] : v[p % nv];
        printf("%.17g,%.17g", pu, pv);
        for (size_t k = 0; k < nd * 3; k++)
            printf(",%.17g", out[p * nd * 3 + k]);
        putchar('\n');
    }
    free(u);
    free(v);
    free(out);
    if (fflush(stdout) || ferror(stdout)) {
        fprintf(stderr, "c2blend: error writing standard output\n");
        return EXIT_USAGE;
    }
    return 0;
}

static int cmd_fit(const options *o, const c2b_blend *b)
{
    c2b_error err;
    c2b_error_clear(&err);
    c2b_fit_options fo = c2b_fit_options_default();
    fo.tol_rel = o->tol;
    fo.degree_v = (int)o->degree_v;
    fo.max_poles = (int)o->max_poles;
    c2b_nurbs_surface *s = NULL;
    c2b_fit_report rep;
    c2b_status st = c2b_fit_blend(b, &fo, &s, &rep, &err);
    if (st)
        return fail(&err);
    static const char *const dn[C2B_MAX_N] = {"S", "S_u", "S_uu", "S_uuu"};
    cJSON *root = cJSON_CreateObject(), *nj = c2b_nurbs_surface_to_json(s);
    cJSON_AddItemToObject(root, "nurbs", nj);
    cJSON_AddNumberToObject(root, "deviation", rep.deviation);
    cJSON_AddNumberToObject(root, "tolerance", rep.tolerance);
    cJSON_AddNumberToObject(root, "tolerance_rel", o->tol);
    cJSON_AddNumberToObject(root, "bbox_diagonal", rep.bbox_diagonal);
    cJSON *res = cJSON_AddObjectToObject(root, "residuals");
    for (int side = 0; side < 2; side++) {
        cJSON *r = cJSON_AddObjectToObject(res, side ? "u1" : "u0");
        for (int k = 0; k < c2b_blend_constraints(b); k++)
            cJSON_AddNumberToObject(r, dn[k], rep.residual[side][k]);
    }
    cJSON *tilt = cJSON_AddObjectToObject(root, "tilt");
    cJSON_AddNumberToObject(tilt, "u0", rep.tilt[0]);
    cJSON_AddNumberToObject(tilt, "u1", rep.tilt[1]);
    cJSON *np = cJSON_AddArrayToObject(root, "poles");
    cJSON_AddItemToArray(np, cJSON_CreateNumber(rep.npoles[0]));
    cJSON_AddItemToArray(np, cJSON_CreateNumber(rep.npoles[1]));
    cJSON_AddNumberToObject(root, "check_points", (double)rep.check_points);
    cJSON_AddNumberToObject(root, "time_ms", 1e3 * rep.seconds);
    /* Exact number printing: the poles and knots must read back bit for bit. */
    size_t len = nj ? c2b_nurbs_json_print(root, 1, NULL, 0) : 0;
    char *text = nj ? malloc(len + 1) : NULL;
    if (text)
        c2b_nurbs_json_print(root, 1, text, len + 1);
    cJSON_Delete(root);
    if (!text)
        st = c2b_error_set(&err, C2B_ERR_NOMEM, "out of memory writing the fit");
    c2b_atomic_file f;
    if (!st)
        st = c2b_atomic_open(&f, o->out, &err);
    if (!st) {
        fputs(text, f.fp);
        fputc('\n', f.fp);
        st = c2b_atomic_commit(&f, &err);
    }
    free(text);
    if (!st && o->iges)
        st = c2b_iges_write_surface(s, o->iges, NULL, &err);
    c2b_nurbs_surface_destroy(s);
    if (st)
        return fail(&err);
    fprintf(stderr, "c2blend fit: deviation %.3g (tolerance %.3g), %d x %d poles, %.1f ms -> %s%s%s\n",
            rep.deviation, rep.tolerance, rep.npoles[0], rep.npoles[1], 1e3 * rep.seconds, o->out,
            o->iges ? ", " : "", o->iges ? o->iges : "");
    return 0;
}

static int cmd_mesh(const options *o, const c2b_blend *b, c2b_spec *spec, double t)
{
    c2b_error err;
    c2b_error_clear(&err);
    c2b_mesh m;
    c2b_status st = c2b_mesh_tessellate(b, spec, t, o->nmesh ? (int)o->nmesh : 64, o->width, &m, &err);
    if (!st)
        st = c2b_mesh_write(&m, o->out, &err);
    if (!st && m.degenerate)
        fprintf(stderr, "c2blend mesh: %zu degenerate vertices (no normal or curvature; valid = 0)\n",
                m.degenerate);
    c2b_mesh_free(&m);
    return st ? fail(&err) : 0;
}

static void add_max(cJSON *o, const char *name, const char *at, const c2b_check_max *m)
{
    cJSON_AddNumberToObject(o, name, m->max);
    cJSON_AddNumberToObject(o, at, m->at_v);
}

static int cmd_check(const options *o, const c2b_blend *b, c2b_spec *spec)
{
    c2b_error err;
    c2b_error_clear(&err);
    c2b_check_side r[2];
    c2b_status st = c2b_check_run(b, spec, &o->check, r, &err);
    if (st)
        return fail(&err);
    cJSON *root = cJSON_CreateObject();
    cJSON *tol = cJSON_AddObjectToObject(root, "tolerances");
    cJSON_AddNumberToObject(tol, "g0_rel_to_diagonal", o->check.g0_rel);
    cJSON_AddNumberToObject(tol, "g1_rad", o->check.g1_rad);
    cJSON_AddNumberToObject(tol, "g2_rel", o->check.g2_rel);
    cJSON_AddNumberToObject(tol, "c_rel", o->check.c_rel);
    cJSON_AddNumberToObject(root, "time", c2b_blend_time(b));
    cJSON *tl = cJSON_AddArrayToObject(root, "trimlines");
    for (int side = 0; side < 2; side++) {
        const c2b_check_side *s = &r[side];
        cJSON *j = cJSON_CreateObject();
        cJSON_AddNumberToObject(j, "side", side);
        cJSON_AddNumberToObject(j, "samples", s->samples);
        add_max(j, "g0_max", "g0_at_v", &s->g0);
        add_max(j, "g1_max_rad", "g1_at_v", &s->g1);
        add_max(j, "g2_max", "g2_at_v", &s->g2);
        add_max(j, "g2_max_rel", "g2_rel_at_v", &s->g2_rel);
        add_max(j, "dk1_max", "dk1_at_v", &s->dk1);
        add_max(j, "dk2_max", "dk2_at_v", &s->dk2);
        add_max(j, "dK_max", "dK_at_v", &s->dK);
        add_max(j, "dH_max", "dH_at_v", &s->dH);
        add_max(j, "c1_max", "c1_at_v", &s->c1);
        add_max(j, "c2_max", "c2_at_v", &s->c2);
        cJSON_AddNumberToObject(j, "length_scale", s->scale_length);
        cJSON_AddNumberToObject(j, "degenerate_points", s->degenerate);
        cJSON_AddStringToObject(j, "verdict", s->verdict);
        cJSON_AddStringToObject(j, "parametric_verdict", s->parametric_verdict);
        if (o->table) {
            cJSON *t = cJSON_AddObjectToObject(j, "table");
            cJSON *tb = cJSON_AddArrayToObject(t, "blend"), *tp = cJSON_AddArrayToObject(t, "primary");
            for (int k = 0; k < 2; k++) {
                cJSON_AddItemToArray(tb, cJSON_CreateNumber(s->table_blend[k]));
                cJSON_AddItemToArray(tp, cJSON_CreateNumber(s->table_primary[k]));
            }
        }
        cJSON_AddItemToArray(tl, j);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text)
        return EXIT_NOMEM;
    puts(text);
    cJSON_free(text);
    return 0;
}

/* Curvature profiles across the trimlines: along u at fixed v, through the primary
 * strips (extended coordinates), as CSV. */
static int cmd_profile(const options *o, const c2b_blend *b, c2b_spec *spec)
{
    c2b_error err;
    c2b_error_clear(&err);
    c2b_vdomain dom = c2b_blend_domain(b);
    double vs[64];
    int nvs = 0;
    if (o->at) {
        const char *p = o->at;
        while (*p && nvs < 64) {
            char *end;
            double v = strtod(p, &end);
            if (end == p || !isfinite(v))
                return usage_error("--at", "needs comma-separated finite numbers");
            vs[nvs++] = v;
            p = *end == ',' ? end + 1 : end;
            if (*end && *end != ',')
                return usage_error("--at", "needs comma-separated finite numbers");
        }
    } else {
        for (int k = 0; k < 4; k++)
            vs[nvs++] = dom.v0 + (dom.v1 - dom.v0) * k / 4.0;
    }
    int n = o->nmesh ? (int)o->nmesh : 201;
    double width = c2b_spec_has_primaries(spec) ? o->width : 0.0;
    int strip = width > 0 ? (int)ceil(width * (n - 1) - 1e-9) : 0;
    size_t rows = (size_t)nvs * (size_t)(n + 2 * strip);
    double *buf = malloc(rows * 7 * sizeof *buf);
    if (!buf)
        return EXIT_NOMEM;
    size_t k = 0;
    c2b_status st = C2B_OK;
    for (int j = 0; j < nvs && !st; j++)
        for (int r = -strip; r < n + strip && !st; r++) {
            double u = (double)r / (n - 1), v = vs[j], d[30];
            int region = r < 0 ? 1 : r >= n ? 2 : 0;
            if (region)
                st = c2b_spec_primary_eval(spec, region - 1, u, v, c2b_blend_time(b), 2, d, &err);
            else
                st = c2b_blend_eval(b, 1, &u, &v, 2, d, &err);
            c2b_curv_point cp;
            double *row = buf + 7 * k++;
            row[0] = v, row[1] = u, row[2] = region;
            if (!st && c2b_curv_eval(d, 0, &cp, NULL) == C2B_OK) {
                row[3] = cp.k1, row[4] = cp.k2;
                row[5] = c2b_curv_normal_curvature(&cp, 0, 1);
                row[6] = c2b_curv_normal_curvature(&cp, 1, 0);
            } else {
                row[3] = row[4] = row[5] = row[6] = NAN;
            }
        }
    if (st) {
        free(buf);
        return fail(&err);
    }
    puts("v,u,region,k1,k2,k_along,k_across");
    for (size_t i = 0; i < k; i++) {
        const double *row = buf + 7 * i;
        printf("%.17g,%.17g,%d,%.17g,%.17g,%.17g,%.17g\n", row[0], row[1], (int)row[2], row[3], row[4],
               row[5], row[6]);
    }
    free(buf);
    return 0;
}

static int cmd_info(const c2b_blend *b, const c2b_spec *spec)
{
    c2b_error err;
    size_t need = 0;
    c2b_blend_info_json(b, NULL, 0, &need, NULL);
    char *buf = malloc(need + 1);
    if (!buf)
        return EXIT_NOMEM;
    if (c2b_blend_info_json(b, buf, need + 1, &need, &err)) {
        free(buf);
        return fail(&err);
    }
    /* Prepend the spec name. */
    printf("{\n\t\"name\":\t\"%s\",%s\n", c2b_spec_name(spec), buf + 1);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    options o;
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        fputs(USAGE, stdout);
        return 0;
    }
    int rc = parse_args(argc, argv, &o);
    if (rc)
        return rc;
    if (strcmp(o.command, "eval") && strcmp(o.command, "info") && strcmp(o.command, "fit") &&
        strcmp(o.command, "mesh") && strcmp(o.command, "check") && strcmp(o.command, "profile"))
        return usage_error("unknown command", o.command);
    c2b_error err;
    c2b_error_clear(&err);
    c2b_spec *spec = NULL;
    c2b_status st = c2b_spec_load(o.spec, &spec, &err);
    if (st)
        return fail(&err);
    c2b_problem pb = *c2b_spec_problem(spec);
    if (o.have_t)
        pb.time = o.t;
    if (c2b_spec_solver_settings(spec).kind != C2B_SOLVER_EXACT && strcmp(o.command, "info")) {
        /* the papers' approximate solvers (docs/APPROX.md): eval; info describes the
         * exact mode analysis of the same data */
        c2b_surface *sf = NULL;
        if (strcmp(o.command, "eval"))
            st = c2b_error_set(&err, C2B_ERR_SPEC, "solver: approximate solvers are available to 'eval' (and 'info') only");
        else
            st = c2b_surface_create(spec, pb.time, &sf, &err);
        rc = st ? fail(&err) : cmd_eval(&o, NULL, sf, &pb);
        c2b_surface_destroy(sf);
        c2b_spec_destroy(spec);
        return rc;
    }
    c2b_blend *b = NULL;
    st = c2b_blend_create(&pb, &b, &err);
    if (st) {
        c2b_spec_destroy(spec);
        return fail(&err);
    }
    if (!strcmp(o.command, "eval"))
        rc = cmd_eval(&o, b, NULL, &pb);
    else if (!strcmp(o.command, "fit"))
        rc = cmd_fit(&o, b);
    else if (!strcmp(o.command, "mesh"))
        rc = cmd_mesh(&o, b, spec, pb.time);
    else if (!strcmp(o.command, "check"))
        rc = cmd_check(&o, b, spec);
    else if (!strcmp(o.command, "profile"))
        rc = cmd_profile(&o, b, spec);
    else
        rc = cmd_info(b, spec);
    c2b_blend_destroy(b);
    c2b_spec_destroy(spec);
    return rc;
}
