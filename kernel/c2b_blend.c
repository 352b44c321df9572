#include "c2b_blend.h"

#include <cjson/cJSON.h>
#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "c2b_constants.h"
#include "c2b_mode.h"
#include "c2b_poly.h"

#define FORCE_MAX_DEG 8
#define NSLOT (2 * C2B_MAX_N)

static const char COMP_NAME[C2B_NCOMP] = {'x', 'y', 'z'};

c2b_problem c2b_problem_default(void)
{
    c2b_problem p;
    memset(&p, 0, sizeof p);
    p.continuity = C2B_C2;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int i = 0; i < 5; i++)
            p.shape[c][i] = 1.0;
    p.dom.v0 = 0.0;
    p.dom.v1 = 1.0;
    p.tol = c2b_tolerances_default();
    return p;
}

/* One v-function of one component with its u-profile
 * G(u) = P(u) + Re sum_i coef_i phi_i(u). */
typedef struct term {
    c2b_vfunc f;
    int mode;                       /* index into the mode cache, -1: P only */
    double d[NSLOT];                /* boundary data amplitudes */
    double fu[FORCE_MAX_DEG + 1];   /* force amplitude per power of u */
    int fdeg;                       /* -1: no force on this term */
    c2b_poly *P;                    /* particular solution / polynomial profile, or NULL */
    double complex coef[C2B_MAX_M];
} term;

/* Context for one u-power coefficient of a force. */
typedef struct force_coef {
    const c2b_ffunc *F;
    int deg, index;
} force_coef;

typedef struct comp {
    c2b_operator op;
    c2b_vseries proj[NSLOT];
    int fdeg;
    force_coef fc[FORCE_MAX_DEG + 1];
    c2b_vseries fproj[FORCE_MAX_DEG + 1];
    term *terms;
    int nt;
} comp;

typedef struct cached_mode {
    int opc;      /* component whose operator it was built for */
    double beta;
    c2b_mode *m;
} cached_mode;

struct c2b_blend {
    c2b_problem pb;
    int n;
    comp comp[C2B_NCOMP];
    cached_mode *modes;
    int nmodes, capmodes;
    double t;
    int have_frame;
    double time_project, time_modes, time_solve; /* seconds, last frame */
    double time_modes_total;
    int modes_built_last;
};

static double now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- force decomposition: F(u, v, t) = sum_i u^i f_i(v, t) ---------------------- */

static double force_coef_fn(void *ctx, double v, double t)
{
    const force_coef *fc = ctx;
    int np = fc->deg + 1;
    double x[FORCE_MAX_DEG + 1], y[FORCE_MAX_DEG + 1], c[FORCE_MAX_DEG + 1];
    for (int j = 0; j < np; j++) {
        x[j] = c2b_poly_cheb_node(j, np);
        y[j] = fc->F->fn(fc->F->ctx, x[j], v, t);
    }
    c2b_poly_interpolate(np, x, y, c);
    return c[fc->index];
}

/* Smallest degree d <= FORCE_MAX_DEG for which F is a polynomial of degree d in u. */
static c2b_status force_degree(const c2b_problem *pb, int c, int *deg, c2b_error *err)
{
    const c2b_ffunc *F = &pb->force[c];
    double L = pb->dom.v1 - pb->dom.v0;
    static const double vs[3] = {0.137, 0.519, 0.883}, uc[4] = {0.071, 0.333, 0.618, 0.947};
    for (int d = 0; d <= FORCE_MAX_DEG; d++) {
        int np = d + 1, ok = 1;
        for (int k = 0; k < 3 && ok; k++) {
            double v = pb->dom.v0 + vs[k] * L, x[FORCE_MAX_DEG + 1], y[FORCE_MAX_DEG + 1],
                   co[FORCE_MAX_DEG + 1], scale = 0;
            for (int j = 0; j < np; j++) {
                x[j] = c2b_poly_cheb_node(j, np);
                y[j] = F->fn(F->ctx, x[j], v, pb->time);
                if (!isfinite(y[j]))
                    return c2b_error_set(err, C2B_ERR_SPEC,
                                         "%s: force is not finite at u=%g, v=%g",
                                         F->label ? F->label : "force", x[j], v);
                scale = fmax(scale, fabs(y[j]));
            }
            c2b_poly_interpolate(np, x, y, co);
            for (int j = 0; j < 4; j++) {
                double yy = F->fn(F->ctx, uc[j], v, pb->time), p = 0;
                for (int i = d; i >= 0; i--)
                    p = p * uc[j] + co[i];
                scale = fmax(scale, fabs(yy));
                if (!(fabs(p - yy) <= pb->tol.structure_rel * fmax(scale, 1e-300)))
                    ok = 0;
            }
        }
        if (ok) {
            *deg = d;
            return C2B_OK;
        }
    }
    return c2b_error_set(err, C2B_ERR_SPEC,
                         "%s: the force must be a polynomial in u of degree <= %d times "
                         "functions of v (F = p(u) f(v)); this one is not polynomial in u",
                         F->label ? F->label : "force", FORCE_MAX_DEG);
}

/* ---- modes ----------------------------------------------------------------------- */

