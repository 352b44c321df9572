/* Solver dispatch for specs; see c2b_surface.h. */
#include "c2b_surface.h"

#include <stdlib.h>

#include "c2b_approx.h"
#include "c2b_blend.h"
#include "c2b_navier.h"

struct c2b_surface {
    c2b_blend *blend;
    c2b_approx *approx;
    c2b_navier *navier;
    c2b_vdata vd;
};

void c2b_surface_destroy(c2b_surface *sf)
{
    if (!sf)
        return;
    c2b_blend_destroy(sf->blend);
    c2b_approx_destroy(sf->approx);
    c2b_navier_destroy(sf->navier);
    free(sf);
}

c2b_status c2b_surface_create(c2b_spec *s, double t, c2b_surface **out, c2b_error *err)
{
    if (!s || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_surface_create: NULL argument");
    *out = NULL;
    c2b_surface *sf = calloc(1, sizeof *sf);
    if (!sf)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    c2b_problem pb = *c2b_spec_problem(s);
    pb.time = t;
    c2b_spec_solver so = c2b_spec_solver_settings(s);
    c2b_status st = C2B_OK;
    if (so.kind == C2B_SOLVER_EXACT) {
        st = c2b_blend_create(&pb, &sf->blend, err);
    } else {
        int c1 = so.kind == C2B_SOLVER_PSEUDO_NAVIER;
        if (pb.continuity != (c1 ? C2B_C1 : C2B_C2))
            st = c2b_error_set(err, C2B_ERR_SPEC, "solver: %s needs \"continuity\": \"%s\"",
                               c1 ? "pseudo-navier" : "thesis-approx", c1 ? "C1" : "C2");
        for (int c = 0; !st && c < C2B_NCOMP; c++)
            if (pb.force[c].fn)
                st = c2b_error_set(err, C2B_ERR_SPEC, "force: not supported by the %s solver",
                                   c1 ? "pseudo-navier" : "thesis-approx");
        if (!st)
            st = c2b_spec_vdata(s, c1 ? 4 : C2B_VDATA_MAX_K, &sf->vd, err);
        if (!st && c1) {
            c2b_navier_options o = c2b_navier_options_default();
            if (so.M)
                o.M = so.M;
            if (so.N)
                o.N = so.N;
            if (so.ci)
                o.ci = so.ci, o.cj = so.cj;
            st = c2b_navier_create(pb.shape, &pb.dom, &sf->vd, t, &o, &sf->navier, err);
        } else if (!st) {
            c2b_approx_options o = c2b_approx_options_default();
            if (so.M)
                o.M = so.M;
            if (so.ci)
                o.ci = so.ci, o.cj = so.cj;
            o.approach = so.approach ? C2B_APPROX_DECOMPOSITION : C2B_APPROX_DIFFERENTIAL;
            o.group2_closed = so.group2_closed;
            st = c2b_approx_create(pb.shape, &pb.dom, &sf->vd, t, &o, &sf->approx, err);
        }
    }
    if (st) {
        c2b_surface_destroy(sf);
        return st;
    }
    *out = sf;
    return C2B_OK;
}

int c2b_surface_max_order(const c2b_surface *sf) { return sf && sf->blend ? C2B_MAX_DERIV : 2; }

c2b_status c2b_surface_eval_grid(const c2b_surface *sf, size_t nu, const double *u, size_t nv,
                                 const double *v, int order, double *out, c2b_error *err)
{
    if (!sf)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_surface_eval_grid: NULL surface");
    if (sf->blend)
        return c2b_blend_eval_grid(sf->blend, nu, u, nv, v, order, out, err);
    if (sf->approx)
        return c2b_approx_eval_grid(sf->approx, nu, u, nv, v, order, out, err);
    return c2b_navier_eval_grid(sf->navier, nu, u, nv, v, order, out, err);
}

c2b_status c2b_surface_eval(const c2b_surface *sf, size_t npts, const double *u, const double *v,
                            int order, double *out, c2b_error *err)
{
    if (!sf || (npts && (!u || !v || !out)))
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_surface_eval: NULL argument");
    if (sf->blend)
        return c2b_blend_eval(sf->blend, npts, u, v, order, out, err);
    size_t nd = c2b_blend_deriv_count(order);
    for (size_t i = 0; i < npts; i++) {
        c2b_status st = c2b_surface_eval_grid(sf, 1, u + i, 1, v + i, order, out + i * nd * 3, err);
        if (st)
            return st;
    }
    return C2B_OK;
}
