/**
 * @file c2b_nurbs.h
 * NURBS curves and surfaces: evaluation with all partial derivatives (Piegl & Tiller,
 * The NURBS Book: basis functions A2.2, derivatives through derivative control points
 * A3.3/A3.4 and A3.7/A3.8, rational derivatives A4.2/A4.4), knot insertion (A5.1),
 * degree elevation (Prautzsch's identity with knot insertion: only convex combinations;
 * A5.9 loses up to 1e-12 where knot spans differ much in length) and point projection.
 *
 * Knot multiplicities are at most p + 1 at the ends of a non-periodic domain (and
 * outside it) and at most p inside it and anywhere in a periodic direction. When all
 * weights are equal the spline is evaluated as a polynomial spline (derivatives of order
 * above the degree are exactly zero).
 *
 * Representation. Poles are given and returned as [x, y, z, w] (Cartesian point and
 * weight, w > 0); internally they are homogeneous [x w, y w, z w, w].
 *  - Non-periodic direction: n poles, a full knot vector of n + p + 1 non-decreasing
 *    values (clamped or not); the domain is [knots[p], knots[n]].
 *  - Periodic direction: n distinct poles and the flat knot vector of the equivalent
 *    unwrapped spline, n + 2p + 1 values, whose n + p poles repeat the first p at the
 *    end. The spacing must be periodic: knots[i + n] - knots[i] = knots[n + p] -
 *    knots[p] for every valid i. The domain is one period, [knots[p], knots[n + p]];
 *    parameters outside it are wrapped.
 * Surface poles are row-major: pole (i, j) (i along u, j along v) is at index i * n_v + j.
 *
 * Derivative layouts: surface order-k evaluation writes (k+1)(k+2)/2 entries
 * [S, Su, Sv, Suu, Suv, Svv, Suuu, Suuv, Suvv, Svvv, ...] of 3 doubles each (same as
 * c2b_blend.h). The table form writes SKL[a][b] = d^(a+b) S / du^a dv^b for a <= du,
 * b <= dv at index (a * (dv + 1) + b) * 3.
 *
 * Objects are not thread-safe to modify; const evaluation is thread-safe.
 */
#ifndef C2B_NURBS_H
#define C2B_NURBS_H

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest degree accepted in either direction. */
#define C2B_NURBS_MAX_DEGREE 15
/** Largest derivative order evaluated. */
#define C2B_NURBS_MAX_DERIV 6
/** Largest number of poles in one direction. */
#define C2B_NURBS_MAX_POLES 100000

typedef struct c2b_nurbs_curve c2b_nurbs_curve;
typedef struct c2b_nurbs_surface c2b_nurbs_surface;

/* ---- curves ------------------------------------------------------------------------ */

/**
 * Create a curve of degree p with n poles ([x, y, z, w] each, copied) and its knot
 * vector (length n + p + 1, or n + 2p + 1 when periodic; copied).
 * @return C2B_OK; C2B_ERR_SPEC naming the problem ("knots: decreasing at index 5",
 *         "poles[3]: weight must be positive", "degree 4 needs at least 5 poles",
 *         "knots: 9 values given, 11 needed", non-finite values, periodic spacing);
 *         C2B_ERR_NOMEM.
 */
c2b_status c2b_nurbs_curve_create(int p, int n, const double *knots, const double *poles,
                                  int periodic, c2b_nurbs_curve **out, c2b_error *err);

/**
 * As c2b_nurbs_curve_create(), with every message prefixed by the field path `path`
 * (e.g. "curves[0]" gives "curves[0].knots: decreasing at index 5 (0.4 after 0.5)" and
 * "curves[0]: degree must be 1..15 (got 0)"). path may be NULL or empty.
 */
c2b_status c2b_nurbs_curve_create_at(int p, int n, const double *knots, const double *poles,
                                     int periodic, const char *path, c2b_nurbs_curve **out,
                                     c2b_error *err);

/** Free a curve. NULL-safe. */
void c2b_nurbs_curve_destroy(c2b_nurbs_curve *c);