static c2b_status get_mode(c2b_blend *b, int c, double beta, int *idx, c2b_error *err)
{
    const c2b_operator *op = &b->comp[c].op;
    for (int i = 0; i < b->nmodes; i++)
        if (b->modes[i].beta == beta && c2b_operator_equal(&b->comp[b->modes[i].opc].op, op)) {
            *idx = i;
            return C2B_OK;
        }
    if (b->nmodes == b->capmodes) {
        int cap = b->capmodes ? 2 * b->capmodes : 16;
        cached_mode *m = realloc(b->modes, (size_t)cap * sizeof *m);
        if (!m)
            return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        b->modes = m;
        b->capmodes = cap;
    }
    double t0 = now();
    c2b_mode *m = NULL;
    c2b_status st = c2b_mode_create(op, beta, &b->pb.tol, &m, err);
    b->time_modes_total += now() - t0;
    if (st)
        return st;
    b->modes[b->nmodes].opc = c;
    b->modes[b->nmodes].beta = beta;
    b->modes[b->nmodes].m = m;
    *idx = b->nmodes++;
    b->modes_built_last++;
    return C2B_OK;
}

/* ---- frame construction ------------------------------------------------------------ */

typedef struct entry {
    c2b_vfunc f;
    int slot; /* < NSLOT: datum; NSLOT + i: force coefficient of u^i */
    double amp;
} entry;

static int entry_cmp(const void *pa, const void *pb)
{
    const entry *a = pa, *b = pb;
    if (a->f.kind != b->f.kind)
        return a->f.kind < b->f.kind ? -1 : 1;
    if (a->f.kind == C2B_VF_POW)
        return (a->f.power > b->f.power) - (a->f.power < b->f.power);
    return (a->f.omega > b->f.omega) - (a->f.omega < b->f.omega);
}

static void free_terms(term *t, int nt)
{
    for (int i = 0; i < nt; i++)
        free(t[i].P);
    free(t);
}

static void describe_vfunc(const c2b_vfunc *f, char *buf, size_t cap)
{
    if (f->kind == C2B_VF_POW)
        snprintf(buf, cap, "v^%d", f->power);
    else
        snprintf(buf, cap, "%s(omega=%.17g)", c2b_vkind_name(f->kind), f->omega);
}

/* Merge the projections of one component into terms and solve them. */
static c2b_status build_terms(c2b_blend *b, int c, c2b_vseries *const *proj,
                              c2b_vseries *const *fproj, int fdeg, term **out, int *nout,
                              c2b_error *err)
{
    comp *cp = &b->comp[c];
    int n = b->n, m2 = 2 * n;
    size_t ne = 0;
    for (int s = 0; s < m2; s++)
        ne += (size_t)proj[s]->n;
    for (int i = 0; i <= fdeg; i++)
        ne += (size_t)fproj[i]->n;
    entry *e = malloc((ne ? ne : 1) * sizeof *e);
    term *terms = calloc(ne ? ne : 1, sizeof *terms);
    c2b_poly *G = NULL;
    c2b_poly *Fm = NULL;
    double *data = NULL;
    c2b_status st = C2B_OK;
    int nt = 0;
    if (!e || !terms) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        goto fail;
    }
    size_t k = 0;
    for (int s = 0; s < m2; s++)
        for (int i = 0; i < proj[s]->n; i++)
            e[k++] = (entry){proj[s]->terms[i].f, s, proj[s]->terms[i].amp};
    for (int d = 0; d <= fdeg; d++)
        for (int i = 0; i < fproj[d]->n; i++)
            e[k++] = (entry){fproj[d]->terms[i].f, NSLOT + d, fproj[d]->terms[i].amp};
    qsort(e, ne, sizeof *e, entry_cmp);
    for (size_t i = 0; i < ne; i++) {
        if (nt == 0 || !c2b_vfunc_same(&terms[nt - 1].f, &e[i].f)) {
            term *t = &terms[nt++];
            t->f = e[i].f;
            t->mode = -1;
            t->fdeg = -1;
        }
        term *t = &terms[nt - 1];
        if (e[i].slot < NSLOT) {
            t->d[e[i].slot] += e[i].amp;
        } else {
            int d = e[i].slot - NSLOT;
            t->fu[d] += e[i].amp;
            if (d > t->fdeg)
                t->fdeg = d;
        }
    }

    /* Exact polynomial recursion for the powers of v (PDE classes). */
    int dm = -1;
    if (!cp->op.beta_free)
        for (int i = 0; i < nt; i++)
            if (terms[i].f.kind == C2B_VF_POW && terms[i].f.power > dm)
                dm = terms[i].f.power;
    if (dm >= 0) {
        G = calloc((size_t)dm + 1, sizeof *G);
        Fm = calloc((size_t)dm + 1, sizeof *Fm);
        data = calloc((size_t)m2 * (size_t)(dm + 1), sizeof *data);
        if (!G || !Fm || !data) {
            st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
            goto fail;
        }
        for (int m = 0; m <= dm; m++)
            c2b_poly_zero(&Fm[m]);
        for (int i = 0; i < nt; i++)
            if (terms[i].f.kind == C2B_VF_POW) {
                int m = terms[i].f.power;
                for (int j = 0; j < m2; j++)
                    data[j * (dm + 1) + m] = terms[i].d[j];
                for (int d = 0; d <= terms[i].fdeg; d++)
                    Fm[m].c[d] = terms[i].fu[d];
                Fm[m].deg = terms[i].fdeg;
            }
        st = c2b_poly_solve_pde(&cp->op, dm, data, Fm, G, err);
        if (st)
            goto fail;
        for (int i = 0; i < nt; i++)
            if (terms[i].f.kind == C2B_VF_POW) {
                terms[i].P = malloc(sizeof *terms[i].P);
                if (!terms[i].P) {
                    st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
                    goto fail;
                }
                *terms[i].P = G[terms[i].f.power];
            }
    }

    /* Every other term is a mode with cached transfer functions. */
    for (int i = 0; i < nt; i++) {
        term *t = &terms[i];
        if (t->P)
            continue;
        double beta = c2b_vfunc_beta(&t->f);
        st = get_mode(b, c, beta, &t->mode, err);
        if (st) {
            char fb[96];
            describe_vfunc(&t->f, fb, sizeof fb);
            c2b_error_prefix(err, "component %c, mode %s: ", COMP_NAME[c], fb);
            goto fail;
        }
        double dd[NSLOT];
        memcpy(dd, t->d, sizeof dd);
        if (t->fdeg >= 0) {
            double ck[C2B_MAX_N + 1];
            c2b_operator_mode_coefficients(&cp->op, beta, ck);
            c2b_poly rhs;
            c2b_poly_zero(&rhs);
            for (int d = 0; d <= t->fdeg; d++)
                rhs.c[d] = t->fu[d];
            rhs.deg = t->fdeg;
            t->P = malloc(sizeof *t->P);
            if (!t->P) {
                st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
                goto fail;
            }
            st = c2b_poly_particular(n, ck, &rhs, t->P, err);
            if (st)
                goto fail;
            double pb[NSLOT];
            c2b_poly_boundary(t->P, n, pb);
            for (int j = 0; j < m2; j++)
                dd[j] -= pb[j];
        }
        c2b_mode_coefficients(b->modes[t->mode].m, dd, t->coef);
    }
    free(e);
    free(G);
    free(Fm);
    free(data);
    *out = terms;
    *nout = nt;
    return C2B_OK;
