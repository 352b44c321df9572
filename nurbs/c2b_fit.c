#include "c2b_fit.h"

#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "c2b_bspline.h"

/* The end rows (S, S_u, ... at u = 0 and 1) are fitted along v to this fraction of
 * the relative tolerance, each relative to its own magnitude along the trimline. */
#define C2B_FIT_TRIM_FACTOR 1e-2
/* ... and their normals (from S_u and S_v) to this fraction of tol_rel (radians). S_v
 * along a trimline is not one of the rows: it follows from S's interpolation in v, and
 * S within 1e-10 of the diagonal left the normal of a box's corner run tilted by
 * 1.5e-8 rad at places, over the 1e-8 rad a G1 check allows. A tighter fraction (0.1)
 * doubled the v-poles of fillets already at 2e-9 rad (a shaft on a plate, a loft), and
 * their faces took twice as long to sew and check. */
#define C2B_FIT_TILT_FACTOR 0.3

c2b_fit_options c2b_fit_options_default(void)
{
    c2b_fit_options o;
    o.tol_rel = 1e-6;
    o.degree_v = 5;
    o.max_poles = 400;
    o.max_iter = 30;
    return o;
}

/* One direction of the tensor product: breakpoints and the derived knot vector. */
typedef struct dir {
    int p, periodic;
    double lo, hi;
    int nb;       /* breakpoints b[0] = lo < ... < b[nb-1] = hi */
    double *b;
    int nt;       /* full (unwrapped) knot vector */
    double *t;
    int nfun;     /* basis functions of the unwrapped spline, nt - p - 1 */
    int npoles;   /* distinct poles (columns after wrapping) */
} dir;

static void dir_free(dir *d)
{
    free(d->b);
    free(d->t);
    d->b = d->t = NULL;
}

/* Rebuild the knot vector from the breakpoints. */
static int dir_build(dir *d)
{
    int ns = d->nb - 1, p = d->p;
    double L = d->hi - d->lo;
    free(d->t);
    if (d->periodic) {
        d->nt = ns + 2 * p + 1;
        d->t = malloc((size_t)d->nt * sizeof *d->t);
        if (!d->t)
            return -1;
        for (int j = 0; j <= ns; j++)
            d->t[p + j] = d->b[j];
        for (int j = 1; j <= p; j++) {
            d->t[p - j] = d->b[ns - j] - L;
            d->t[p + ns + j] = d->b[j] + L;
        }
        d->npoles = ns;
    } else {
        d->nt = ns - 1 + 2 * (p + 1);
        d->t = malloc((size_t)d->nt * sizeof *d->t);
        if (!d->t)
            return -1;
        for (int j = 0; j <= p; j++) {
            d->t[j] = d->lo;
            d->t[d->nt - 1 - j] = d->hi;
        }
        for (int j = 1; j < ns; j++)
            d->t[p + j] = d->b[j];
        d->npoles = d->nt - p - 1;
    }
    d->nfun = d->nt - p - 1;
    return 0;
}

static int dir_init(dir *d, int p, int periodic, double lo, double hi, int spans)
{
    memset(d, 0, sizeof *d);
    d->p = p;
    d->periodic = periodic;
    d->lo = lo;
    d->hi = hi;
    d->nb = spans + 1;
    d->b = malloc((size_t)d->nb * sizeof *d->b);
    if (!d->b)
        return -1;
    for (int j = 0; j < d->nb; j++)
        d->b[j] = lo + (hi - lo) * j / spans;
    d->b[d->nb - 1] = hi;
    return dir_build(d);
}

/* Split the spans flagged in split[0..nb-2] at their midpoints. */
static int dir_refine(dir *d, const unsigned char *split)
{
    int add = 0;
    for (int k = 0; k < d->nb - 1; k++)
        add += split[k] != 0;
    if (!add)
        return 0;
    double *nb = malloc((size_t)(d->nb + add) * sizeof *nb);
    if (!nb)
        return -1;
    int m = 0;
    for (int k = 0; k < d->nb - 1; k++) {
        nb[m++] = d->b[k];
        if (split[k])
            nb[m++] = 0.5 * (d->b[k] + d->b[k + 1]);
    }
    nb[m++] = d->b[d->nb - 1];
    free(d->b);
    d->b = nb;
    d->nb = m;
    return dir_build(d);
}