/** Deep copy. @return C2B_OK or C2B_ERR_NOMEM. */
c2b_status c2b_nurbs_curve_copy(const c2b_nurbs_curve *c, c2b_nurbs_curve **out, c2b_error *err);

/** Parameter domain [t0, t1]. */
void c2b_nurbs_curve_domain(const c2b_nurbs_curve *c, double *t0, double *t1);

/** Degree, number of (distinct) poles, periodic flag. */
int c2b_nurbs_curve_degree(const c2b_nurbs_curve *c);
int c2b_nurbs_curve_npoles(const c2b_nurbs_curve *c);
int c2b_nurbs_curve_periodic(const c2b_nurbs_curve *c);

/** Knot vector (length c2b_nurbs_curve_nknots(), owned by the curve). */
int c2b_nurbs_curve_nknots(const c2b_nurbs_curve *c);
const double *c2b_nurbs_curve_knots(const c2b_nurbs_curve *c);

/** Pole i (distinct poles only) as [x, y, z, w] into out[4]. */
void c2b_nurbs_curve_pole(const c2b_nurbs_curve *c, int i, double *out);

/**
 * Point and derivatives C^(k)(t), k = 0..order (order <= C2B_NURBS_MAX_DERIV), into
 * out[k * 3 + xyz]. t outside the domain: wrapped when periodic, else C2B_ERR_ARG.
 */
c2b_status c2b_nurbs_curve_eval(const c2b_nurbs_curve *c, double t, int order, double *out,
                                c2b_error *err);

/** Insert knot t `times` times (shape unchanged; periodic curves insert t + m T for every
 *  m, one pole per insertion). @return C2B_OK; C2B_ERR_ARG when t is outside the domain
 *  or the multiplicity would exceed p; C2B_ERR_LIMIT beyond C2B_NURBS_MAX_POLES poles;
 *  C2B_ERR_NOMEM. On failure the curve is unchanged. */
c2b_status c2b_nurbs_curve_insert_knot(c2b_nurbs_curve *c, double t, int times, c2b_error *err);

/** Raise the degree by `times` (shape unchanged; non-periodic curves; an unclamped knot
 *  vector becomes clamped, with the same domain). Every new pole is a convex combination
 *  of the old ones. @return C2B_OK; C2B_ERR_ARG for a periodic curve, times < 0 or a
 *  degree above C2B_NURBS_MAX_DEGREE; C2B_ERR_LIMIT; C2B_ERR_NOMEM. On failure the curve
 *  is unchanged. */
c2b_status c2b_nurbs_curve_elevate(c2b_nurbs_curve *c, int times, c2b_error *err);

/**
 * Closest point: the parameter t minimising |C(t) - point|, with the distance. The same
 * method as c2b_nurbs_surface_project's in one direction. dist may be NULL.
 * @return C2B_OK; C2B_ERR_ARG for NULL arguments or a non-finite point; C2B_ERR_NOMEM.
 */
c2b_status c2b_nurbs_curve_project(const c2b_nurbs_curve *c, const double *point, double *t,
                                   double *dist, c2b_error *err);

/* ---- surfaces ------------------------------------------------------------------------ */

/**
 * Create a surface of degrees (p, q) with nu x nv poles ([x, y, z, w], row-major, copied)
 * and knot vectors knots_u, knots_v (lengths as for curves, per direction).
 * periodic may be NULL (both open).
 * @return as c2b_nurbs_curve_create(); messages name the direction ("knots_u: ...",
 *         "poles[2][3]: weight must be positive").
 */
c2b_status c2b_nurbs_surface_create(int p, int q, int nu, int nv, const double *knots_u,
                                    const double *knots_v, const double *poles,
                                    const int *periodic, c2b_nurbs_surface **out,
                                    c2b_error *err);

/** As c2b_nurbs_surface_create(), with every message prefixed by the field path `path`
 *  ("primaries[0].nurbs.knots_u: ..."). path may be NULL or empty. */