fail:
    free(e);
    free(G);
    free(Fm);
    free(data);
    free_terms(terms, nt);
    return st;
}

static c2b_status project_datum(const c2b_blend *b, const c2b_bfunc *bf, double t,
                                c2b_vseries *out, c2b_error *err)
{
    c2b_status st;
    if (bf->fn) {
        st = c2b_vseries_project(&b->pb.dom, bf->fn, bf->fn_vv, bf->ctx, t, &b->pb.tol, out,
                                 err);
        if (!st && out->err_abs > C2B_UNRESOLVED_REL * out->scale &&
            out->err_abs > b->pb.tol.truncation_rel * out->scale) {
            st = c2b_error_set(err, C2B_ERR_LIMIT,
                               "not resolved with %d samples (tolerance max_samples): truncation "
                               "error %.3g of the data scale %.3g at t=%g; the data vary faster "
                               "(a huge mode frequency) than the samples can represent",
                               out->n_samples, out->err_abs, out->scale, t);
            c2b_vseries_clear(out);
        }
    }
    else if (bf->samples)
        st = c2b_vseries_project_samples(&b->pb.dom, bf->samples, bf->stride ? bf->stride : 1,
                                         bf->n_samples, &b->pb.tol, out, err);
    else {
        out->n = 0;
        out->method = C2B_VM_ZERO;
        out->scale = out->err_abs = 0;
        st = C2B_OK;
    }
    if (st && bf->label)
        c2b_error_prefix(err, "%s: ", bf->label);
    return st;
}

static c2b_status build_frame(c2b_blend *b, double t, c2b_error *err)
{
    int n = b->n, m2 = 2 * n;
    c2b_vseries np[C2B_NCOMP][NSLOT], nf[C2B_NCOMP][FORCE_MAX_DEG + 1];
    int fresh[C2B_NCOMP][NSLOT], ffresh[C2B_NCOMP][FORCE_MAX_DEG + 1];
    term *nterms[C2B_NCOMP] = {NULL, NULL, NULL};
    int nnt[C2B_NCOMP] = {0, 0, 0};
    memset(np, 0, sizeof np);
    memset(nf, 0, sizeof nf);
    memset(fresh, 0, sizeof fresh);
    memset(ffresh, 0, sizeof ffresh);
    c2b_status st = C2B_OK;
    b->modes_built_last = 0;
    double t0 = now(), tm0 = b->time_modes_total;

    for (int c = 0; c < C2B_NCOMP && !st; c++) {
        comp *cp = &b->comp[c];
        for (int s = 0; s < m2 && !st; s++) {
            const c2b_bfunc *bf = &b->pb.data[c][s / n][s % n];
            if (!b->have_frame || bf->time_dependent) {
                fresh[c][s] = 1;
                st = project_datum(b, bf, t, &np[c][s], err);
            }
        }
        for (int d = 0; d <= cp->fdeg && !st; d++) {
            const c2b_ffunc *F = &b->pb.force[c];
            if (!b->have_frame || F->time_dependent) {
                ffresh[c][d] = 1;
                st = c2b_vseries_project(&b->pb.dom, force_coef_fn, NULL, &cp->fc[d], t,
                                         &b->pb.tol, &nf[c][d], err);
                if (st)
                    c2b_error_prefix(err, "%s (coefficient of u^%d): ",
                                     F->label ? F->label : "force", d);
            }
        }
    }
    double t1 = now();
    for (int c = 0; c < C2B_NCOMP && !st; c++) {
        c2b_vseries *pp[NSLOT], *fp[FORCE_MAX_DEG + 1];
        for (int s = 0; s < m2; s++)
            pp[s] = fresh[c][s] ? &np[c][s] : &b->comp[c].proj[s];
        for (int d = 0; d <= b->comp[c].fdeg; d++)
            fp[d] = ffresh[c][d] ? &nf[c][d] : &b->comp[c].fproj[d];
        st = build_terms(b, c, pp, fp, b->comp[c].fdeg, &nterms[c], &nnt[c], err);
    }
    double t2 = now();
    if (st) {
        for (int c = 0; c < C2B_NCOMP; c++) {
            for (int s = 0; s < NSLOT; s++)
                c2b_vseries_clear(&np[c][s]);
            for (int d = 0; d <= FORCE_MAX_DEG; d++)
                c2b_vseries_clear(&nf[c][d]);
            free_terms(nterms[c], nnt[c]);
        }
        return st;
    }
    for (int c = 0; c < C2B_NCOMP; c++) {
        comp *cp = &b->comp[c];
        for (int s = 0; s < m2; s++)
            if (fresh[c][s]) {
                c2b_vseries_clear(&cp->proj[s]);
                cp->proj[s] = np[c][s];
            }
        for (int d = 0; d <= cp->fdeg; d++)
            if (ffresh[c][d]) {
                c2b_vseries_clear(&cp->fproj[d]);
                cp->fproj[d] = nf[c][d];
            }
        free_terms(cp->terms, cp->nt);
        cp->terms = nterms[c];
        cp->nt = nnt[c];
    }
    b->t = t;
    b->have_frame = 1;
    b->time_project = t1 - t0;
    b->time_modes = b->time_modes_total - tm0;
    b->time_solve = (t2 - t1) - b->time_modes;
    return C2B_OK;
}

