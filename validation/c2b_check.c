#include "c2b_check.h"
#include "c2b_vec3.h"

#include <math.h>
#include <string.h>

#include "c2b_curv.h"

c2b_check_options c2b_check_options_default(void)
{
    c2b_check_options o;
    o.samples = 101;
    o.g0_rel = 1e-9;
    o.g1_rad = 1e-8;
    o.g2_rel = 1e-6;
    o.c_rel = 1e-9;
    return o;
}



static void upd(c2b_check_max *m, double value, double v)
{
    if (!(value <= m->max)) { /* also records NaN */
        m->max = value;
        m->at_v = v;
    }
}

/* Thesis Table 4 style: normal curvature along the trimline (the S_v direction, the
 * thesis' "maximum", in the horizontal plane of its cylinders) and across it (the S_u
 * direction, its "minimum", vertical), times sign. */
static void table_pair(const c2b_curv_point *p, double sign, double *out)
{
    out[0] = sign * c2b_curv_normal_curvature(p, 0, 1);
    out[1] = sign * c2b_curv_normal_curvature(p, 1, 0);
}

c2b_status c2b_check_run(const c2b_blend *b, c2b_spec *spec, const c2b_check_options *opt,
                         c2b_check_side out[2], c2b_error *err)
{
    c2b_check_options def = c2b_check_options_default();
    if (!opt)
        opt = &def;
    if (!b || !spec || !out || opt->samples < 2)
        return c2b_error_set(err, C2B_ERR_ARG, "check: invalid arguments (samples >= 2)");
    if (!c2b_spec_has_primaries(spec))
        return c2b_error_set(err, C2B_ERR_ARG,
                             "check: the spec gives explicit boundary data, not primary surfaces; "
                             "`c2blend info` reports how well the data are reproduced");
    c2b_vdomain dom = c2b_blend_domain(b);
    int ns = opt->samples;
    double t = c2b_blend_time(b);
    /* Length scale: bounding-box diagonal of both trimlines. */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int side = 0; side < 2; side++)
        for (int i = 0; i < ns; i++) {
            double u = side, v = dom.v0 + (dom.v1 - dom.v0) * i / (ns - 1), p[3];
            c2b_blend_eval(b, 1, &u, &v, 0, p, NULL);
            for (int c = 0; c < 3; c++) {
                lo[c] = fmin(lo[c], p[c]);
                hi[c] = fmax(hi[c], p[c]);
            }
        }
    double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
    if (!(diag > 0))
        diag = 1.0;
    for (int side = 0; side < 2; side++) {
        c2b_check_side *r = &out[side];
        memset(r, 0, sizeof *r);
        r->side = side;
        r->samples = ns;
        r->scale_length = diag;
        r->scale_curvature = 1.0 / diag;
        double su_max = 0, suu_scale = 0;
        double pts_db[30], pts_dp[18];
        /* First pass for the parametric scales. */
        for (int i = 0; i < ns; i++) {
            double u = side, v = dom.v0 + (dom.v1 - dom.v0) * i / (ns - 1);
            c2b_status st = c2b_spec_primary_eval(spec, side, u, v, t, 2, pts_dp, err);
            if (st)
                return st;
            su_max = fmax(su_max, c2b_vec3_norm(pts_dp + 3));
            suu_scale = fmax(suu_scale, c2b_vec3_norm(pts_dp + 9));
        }
        suu_scale = fmax(suu_scale, su_max * su_max / diag);
        for (int i = 0; i < ns; i++) {
            double u = side, v = dom.v0 + (dom.v1 - dom.v0) * i / (ns - 1);
            c2b_blend_eval(b, 1, &u, &v, 2, pts_db, NULL);
            c2b_status st = c2b_spec_primary_eval(spec, side, u, v, t, 2, pts_dp, err);
            if (st)
                return st;
            upd(&r->g0, c2b_vec3_dist(pts_db, pts_dp), v);
            upd(&r->c1, c2b_vec3_dist(pts_db + 3, pts_dp + 3), v);
            upd(&r->c2, c2b_vec3_dist(pts_db + 9, pts_dp + 9), v);
            c2b_curv_point cb, cp;
            if (c2b_curv_eval(pts_db, 0, &cb, NULL) || c2b_curv_eval(pts_dp, 0, &cp, NULL)) {
                r->degenerate++;
                continue;
            }
            double cr[3];
            c2b_vec3_cross(cb.normal, cp.normal, cr);
            upd(&r->g1, atan2(c2b_vec3_norm(cr), c2b_vec3_dot(cb.normal, cp.normal)), v);
            /* Normal curvature across the trimline: the blend's S_u direction in 3-D. */
            double kb = 0, kp = 0;
            if (c2b_curv_normal_curvature_3d(pts_db, &cb, pts_db + 3, &kb, NULL) == C2B_OK &&
                c2b_curv_normal_curvature_3d(pts_dp, &cp, pts_db + 3, &kp, NULL) == C2B_OK) {
                double kscale = fmax(fmax(fabs(cp.k1), fabs(cp.k2)), r->scale_curvature);
                upd(&r->g2, fabs(kb - kp), v);
                upd(&r->g2_rel, fabs(kb - kp) / kscale, v);
            } else {
                r->degenerate++;
            }
            upd(&r->dk1, fabs(cb.k1 - cp.k1), v);
            upd(&r->dk2, fabs(cb.k2 - cp.k2), v);
            upd(&r->dK, fabs(cb.K - cp.K), v);
            upd(&r->dH, fabs(cb.H - cp.H), v);
            if (i == 0) {
                double sign = c2b_curv_normal_curvature(&cp, 0, 1) +
                                          c2b_curv_normal_curvature(&cp, 1, 0) >= 0 ? 1.0 : -1.0;
                table_pair(&cb, sign, r->table_blend);
                table_pair(&cp, sign, r->table_primary);
            }
        }
        int g0 = r->g0.max <= opt->g0_rel * diag;
        int g1 = g0 && r->g1.max <= opt->g1_rad;
        int g2 = g1 && r->g2_rel.max <= opt->g2_rel;
        r->verdict = g2 ? "G2" : g1 ? "G1" : g0 ? "G0" : "none";
        int c1 = g0 && r->c1.max <= opt->c_rel * fmax(su_max, 1e-300);
        int c2 = c1 && r->c2.max <= opt->c_rel * suu_scale;
        r->parametric_verdict = c2 ? "C2" : c1 ? "C1" : g0 ? "C0" : "none";
    }
    return C2B_OK;
}