c2b_status c2b_nurbs_surface_create_at(int p, int q, int nu, int nv, const double *knots_u,
                                       const double *knots_v, const double *poles,
                                       const int *periodic, const char *path,
                                       c2b_nurbs_surface **out, c2b_error *err);

/** Free a surface. NULL-safe. */
void c2b_nurbs_surface_destroy(c2b_nurbs_surface *s);

/** Deep copy. */
c2b_status c2b_nurbs_surface_copy(const c2b_nurbs_surface *s, c2b_nurbs_surface **out,
                                  c2b_error *err);

/** Domain: dom = [u0, u1, v0, v1]. */
void c2b_nurbs_surface_domain(const c2b_nurbs_surface *s, double *dom);

/** Degree, number of distinct poles, periodic flag, knots of direction dir (0 = u, 1 = v). */
int c2b_nurbs_surface_degree(const c2b_nurbs_surface *s, int dir);
int c2b_nurbs_surface_npoles(const c2b_nurbs_surface *s, int dir);
int c2b_nurbs_surface_periodic(const c2b_nurbs_surface *s, int dir);
int c2b_nurbs_surface_nknots(const c2b_nurbs_surface *s, int dir);
const double *c2b_nurbs_surface_knots(const c2b_nurbs_surface *s, int dir);

/** Pole (i, j) (distinct poles) as [x, y, z, w] into out[4]. */
void c2b_nurbs_surface_pole(const c2b_nurbs_surface *s, int i, int j, double *out);

/**
 * Derivative table SKL[a][b], a <= du, b <= dv (each <= C2B_NURBS_MAX_DERIV), at (u, v),
 * into skl[(a * (dv + 1) + b) * 3 + xyz].
 * @return C2B_OK; C2B_ERR_ARG for orders out of range or (u, v) outside a non-periodic
 *         domain (a tolerance of 1e-12 of the domain length is clamped).
 */
c2b_status c2b_nurbs_surface_derivs(const c2b_nurbs_surface *s, double u, double v, int du,
                                    int dv, double *skl, c2b_error *err);

/**
 * Point and all partial derivatives of total order <= order, in the blend layout
 * [S, Su, Sv, Suu, Suv, Svv, Suuu, Suuv, Suvv, Svvv] x 3 (order <= 3 as in c2b_blend.h;
 * up to C2B_NURBS_MAX_DERIV accepted, block k listing d^k/du^(k-j) dv^j for j = 0..k).
 * @return as c2b_nurbs_surface_derivs().
 */
c2b_status c2b_nurbs_surface_eval(const c2b_nurbs_surface *s, double u, double v, int order,
                                  double *out, c2b_error *err);

/** Insert knot t `times` times in direction dir (0 = u, 1 = v); as
 *  c2b_nurbs_curve_insert_knot(). */
c2b_status c2b_nurbs_surface_insert_knot(c2b_nurbs_surface *s, int dir, double t, int times,
                                         c2b_error *err);

/** Raise the degree in direction dir by `times` (non-periodic directions); as
 *  c2b_nurbs_curve_elevate(). */
c2b_status c2b_nurbs_surface_elevate(c2b_nurbs_surface *s, int dir, int times, c2b_error *err);

/**
 * Closest point on the surface: uv[2] minimising |S(u, v) - point| (grid search, then
 * Newton with bound handling), and the distance.
 * Method: 8 samples per knot span and direction (fewer when the grid would exceed 1e6
 * points), Newton on |S - P|^2 / 2 with the full Hessian from the 4 best samples, a
 * parameter at a non-periodic bound with the gradient pointing outward held there,
 * periodic parameters wrapped. dist may be NULL.
 * @return C2B_OK; C2B_ERR_ARG for NULL arguments or a non-finite point; C2B_ERR_NOMEM.
 */
c2b_status c2b_nurbs_surface_project(const c2b_nurbs_surface *s, const double *point,
                                     double *uv, double *dist, c2b_error *err);

#ifdef __cplusplus
}
#endif
#endif