c2b_status c2b_blend_create(const c2b_problem *pb, c2b_blend **out, c2b_error *err)
{
    if (!pb || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_blend_create: NULL argument");
    *out = NULL;
    if (!isfinite(pb->dom.v0) || !isfinite(pb->dom.v1) || !(pb->dom.v1 > pb->dom.v0))
        return c2b_error_set(err, C2B_ERR_SPEC,
                             "v_range: [%g, %g] must be finite with v_range[1] > v_range[0]",
                             pb->dom.v0, pb->dom.v1);
    if (!isfinite(pb->time))
        return c2b_error_set(err, C2B_ERR_SPEC, "time: must be finite");
    c2b_blend *b = calloc(1, sizeof *b);
    if (!b)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    b->pb = *pb;
    b->n = c2b_continuity_n(pb->continuity);
    c2b_status st = C2B_OK;
    for (int c = 0; c < C2B_NCOMP && !st; c++) {
        st = c2b_operator_init(&b->comp[c].op, pb->continuity, pb->shape[c],
                               c2b_continuity_nshape(pb->continuity), err);
        if (st) {
            c2b_error_prefix(err, "shape (component %c): ", COMP_NAME[c]);
            break;
        }
        b->comp[c].fdeg = -1;
        if (pb->force[c].fn) {
            st = force_degree(&b->pb, c, &b->comp[c].fdeg, err);
            for (int d = 0; d <= b->comp[c].fdeg; d++)
                b->comp[c].fc[d] = (force_coef){&b->pb.force[c], b->comp[c].fdeg, d};
        }
    }
    if (!st)
        st = build_frame(b, pb->time, err);
    if (st) {
        c2b_blend_destroy(b);
        return st;
    }
    *out = b;
    return C2B_OK;
}

void c2b_blend_destroy(c2b_blend *b)
{
    if (!b)
        return;
    for (int c = 0; c < C2B_NCOMP; c++) {
        for (int s = 0; s < NSLOT; s++)
            c2b_vseries_clear(&b->comp[c].proj[s]);
        for (int d = 0; d <= FORCE_MAX_DEG; d++)
            c2b_vseries_clear(&b->comp[c].fproj[d]);
        free_terms(b->comp[c].terms, b->comp[c].nt);
    }
    for (int i = 0; i < b->nmodes; i++)
        c2b_mode_destroy(b->modes[i].m);
    free(b->modes);
    free(b);
}

c2b_status c2b_blend_set_time(c2b_blend *b, double t, c2b_error *err)
{
    if (!b)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_blend_set_time: NULL blend");
    if (!isfinite(t))
        return c2b_error_set(err, C2B_ERR_ARG, "time %g is not finite", t);
    return build_frame(b, t, err);
}

double c2b_blend_time(const c2b_blend *b) { return b->t; }

size_t c2b_blend_deriv_count(int order)
{
    return (size_t)(order + 1) * (size_t)(order + 2) / 2;
}

/* ---- evaluation ---------------------------------------------------------------------- */

static int deriv_index(int a, int bv)
{
    int q = a + bv;
    return q * (q + 1) / 2 + bv;
}

/* u-profile derivatives G^{(a)}(u), a = 0..order, of a term; phi is the basis of its
 * mode at u (NULL if it has none). */
static void term_profile(const c2b_blend *b, const term *t, const double complex *phi,
                         double u, int order, double *g)
{
    for (int a = 0; a <= order; a++)
        g[a] = 0.0;
    if (t->P)
        c2b_poly_eval(t->P, u, order, g);
    if (t->mode >= 0)
        for (int a = 0; a <= order; a++)
            g[a] += c2b_mode_combine(b->modes[t->mode].m, t->coef, phi, a);
}

static c2b_status check_eval_args(const c2b_blend *b, size_t npts, int order, double *out,
                                  c2b_error *err)
{
    if (!b || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "evaluation: NULL argument");
    if (order < 0 || order > C2B_MAX_DERIV)
        return c2b_error_set(err, C2B_ERR_ARG, "evaluation: derivative order %d not in 0..%d",
                             order, C2B_MAX_DERIV);
    if (npts > (size_t)b->pb.tol.max_eval_points)
        return c2b_error_set(err, C2B_ERR_LIMIT,
                             "evaluation: %zu points requested, the limit is %ld", npts,
                             b->pb.tol.max_eval_points);
    return C2B_OK;
}

c2b_status c2b_blend_eval(const c2b_blend *b, size_t npts, const double *u, const double *v,
                          int order, double *out, c2b_error *err)
{
    c2b_status st = check_eval_args(b, npts, order, out, err);
    if (st)
        return st;
    if (npts && (!u || !v))
        return c2b_error_set(err, C2B_ERR_ARG, "evaluation: NULL coordinates");
    size_t nd = c2b_blend_deriv_count(order);
    double complex *phi = malloc(((size_t)b->nmodes + 1) * 4 * C2B_MAX_M * sizeof *phi);
    if (!phi)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    double L = b->pb.dom.v1 - b->pb.dom.v0;
    for (size_t p = 0; p < npts; p++) {
        if (!isfinite(u[p]) || !isfinite(v[p])) {
            free(phi);
            return c2b_error_set(err, C2B_ERR_ARG, "evaluation: point %zu (u=%g, v=%g) is not finite",
                                 p, u[p], v[p]);
        }
        for (int i = 0; i < b->nmodes; i++)
            c2b_mode_basis(b->modes[i].m, u[p], order, phi + (size_t)i * 4 * C2B_MAX_M);
        double *o = out + p * nd * 3;
        memset(o, 0, nd * 3 * sizeof *o);
        for (int c = 0; c < C2B_NCOMP; c++) {
            const comp *cp = &b->comp[c];
            for (int i = 0; i < cp->nt; i++) {
                const term *t = &cp->terms[i];
                double g[4], f[4];
                term_profile(b, t, t->mode >= 0 ? phi + (size_t)t->mode * 4 * C2B_MAX_M : NULL,
                             u[p], order, g);
                c2b_vfunc_eval(&t->f, v[p] - b->pb.dom.v0, L, order, f);
                for (int a = 0; a <= order; a++)
                    for (int bv = 0; a + bv <= order; bv++)
                        o[deriv_index(a, bv) * 3 + c] += g[a] * f[bv];
            }
        }
    }
    free(phi);
    return C2B_OK;
}

/* The v-table of a grid evaluation: each term's v-derivatives up to the order are
 * multiples of a few functions (c2b_vfunc_derivative), shared between the derivatives and
 * the components, so each distinct one is evaluated once per v. */
typedef struct vtable {
    c2b_vfunc *row; /* the distinct functions */
    int nrow;
    int *ri;        /* per (term, bv): its row, -1 where the derivative vanishes */
    double *fac;    /* per (term, bv): the multiple */
} vtable;

typedef struct vtable_entry {
    c2b_vfunc g;
    size_t at; /* term * K + bv */
} vtable_entry;

static int vtable_entry_cmp(const void *a, const void *b)
{
    return c2b_vfunc_compare(&((const vtable_entry *)a)->g, &((const vtable_entry *)b)->g);
}

static void vtable_free(vtable *vt)
{
    free(vt->row);
    free(vt->ri);
    free(vt->fac);
}

/* Build the table over the tt terms of all components (in component order), K = order + 1.
 * Returns -1 when out of memory; vtable_free() releases it either way. */
static int vtable_build(const c2b_blend *b, size_t tt, size_t K, vtable *vt)
{
    size_t ne = tt * K, k = 0;
    vtable_entry *e = malloc((ne ? ne : 1) * sizeof *e);
    vt->row = malloc((ne ? ne : 1) * sizeof *vt->row);
    vt->ri = malloc((ne ? ne : 1) * sizeof *vt->ri);
    vt->fac = malloc((ne ? ne : 1) * sizeof *vt->fac);
    vt->nrow = 0;
    if (!e || !vt->row || !vt->ri || !vt->fac) {
        free(e);
        return -1;
    }
    size_t T = 0;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int t = 0; t < b->comp[c].nt; t++, T++)
            for (size_t bv = 0; bv < K; bv++) {
                c2b_vfunc g;
                double f = c2b_vfunc_derivative(&b->comp[c].terms[t].f, (int)bv, &g);
                vt->fac[T * K + bv] = f;
                vt->ri[T * K + bv] = -1;
                if (f != 0.0)
                    e[k++] = (vtable_entry){g, T * K + bv};
            }
    qsort(e, k, sizeof *e, vtable_entry_cmp);
    for (size_t i = 0; i < k; i++) {
        if (i == 0 || c2b_vfunc_compare(&e[i].g, &e[i - 1].g))
            vt->row[vt->nrow++] = e[i].g;
        vt->ri[e[i].at] = vt->nrow - 1;
    }
    free(e);
    return 0;
}