static double dir_wrap(const dir *d, double x)
{
    if (!d->periodic)
        return x;
    double L = d->hi - d->lo, y = d->lo + fmod(x - d->lo, L);
    if (y < d->lo)
        y += L;
    if (y >= d->hi)
        y -= L;
    return y;
}

/* Span index (into breakpoints) containing x. */
static int dir_bspan(const dir *d, double x)
{
    int lo = 0, hi = d->nb - 1;
    if (x >= d->b[hi])
        return hi - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (x < d->b[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

/* Non-zero basis derivatives of order k at x: first distinct-pole index of each of
 * the p+1 values into idx, values into val. */
static void dir_basis(const dir *d, double x, int k, int *idx, double *val)
{
    double work[(C2B_NURBS_MAX_DEGREE + 1) * (C2B_NURBS_MAX_DEGREE + 3)];
    double ders[(C2B_MAX_N) * (C2B_NURBS_MAX_DEGREE + 1)];
    x = dir_wrap(d, x);
    int span = c2b_bspline_span(d->p, d->nfun, d->t, x);
    c2b_bspline_basis_derivs(d->p, d->t, span, x, k, ders, work);
    for (int j = 0; j <= d->p; j++) {
        int c = span - d->p + j;
        idx[j] = d->periodic ? c % d->npoles : c;
        val[j] = ders[k * (d->p + 1) + j];
    }
}

/* Greville abscissae of the distinct poles (wrapped for periodic). */
static void dir_greville(const dir *d, double *g)
{
    for (int c = 0; c < d->npoles; c++) {
        double s = 0;
        for (int i = 1; i <= d->p; i++)
            s += d->t[c + i];
        g[c] = dir_wrap(d, s / d->p);
    }
}

/* The fit: u and v directions and poles[(i * npv + j) * 3 + c]. */
typedef struct fit {
    dir u, v;
    int n;           /* constraints per trimline */
    double *usite;   /* npu u-sites: interior interpolation sites (rows n..npu-n-1) */
    double *vsite;   /* npv v-sites */
    double *poles;
} fit;

static void fit_free(fit *f)
{
    dir_free(&f->u);
    dir_free(&f->v);
    free(f->usite);
    free(f->vsite);
    free(f->poles);
    memset(f, 0, sizeof *f);
}

/* Evaluate d^(ku+kv)/du^ku dv^kv of the fit on the grid u[nu] x v[nv] into
 * out[(i*nv+j)*3+c]. */
static int fit_eval_grid(const fit *f, int nu, const double *u, int ku, int nv, const double *v,
                         int kv, double *out)
{
    int npu = f->u.npoles, npv = f->v.npoles, pu = f->u.p, pv = f->v.p;
    double *q = malloc((size_t)npu * (size_t)nv * 3 * sizeof *q);
    if (!q)
        return -1;
    /* q[i][j] = sum_l M_l(v_j) P_il */
    memset(q, 0, (size_t)npu * (size_t)nv * 3 * sizeof *q);
    for (int j = 0; j < nv; j++) {
        int idx[C2B_NURBS_MAX_DEGREE + 1];
        double val[C2B_NURBS_MAX_DEGREE + 1];
        dir_basis(&f->v, v[j], kv, idx, val);
        for (int i = 0; i < npu; i++)
            for (int l = 0; l <= pv; l++) {
                const double *P = f->poles + ((size_t)i * (size_t)npv + (size_t)idx[l]) * 3;
                double *qq = q + ((size_t)i * (size_t)nv + (size_t)j) * 3;
                qq[0] += val[l] * P[0];
                qq[1] += val[l] * P[1];
                qq[2] += val[l] * P[2];
            }
    }
    for (int i = 0; i < nu; i++) {
        int idx[C2B_NURBS_MAX_DEGREE + 1];
        double val[C2B_NURBS_MAX_DEGREE + 1];
        dir_basis(&f->u, u[i], ku, idx, val);
        double *o = out + (size_t)i * (size_t)nv * 3;
        memset(o, 0, (size_t)nv * 3 * sizeof *o);
        for (int l = 0; l <= pu; l++) {
            const double *qq = q + (size_t)idx[l] * (size_t)nv * 3;
            for (int k = 0; k < nv * 3; k++)
                o[k] += val[l] * qq[k];
        }
    }
    free(q);
    return 0;
}

static const int UENTRY[C2B_MAX_N] = {0, 1, 3, 6}; /* S, Su, Suu, Suuu in the blend layout */

/* Solve for the poles of the current knot vectors. */
static c2b_status fit_solve(fit *f, const c2b_blend *b, c2b_error *err)
{
    int n = f->n, npu = f->u.npoles, npv = f->v.npoles;
    int nin = npu - 2 * n;
    free(f->usite);
    free(f->vsite);
    free(f->poles);
    f->usite = malloc((size_t)(nin > 0 ? nin : 1) * sizeof *f->usite);
    f->vsite = malloc((size_t)npv * sizeof *f->vsite);
    f->poles = malloc((size_t)npu * (size_t)npv * 3 * sizeof *f->poles);
    double *g = malloc((size_t)npu * sizeof *g);
    double *au = calloc((size_t)npu * (size_t)npu, sizeof *au);
    double *av = calloc((size_t)npv * (size_t)npv, sizeof *av);
    double *ulist = malloc((size_t)(nin + 2) * sizeof *ulist);
    size_t nd = c2b_blend_deriv_count(n - 1);
    double *an = malloc((size_t)(nin + 2) * (size_t)npv * nd * 3 * sizeof *an);
    double *rhs = malloc((size_t)npu * (size_t)npv * 3 * sizeof *rhs);
    double *rhs2 = malloc((size_t)npu * (size_t)npv * 3 * sizeof *rhs2);
    lapack_int *piv = malloc((size_t)(npu > npv ? npu : npv) * sizeof *piv);
    c2b_status st = C2B_OK;
    if (!f->usite || !f->vsite || !f->poles || !g || !au || !av || !ulist || !an || !rhs ||
        !rhs2 || !piv) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
        goto done;
    }
    dir_greville(&f->u, g);
    for (int i = 0; i < nin; i++)
        f->usite[i] = g[n + i];
    dir_greville(&f->v, f->vsite);
    /* u-system rows: derivatives 0..n-1 at u=0, interpolation at the sites, derivatives at u=1 */
    int idx[C2B_NURBS_MAX_DEGREE + 1];
    double val[C2B_NURBS_MAX_DEGREE + 1];
    for (int r = 0; r < npu; r++) {
        double x;
        int k;
        if (r < n) {
            x = 0.0;
            k = r;
        } else if (r < n + nin) {
            x = f->usite[r - n];
            k = 0;
        } else {
            x = 1.0;
            k = r - n - nin;
        }
        dir_basis(&f->u, x, k, idx, val);
        for (int l = 0; l <= f->u.p; l++)
            au[(size_t)r * (size_t)npu + (size_t)idx[l]] += val[l];
    }
    for (int s = 0; s < npv; s++) {
        dir_basis(&f->v, f->vsite[s], 0, idx, val);
        for (int l = 0; l <= f->v.p; l++)
            av[(size_t)s * (size_t)npv + (size_t)idx[l]] += val[l];
    }
    /* Analytic data on [0, u-sites, 1] x v-sites. */
    ulist[0] = 0.0;
    for (int i = 0; i < nin; i++)
        ulist[i + 1] = f->usite[i];
    ulist[nin + 1] = 1.0;
    st = c2b_blend_eval_grid(b, (size_t)nin + 2, ulist, (size_t)npv, f->vsite, n - 1, an, err);
    if (st)
        goto done;
    for (int r = 0; r < npu; r++) {
        int row, e;
        if (r < n) {
            row = 0;
            e = UENTRY[r];
        } else if (r < n + nin) {
            row = r - n + 1;
            e = 0;
        } else {
            row = nin + 1;
            e = UENTRY[r - n - nin];
        }
        for (int s = 0; s < npv; s++)
            for (int c = 0; c < 3; c++)
                rhs[((size_t)r * (size_t)npv + (size_t)s) * 3 + (size_t)c] =
                    an[(((size_t)row * (size_t)npv + (size_t)s) * nd + (size_t)e) * 3 + (size_t)c];
    }
    lapack_int info = LAPACKE_dgesv(LAPACK_ROW_MAJOR, npu, npv * 3, au, npu, piv, rhs, npv * 3);
    if (info == 0) {
        /* rhs now X[i][s*3+c]; transpose to B[s][i*3+c] and solve in v. */
        for (int i = 0; i < npu; i++)
            for (int s = 0; s < npv; s++)
                for (int c = 0; c < 3; c++)
                    rhs2[((size_t)s * (size_t)npu + (size_t)i) * 3 + (size_t)c] =
                        rhs[((size_t)i * (size_t)npv + (size_t)s) * 3 + (size_t)c];
        info = LAPACKE_dgesv(LAPACK_ROW_MAJOR, npv, npu * 3, av, npv, piv, rhs2, npu * 3);
    }
    if (info != 0) {
        st = c2b_error_set(err, C2B_ERR_NUMERIC, "fit: interpolation system singular (LAPACK info %d)",
                           (int)info);
        goto done;
    }
    for (int i = 0; i < npu; i++)
        for (int j = 0; j < npv; j++)
            for (int c = 0; c < 3; c++)
                f->poles[((size_t)i * (size_t)npv + (size_t)j) * 3 + (size_t)c] =
                    rhs2[((size_t)j * (size_t)npu + (size_t)i) * 3 + (size_t)c];
done:
    free(g);
    free(au);
    free(av);
    free(ulist);
    free(an);
    free(rhs);
    free(rhs2);
    free(piv);
    return st;
}

/* Points inside each span at the given fractions (plus, optionally, both ends). */
static double *span_samples(const dir *d, int nfrac, const double *frac, int ends, int *count)
{
    int ns = d->nb - 1, m = ns * nfrac + (ends ? 2 : 0);
    double *x = malloc((size_t)m * sizeof *x);
    if (!x)
        return NULL;
    int k = 0;
    if (ends)
        x[k++] = d->lo;
    for (int s = 0; s < ns; s++)
        for (int i = 0; i < nfrac; i++)
            x[k++] = d->b[s] + frac[i] * (d->b[s + 1] - d->b[s]);
    if (ends)
        x[k++] = d->hi;
    *count = k;
    return x;
}

/* Max distance between the fit and the blend on u[nu] x v[nv]; per-span maxima into
 * eu[] / ev[] (may be NULL). */
static c2b_status deviation(const fit *f, const c2b_blend *b, int nu, const double *u, int nv,
                            const double *v, double *eu, double *ev, double *dmax,
                            double *bbox, c2b_error *err)
{
    size_t np = (size_t)nu * (size_t)nv;
    double *a = malloc(np * 3 * sizeof *a), *s = malloc(np * 3 * sizeof *s);
    c2b_status st = C2B_OK;
    if (!a || !s) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
        goto done;
    }
    st = c2b_blend_eval_grid(b, (size_t)nu, u, (size_t)nv, v, 0, a, err);
    if (st)
        goto done;
    if (fit_eval_grid(f, nu, u, 0, nv, v, 0, s)) {
        st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
        goto done;
    }
    *dmax = 0;
    for (int i = 0; i < nu; i++) {
        int su = dir_bspan(&f->u, u[i]);
        for (int j = 0; j < nv; j++) {
            const double *pa = a + ((size_t)i * (size_t)nv + (size_t)j) * 3;
            const double *ps = s + ((size_t)i * (size_t)nv + (size_t)j) * 3;
            double dx = pa[0] - ps[0], dy = pa[1] - ps[1], dz = pa[2] - ps[2];
            double dist = sqrt(dx * dx + dy * dy + dz * dz);
            *dmax = fmax(*dmax, dist);
            if (eu)
                eu[su] = fmax(eu[su], dist);
            if (ev) {
                int sv = dir_bspan(&f->v, dir_wrap(&f->v, v[j]));
                ev[sv] = fmax(ev[sv], dist);
            }
            if (bbox)
                for (int c = 0; c < 3; c++) {
                    bbox[c] = fmin(bbox[c], pa[c]);
                    bbox[3 + c] = fmax(bbox[3 + c], pa[c]);
                }
        }
    }
done:
    free(a);
    free(s);
    return st;
}

/* Relative v-approximation error of the end rows, pointwise: for k < n at u = 0, 1,
 * |d^k S_fit/du^k - d^k S/du^k| divided by a local scale, per v-span into ev[] (and
 * the maximum absolute residuals per side and order into res, when not NULL). The
 * scale is diag for S (position), |S_u(v)| for S_u (so the ratio is the tangent
 * angle error) and max(|d^k S/du^k (v)|, |S_u(v)|^k / diag^(k-1)) for k >= 2 (an S_uu
 * error of that size changes the normal curvature by about 1/diag, so nearly flat
 * rows are not chased into rounding noise). */
static c2b_status trim_errors(const fit *f, const c2b_blend *b, int nv, const double *v,
                              double diag, double *ev, double *evn,
                              double res[2][C2B_MAX_N], double tilt[2], c2b_error *err)
{
    int n = f->n;
    size_t nd = c2b_blend_deriv_count(n - 1);
    double ue[2] = {0.0, 1.0};
    double *an = malloc(2 * (size_t)nv * nd * 3 * sizeof *an);
    double *fv = malloc((size_t)nv * 3 * sizeof *fv);
    double *fu = malloc((size_t)nv * 3 * sizeof *fu);
    c2b_status st = C2B_OK;
    if (!an || !fv || !fu)
        st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
    else
        st = c2b_blend_eval_grid(b, 2, ue, (size_t)nv, v, n - 1, an, err);
    double pmax = 0; /* largest pole coordinate: the rounding floor of the end rows */
    for (size_t k = 0; k < 3 * (size_t)f->u.npoles * (size_t)f->v.npoles; k++)
        pmax = fmax(pmax, fabs(f->poles[k]));
    for (int side = 0; !st && side < 2; side++)
        for (int k = 0; k < n; k++) {
            if (fit_eval_grid(f, 1, &ue[side], k, nv, v, 0, fv)) {
                st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
                break;
            }
            /* d^k/du^k at an end is a difference of the first k + 1 pole rows with
             * weights summing to 2^k p!/(p-k)! / h^k (h: the end span), so rounding alone
             * leaves an error of about eps * pmax times that, which no refinement
             * along v removes. Only the part above this floor counts for refinement. */
            double h = side ? f->u.b[f->u.nb - 1] - f->u.b[f->u.nb - 2] : f->u.b[1] - f->u.b[0];
            double amp = 1;
            for (int i = 0; i < k; i++)
                amp *= 2.0 * (f->u.p - i) / h;
            double floor = 16 * DBL_EPSILON * pmax * amp;
            double r = 0;
            for (int j = 0; j < nv; j++) {
                const double *row = an + ((size_t)side * (size_t)nv + (size_t)j) * nd * 3;
                const double *a = row + (size_t)UENTRY[k] * 3, *su = row + 3;
                double dx = fv[j * 3] - a[0], dy = fv[j * 3 + 1] - a[1], dz = fv[j * 3 + 2] - a[2];
                double d = sqrt(dx * dx + dy * dy + dz * dz);
                double nsu = sqrt(su[0] * su[0] + su[1] * su[1] + su[2] * su[2]);
                double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
                double scale = k == 0 ? diag : k == 1 ? nsu : fmax(na, pow(nsu, k) / pow(diag, k - 1));
                r = fmax(r, d);
                if (ev && scale > 0) {
                    int sv = dir_bspan(&f->v, dir_wrap(&f->v, v[j]));
                    ev[sv] = fmax(ev[sv], fmax(d - floor, 0.0) / scale);
                }
            }
            if (res)
                res[side][k] = r;
        }
    /* The normal's angle to the blend's along each trimline, from the fit's S_u and S_v,
     * per v-span into evn[] (may be NULL), less the rounding floor: S_u and S_v are
     * differences of pole rows amplified by 2p/h (h: the span), relative to their
     * length. */
    for (int side = 0; !st && side < 2; side++) {
        if (fit_eval_grid(f, 1, &ue[side], 1, nv, v, 0, fu) ||
            fit_eval_grid(f, 1, &ue[side], 0, nv, v, 1, fv)) {
            st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
            break;
        }
        double hu = side ? f->u.b[f->u.nb - 1] - f->u.b[f->u.nb - 2] : f->u.b[1] - f->u.b[0];
        double worst = 0;
        for (int j = 0; j < nv; j++) {
            const double *row = an + ((size_t)side * (size_t)nv + (size_t)j) * nd * 3;
            const double *su = row + 3, *sv = row + 6, *gu = fu + j * 3, *gv = fv + j * 3;
            double nb[3] = {su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2],
                            su[0] * sv[1] - su[1] * sv[0]};
            double nf[3] = {gu[1] * gv[2] - gu[2] * gv[1], gu[2] * gv[0] - gu[0] * gv[2],
                            gu[0] * gv[1] - gu[1] * gv[0]};
            double cr[3] = {nb[1] * nf[2] - nb[2] * nf[1], nb[2] * nf[0] - nb[0] * nf[2],
                            nb[0] * nf[1] - nb[1] * nf[0]};
            double dot = nb[0] * nf[0] + nb[1] * nf[1] + nb[2] * nf[2];
            double a = atan2(sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), dot);
            int sp = dir_bspan(&f->v, dir_wrap(&f->v, v[j]));
            double hv = f->v.b[sp + 1] - f->v.b[sp];
            double nsu = sqrt(su[0] * su[0] + su[1] * su[1] + su[2] * su[2]);
            double nsv = sqrt(sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2]);
            if (!(nsu > 0 && nsv > 0))
                continue;
            double floor = 16 * DBL_EPSILON * pmax *
                           (2.0 * f->u.p / hu / nsu + 2.0 * f->v.p / hv / nsv);
            worst = fmax(worst, a);
            if (evn)
                evn[sp] = fmax(evn[sp], fmax(a - floor, 0.0));
        }
        if (tilt)
            tilt[side] = worst;
    }
    free(an);
    free(fv);
    free(fu);
    return st;
}