c2b_status c2b_blend_eval_grid(const c2b_blend *b, size_t nu, const double *u, size_t nv,
                               const double *v, int order, double *out, c2b_error *err)
{
    if (nu && nv && nu > SIZE_MAX / nv)
        return c2b_error_set(err, C2B_ERR_LIMIT, "evaluation: grid size overflows");
    c2b_status st = check_eval_args(b, nu * nv, order, out, err);
    if (st)
        return st;
    if ((nu && !u) || (nv && !v))
        return c2b_error_set(err, C2B_ERR_ARG, "evaluation: NULL coordinates");
    for (size_t i = 0; i < nu; i++)
        if (!isfinite(u[i]))
            return c2b_error_set(err, C2B_ERR_ARG, "evaluation: u[%zu] is not finite", i);
    for (size_t j = 0; j < nv; j++)
        if (!isfinite(v[j]))
            return c2b_error_set(err, C2B_ERR_ARG, "evaluation: v[%zu] is not finite", j);
    if (!nu || !nv)
        return C2B_OK;
    size_t nd = c2b_blend_deriv_count(order), K = (size_t)order + 1, tt = 0;
    double L = b->pb.dom.v1 - b->pb.dom.v0;
    for (int c = 0; c < C2B_NCOMP; c++)
        tt += (size_t)b->comp[c].nt;
    /* Per point (u, v), derivative and component: the sum over the component's terms
     * of its u-profile times its v-multiple times a row of the v-table. Blocks of v
     * keep the table's rows in cache (about 256 KB). */
    vtable vt;
    double *gu = malloc((tt ? tt : 1) * K * nu * sizeof *gu);
    double complex *phi = malloc(((size_t)b->nmodes + 1) * 4 * C2B_MAX_M * sizeof *phi);
    int bad = vtable_build(b, tt, K, &vt);
    size_t nr = vt.nrow ? (size_t)vt.nrow : 1, rows = 3 * nd;
    size_t NVB = 32768 / nr < 16 ? 16 : 32768 / nr > 512 ? 512 : 32768 / nr;
    double *B = malloc(nr * NVB * sizeof *B), *acc = malloc(NVB * sizeof *acc);
    if (bad || !gu || !phi || !B || !acc) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "out of memory for a %zu x %zu grid", nu, nv);
        goto done;
    }
    for (size_t i = 0; i < nu; i++) {
        /* Each cached mode's basis once per u, shared by all components and terms. */
        for (int mi = 0; mi < b->nmodes; mi++)
            c2b_mode_basis(b->modes[mi].m, u[i], order, phi + (size_t)mi * 4 * C2B_MAX_M);
        size_t T = 0;
        for (int c = 0; c < C2B_NCOMP; c++)
            for (int t = 0; t < b->comp[c].nt; t++, T++) {
                const term *tm = &b->comp[c].terms[t];
                double g[4];
                term_profile(b, tm, tm->mode >= 0 ? phi + (size_t)tm->mode * 4 * C2B_MAX_M : NULL,
                             u[i], order, g);
                for (size_t a = 0; a < K; a++)
                    gu[(T * K + a) * nu + i] = g[a];
            }
    }
    for (size_t j0 = 0; j0 < nv; j0 += NVB) {
        size_t nvb = nv - j0 < NVB ? nv - j0 : NVB;
        for (int r = 0; r < vt.nrow; r++) {
            const c2b_vfunc *f = &vt.row[r];
            double *row = B + (size_t)r * nvb;
            if (f->kind == C2B_VF_COS && r + 1 < vt.nrow && vt.row[r + 1].kind == C2B_VF_SIN &&
                vt.row[r + 1].omega == f->omega) {
                /* cos and sin of one angle together (one sincos), as c2b_vfunc_value. */
                for (size_t jj = 0; jj < nvb; jj++) {
                    double x = f->omega * (v[j0 + jj] - b->pb.dom.v0);
                    row[jj] = cos(x);
                    row[nvb + jj] = sin(x);
                }
                r++;
                continue;
            }
            for (size_t jj = 0; jj < nvb; jj++)
                row[jj] = c2b_vfunc_value(f, v[j0 + jj] - b->pb.dom.v0, L);
        }
        for (size_t i = 0; i < nu; i++)
            for (int a = 0; a <= order; a++)
                for (int bv = 0; a + bv <= order; bv++) {
                    size_t T0 = 0;
                    for (int c = 0; c < C2B_NCOMP; T0 += (size_t)b->comp[c++].nt) {
                        for (size_t jj = 0; jj < nvb; jj++)
                            acc[jj] = 0.0;
                        for (size_t T = T0; T < T0 + (size_t)b->comp[c].nt; T++) {
                            int r = vt.ri[T * K + (size_t)bv];
                            double g = gu[(T * K + (size_t)a) * nu + i] * vt.fac[T * K + (size_t)bv];
                            if (r < 0 || g == 0.0)
                                continue;
                            const double *f = B + (size_t)r * nvb;
                            for (size_t jj = 0; jj < nvb; jj++)
                                acc[jj] += g * f[jj];
                        }
                        double *o = out + (i * nv + j0) * rows + (size_t)deriv_index(a, bv) * 3 +
                                    (size_t)c;
                        for (size_t jj = 0; jj < nvb; jj++)
                            o[jj * rows] = acc[jj];
                    }
                }
    }
done:
    vtable_free(&vt);
    free(gu);
    free(phi);
    free(B);
    free(acc);
    return st;
}

int c2b_blend_constraints(const c2b_blend *b) { return b->n; }

c2b_vdomain c2b_blend_domain(const c2b_blend *b) { return b->pb.dom; }

c2b_status c2b_blend_boundary_residual(const c2b_blend *b, int ns, double *res, double *scale,
                                       c2b_error *err)
{
    if (!b || !res || !scale || ns < 2)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_blend_boundary_residual: invalid arguments");
    int n = b->n, order = n - 1;
    static const int uentry[C2B_MAX_N] = {0, 1, 3, 6}; /* S, Su, Suu, Suuu */
    const c2b_vdomain *dom = &b->pb.dom;
    double L = dom->v1 - dom->v0;
    size_t nd = c2b_blend_deriv_count(order), most = (size_t)ns;
    for (int k = 0; k < 2 * n; k++)
        res[k] = scale[k] = 0.0;
    for (int side = 0; side < 2; side++)
        for (int c = 0; c < C2B_NCOMP; c++)
            for (int p = 0; p < n; p++) {
                const c2b_bfunc *bf = &b->pb.data[c][side][p];
                if (bf->samples && !bf->fn && (size_t)bf->n_samples > most)
                    most = (size_t)bf->n_samples;
            }
    double *v = malloc(most * sizeof *v), *out = malloc(most * nd * 3 * sizeof *out);
    c2b_status st = v && out ? C2B_OK : c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    /* One grid evaluation (a row at u = side) per side and set of v: sampled data
     * usually share one sample count, so that is one or two per side. */
    for (int side = 0; side < 2 && !st; side++) {
        int have = 0; /* the v set in out: 0 none, m + 1 for m sampled points, -1 for ns */
        for (int c = 0; c < C2B_NCOMP && !st; c++)
            for (int p = 0; p < n && !st; p++) {
                const c2b_bfunc *bf = &b->pb.data[c][side][p];
                int sampled = bf->samples && !bf->fn;
                int m = sampled ? bf->n_samples : ns, iv = sampled && dom->periodic ? m : m - 1;
                if (have != (sampled ? m + 1 : -1)) {
                    for (int i = 0; i < m; i++)
                        v[i] = dom->v0 + L * i / iv;
                    double u = side;
                    st = c2b_blend_eval_grid(b, 1, &u, (size_t)m, v, order, out, err);
                    have = sampled ? m + 1 : -1;
                }
                size_t stride = (size_t)(bf->stride ? bf->stride : 1);
                for (int i = 0; i < m && !st; i++) {
                    double want = sampled ? bf->samples[(size_t)i * stride]
                                  : bf->fn ? bf->fn(bf->ctx, v[i], b->t) : 0.0;
                    double got = out[((size_t)i * nd + (size_t)uentry[p]) * 3 + (size_t)c];
                    res[side * n + p] = fmax(res[side * n + p], fabs(got - want));
                    scale[side * n + p] = fmax(scale[side * n + p], fabs(want));
                }
            }
    }
    free(v);
    free(out);
    return st;
}