static double now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static c2b_status make_surface(const fit *f, c2b_nurbs_surface **out, c2b_error *err)
{
    int npu = f->u.npoles, npv = f->v.npoles;
    double *p4 = malloc((size_t)npu * (size_t)npv * 4 * sizeof *p4);
    if (!p4)
        return c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
    for (size_t k = 0; k < (size_t)npu * (size_t)npv; k++) {
        p4[4 * k] = f->poles[3 * k];
        p4[4 * k + 1] = f->poles[3 * k + 1];
        p4[4 * k + 2] = f->poles[3 * k + 2];
        p4[4 * k + 3] = 1.0;
    }
    int per[2] = {0, f->v.periodic};
    c2b_status st = c2b_nurbs_surface_create(f->u.p, f->v.p, npu, npv, f->u.t, f->v.t, p4, per,
                                             out, err);
    free(p4);
    return st;
}

c2b_status c2b_fit_blend(const c2b_blend *b, const c2b_fit_options *opt,
                         c2b_nurbs_surface **out, c2b_fit_report *rep, c2b_error *err)
{
    c2b_fit_options def = c2b_fit_options_default();
    if (!opt)
        opt = &def;
    if (!b || !out || !rep)
        return c2b_error_set(err, C2B_ERR_ARG, "fit: NULL argument");
    if (!(opt->tol_rel > 0 && opt->tol_rel < 1) || (opt->degree_v != 3 && opt->degree_v != 5) ||
        opt->max_poles < 16 || opt->max_iter < 1)
        return c2b_error_set(err, C2B_ERR_ARG,
                             "fit: tolerance must be in (0, 1), v-degree 3 or 5, pole budget >= 16");
    *out = NULL;
    memset(rep, 0, sizeof *rep);
    double t0 = now();
    c2b_vdomain dom = c2b_blend_domain(b);
    fit f;
    memset(&f, 0, sizeof f);
    f.n = c2b_blend_constraints(b);
    c2b_status st = C2B_OK;
    if (dir_init(&f.u, 2 * f.n - 1, 0, 0.0, 1.0, 4) ||
        dir_init(&f.v, opt->degree_v, dom.periodic, dom.v0, dom.v1, 8)) {
        fit_free(&f);
        return c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
    }
    static const double F6[6] = {0.07, 0.23, 0.41, 0.59, 0.77, 0.93};
    static const double F8[8] = {0.03, 0.16, 0.29, 0.44, 0.56, 0.71, 0.84, 0.97};
    double tol = 0, bbox[6], trim_worst = 0; /* the end rows' worst relative residual */
    double tilt_worst = 0;                      /* ... and their normals' worst angle */
    int done = 0;
    double *us = NULL, *vs = NULL, *eu = NULL, *ev = NULL;
    for (rep->iterations = 1; rep->iterations <= opt->max_iter && !st; rep->iterations++) {
        if (f.u.npoles > opt->max_poles || f.v.npoles > opt->max_poles)
            break;
        st = fit_solve(&f, b, err);
        if (st)
            break;
        int nus, nvs, nin = f.u.npoles - 2 * f.n;
        free(us);
        free(vs);
        free(eu);
        free(ev);
        us = span_samples(&f.u, 6, F6, 1, &nus);
        vs = span_samples(&f.v, 6, F6, !dom.periodic, &nvs);
        eu = calloc((size_t)f.u.nb, sizeof *eu);
        ev = calloc((size_t)f.v.nb, sizeof *ev);
        double *usites = malloc((size_t)(nin + 2) * sizeof *usites);
        if (!us || !vs || !eu || !ev || !usites) {
            free(usites);
            st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
            break;
        }
        usites[0] = 0;
        memcpy(usites + 1, f.usite, (size_t)(nin > 0 ? nin : 0) * sizeof *usites);
        usites[nin + 1] = 1;
        double d1, d2;
        for (int c = 0; c < 3; c++) {
            bbox[c] = INFINITY;
            bbox[3 + c] = -INFINITY;
        }
        /* Along u at the v-sites (v-interpolation exact there), along v at the u-sites. */
        st = deviation(&f, b, nus, us, f.v.npoles, f.vsite, eu, NULL, &d1, bbox, err);
        if (!st)
            st = deviation(&f, b, nin + 2, usites, nvs, vs, NULL, ev, &d2, bbox, err);
        free(usites);
        if (st)
            break;
        if (rep->iterations == 1) {
            double dx = bbox[3] - bbox[0], dy = bbox[4] - bbox[1], dz = bbox[5] - bbox[2];
            rep->bbox_diagonal = sqrt(dx * dx + dy * dy + dz * dz);
            tol = opt->tol_rel * rep->bbox_diagonal;
            rep->tolerance = tol;
        }
        /* The end rows are the contact with the primaries: refine v until each is
         * approximated to C2B_FIT_TRIM_FACTOR * tol_rel of its own magnitude. */
        double *evt = calloc((size_t)f.v.nb, sizeof *evt);
        double *evn = calloc((size_t)f.v.nb, sizeof *evn);
        unsigned char *su = calloc((size_t)f.u.nb, 1), *sv = calloc((size_t)f.v.nb, 1);
        if (!su || !sv || !evt || !evn) {
            free(su);
            free(sv);
            free(evt);
            free(evn);
            st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
            break;
        }
        st = trim_errors(&f, b, nvs, vs, rep->bbox_diagonal, evt, evn, NULL, NULL, err);
        if (st) {
            free(su);
            free(sv);
            free(evt);
            free(evn);
            break;
        }
        int nsplit = 0;
        trim_worst = tilt_worst = 0;
        for (int k = 0; k < f.v.nb - 1; k++) {
            trim_worst = fmax(trim_worst, evt[k]);
            tilt_worst = fmax(tilt_worst, evn[k]);
        }
        for (int k = 0; k < f.u.nb - 1; k++)
            nsplit += su[k] = eu[k] > 0.5 * tol;
        for (int k = 0; k < f.v.nb - 1; k++)
            nsplit += sv[k] = ev[k] > 0.5 * tol || evt[k] > C2B_FIT_TRIM_FACTOR * opt->tol_rel ||
                              evn[k] > C2B_FIT_TILT_FACTOR * opt->tol_rel;
        free(evt);
        free(evn);
        if (!nsplit) {
            /* Independent check grid, offset from every site and knot. */
            int ncu, ncv;
            double *cu = span_samples(&f.u, 8, F8, 1, &ncu), *cv = span_samples(&f.v, 8, F8, 1, &ncv);
            double *ceu = calloc((size_t)f.u.nb, sizeof *ceu), *cev = calloc((size_t)f.v.nb, sizeof *cev);
            if (!cu || !cv || !ceu || !cev) {
                st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
            } else {
                double dc;
                st = deviation(&f, b, ncu, cu, ncv, cv, ceu, cev, &dc, NULL, err);
                rep->deviation = dc;
                rep->check_points = (long)ncu * ncv;
                if (!st && dc <= tol) {
                    done = 1;
                } else if (!st) {
                    for (int k = 0; k < f.u.nb - 1; k++)
                        su[k] = ceu[k] > 0.5 * tol;
                    for (int k = 0; k < f.v.nb - 1; k++)
                        sv[k] = cev[k] > 0.5 * tol;
                }
                /* Residuals of the end rows against the blend: on the check v's, and at
                 * the v-interpolation sites, where the Hermite end rows are exact. */
                if (!st && done)
                    st = trim_errors(&f, b, ncv, cv, rep->bbox_diagonal, NULL, NULL,
                                     rep->residual, rep->tilt, err);
                if (!st && done)
                    st = trim_errors(&f, b, f.v.npoles, f.vsite, rep->bbox_diagonal, NULL, NULL,
                                     rep->site_residual, NULL, err);
            }
            free(cu);
            free(cv);
            free(ceu);
            free(cev);
        } else {
            rep->deviation = fmax(d1, d2);
        }
        if (st || done) {
            free(su);
            free(sv);
            break;
        }
        int e1 = dir_refine(&f.u, su), e2 = dir_refine(&f.v, sv);
        free(su);
        free(sv);
        if (e1 || e2)
            st = c2b_error_set(err, C2B_ERR_NOMEM, "fit: out of memory");
    }
    free(us);
    free(vs);
    free(eu);
    free(ev);
    rep->npoles[0] = f.u.npoles;
    rep->npoles[1] = f.v.npoles;
    rep->seconds = now() - t0;
    if (!st && !done) {
        char why[160];
        if (f.u.npoles > opt->max_poles || f.v.npoles > opt->max_poles)
            snprintf(why, sizeof why, "the next refinement needs %d x %d poles, over the budget "
                     "of %d per direction", f.u.npoles, f.v.npoles, opt->max_poles);
        else
            snprintf(why, sizeof why, "%d refinement rounds (the limit) gave %d x %d poles",
                     opt->max_iter, f.u.npoles, f.v.npoles);
        double rows = C2B_FIT_TRIM_FACTOR * opt->tol_rel, tilt = C2B_FIT_TILT_FACTOR * opt->tol_rel;
        if (rep->deviation > tol)
            st = c2b_error_set(err, C2B_ERR_NUMERIC,
                               "fit: tolerance %.3g (%.3g x bounding-box diagonal %.6g) not "
                               "reached: deviation %.3g; %s",
                               tol, opt->tol_rel, rep->bbox_diagonal, rep->deviation, why);
        else if (trim_worst > rows)
            st = c2b_error_set(err, C2B_ERR_NUMERIC,
                               "fit: the trimline rows (S, S_u, S_uu at u = 0 and 1) are within "
                               "%.3g of their size, not the %.3g that exact contact needs (the "
                               "surface is within %.3g, under the tolerance %.3g); %s",
                               trim_worst, rows, rep->deviation, tol, why);
        else
            st = c2b_error_set(err, C2B_ERR_NUMERIC,
                               "fit: the normals along the trimlines (u = 0 and 1) are within "
                               "%.3g rad of the blend's, not the %.3g rad that exact contact "
                               "needs (the surface is within %.3g, under the tolerance %.3g); %s",
                               tilt_worst, tilt, rep->deviation, tol, why);
    }
    if (!st)
        st = make_surface(&f, out, err);
    fit_free(&f);
    return st;
}