/* ---- introspection ----------------------------------------------------------------- */

double c2b_blend_truncation_error(const c2b_blend *b)
{
    double e = 0;
    for (int c = 0; c < C2B_NCOMP; c++) {
        for (int s = 0; s < 2 * b->n; s++)
            e = fmax(e, b->comp[c].proj[s].err_abs);
        for (int d = 0; d <= b->comp[c].fdeg; d++)
            e = fmax(e, b->comp[c].fproj[d].err_abs);
    }
    return e;
}

double c2b_blend_max_condition(const c2b_blend *b)
{
    double k = 1.0;
    for (int c = 0; c < C2B_NCOMP; c++)
        for (int i = 0; i < b->comp[c].nt; i++)
            if (b->comp[c].terms[i].mode >= 0)
                k = fmax(k, c2b_mode_condition(b->modes[b->comp[c].terms[i].mode].m));
    return k;
}

static cJSON *complex_array(const double complex *z, int n)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < n; i++) {
        cJSON *p = cJSON_CreateArray();
        cJSON_AddItemToArray(p, cJSON_CreateNumber(creal(z[i])));
        cJSON_AddItemToArray(p, cJSON_CreateNumber(cimag(z[i])));
        cJSON_AddItemToArray(a, p);
    }
    return a;
}

c2b_status c2b_blend_info_json(const c2b_blend *b, char *buf, size_t cap, size_t *needed,
                               c2b_error *err)
{
    if (!b || !needed)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_blend_info_json: NULL argument");
    static const char *const side_name[2] = {"u0", "u1"};
    static const char *const deriv_name[C2B_MAX_N] = {"S", "S_u", "S_uu", "S_uuu"};
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "continuity", c2b_continuity_name(b->pb.continuity));
    cJSON_AddNumberToObject(root, "time", b->t);
    cJSON *vr = cJSON_AddArrayToObject(root, "v_range");
    cJSON_AddItemToArray(vr, cJSON_CreateNumber(b->pb.dom.v0));
    cJSON_AddItemToArray(vr, cJSON_CreateNumber(b->pb.dom.v1));
    cJSON_AddBoolToObject(root, "periodic", b->pb.dom.periodic);
    cJSON *comps = cJSON_AddArrayToObject(root, "components");
    for (int c = 0; c < C2B_NCOMP; c++) {
        const comp *cp = &b->comp[c];
        cJSON *jc = cJSON_CreateObject();
        char nm[2] = {COMP_NAME[c], 0};
        cJSON_AddStringToObject(jc, "component", nm);
        cJSON *sh = cJSON_AddObjectToObject(jc, "shape");
        for (int i = 0; i < c2b_continuity_nshape(b->pb.continuity); i++)
            cJSON_AddNumberToObject(sh, c2b_continuity_param_name(b->pb.continuity, i), cp->op.a[i]);
        cJSON_AddItemToObject(jc, "characteristic_roots_w", complex_array(cp->op.w, cp->op.n));
        cJSON *data = cJSON_AddArrayToObject(jc, "boundary_data");
        for (int s = 0; s < 2 * b->n; s++) {
            const c2b_vseries *p = &cp->proj[s];
            cJSON *jd = cJSON_CreateObject();
            cJSON_AddStringToObject(jd, "side", side_name[s / b->n]);
            cJSON_AddStringToObject(jd, "datum", deriv_name[s % b->n]);
            cJSON_AddStringToObject(jd, "method", c2b_vmethod_name(p->method));
            cJSON_AddNumberToObject(jd, "terms", p->n);
            cJSON_AddNumberToObject(jd, "samples", p->n_samples);
            cJSON_AddNumberToObject(jd, "scale", p->scale);
            cJSON_AddNumberToObject(jd, "truncation_error", p->err_abs);
            cJSON_AddItemToArray(data, jd);
        }
        cJSON_AddNumberToObject(jc, "force_u_degree", cp->fdeg);
        cJSON *modes = cJSON_AddArrayToObject(jc, "modes");
        for (int i = 0; i < cp->nt; i++) {
            const term *t = &cp->terms[i];
            cJSON *jm = cJSON_CreateObject();
            cJSON_AddStringToObject(jm, "kind", c2b_vkind_name(t->f.kind));
            if (t->f.kind == C2B_VF_POW)
                cJSON_AddNumberToObject(jm, "power", t->f.power);
            else
                cJSON_AddNumberToObject(jm, "omega", t->f.omega);
            cJSON_AddNumberToObject(jm, "beta", c2b_vfunc_beta(&t->f));
            cJSON *am = cJSON_AddArrayToObject(jm, "amplitude");
            for (int s = 0; s < 2 * b->n; s++)
                cJSON_AddItemToArray(am, cJSON_CreateNumber(t->d[s]));
            if (t->mode >= 0) {
                const c2b_mode *m = b->modes[t->mode].m;
                double complex r[C2B_MAX_M];
                c2b_mode_exponents(m, r);
                cJSON_AddStringToObject(jm, "solution", "exponential");
                cJSON_AddNumberToObject(jm, "condition", c2b_mode_condition(m));
                cJSON_AddNumberToObject(jm, "repeated_root_clusters", c2b_mode_repeated_clusters(m));
                cJSON_AddItemToObject(jm, "exponents", complex_array(r, c2b_mode_size(m)));
            } else {
                cJSON_AddStringToObject(jm, "solution", "polynomial");
                cJSON_AddNumberToObject(jm, "u_degree", t->P ? t->P->deg : -1);
            }
            cJSON_AddBoolToObject(jm, "forced", t->fdeg >= 0);
            cJSON_AddItemToArray(modes, jm);
        }
        cJSON_AddItemToArray(comps, jc);
    }
    {
        static const char *const rname[C2B_MAX_N] = {"S", "S_u", "S_uu", "S_uuu"};
        double res[2 * C2B_MAX_N], sc[2 * C2B_MAX_N];
        if (c2b_blend_boundary_residual(b, 101, res, sc, NULL) == C2B_OK) {
            cJSON *br = cJSON_AddArrayToObject(root, "boundary_residuals");
            for (int k = 0; k < 2 * b->n; k++) {
                cJSON *jr = cJSON_CreateObject();
                cJSON_AddStringToObject(jr, "side", side_name[k / b->n]);
                cJSON_AddStringToObject(jr, "datum", rname[k % b->n]);
                cJSON_AddNumberToObject(jr, "max_abs", res[k]);
                cJSON_AddNumberToObject(jr, "data_scale", sc[k]);
                cJSON_AddItemToArray(br, jr);
            }
        }
    }
    cJSON_AddNumberToObject(root, "cached_transfer_sets", b->nmodes);
    cJSON_AddNumberToObject(root, "truncation_error", c2b_blend_truncation_error(b));
    cJSON_AddNumberToObject(root, "max_condition", c2b_blend_max_condition(b));
    cJSON *tm = cJSON_AddObjectToObject(root, "time_ms");
    cJSON_AddNumberToObject(tm, "projection", 1e3 * b->time_project);
    cJSON_AddNumberToObject(tm, "modes", 1e3 * b->time_modes);
    cJSON_AddNumberToObject(tm, "solve", 1e3 * b->time_solve);
    char *s = cJSON_Print(root);
    cJSON_Delete(root);
    if (!s)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory printing the info");
    size_t len = strlen(s);
    *needed = len;
    c2b_status st = C2B_OK;
    if (!buf || cap < len + 1)
        st = c2b_error_set(err, C2B_ERR_LIMIT, "info buffer of %zu bytes too small, need %zu",
                           cap, len + 1);
    else
        memcpy(buf, s, len + 1);
    cJSON_free(s);
    return st;
}
