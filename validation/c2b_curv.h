/**
 * @file c2b_curv.h
 * Analytic differential geometry of a parametric surface at one point: fundamental
 * forms, Gaussian and mean curvature, principal curvatures and directions, normal
 * curvature (MATH.md section 8; do Carmo, "Differential Geometry of Curves and
 * Surfaces", sections 3-2 and 3-3).
 *
 * @par Input layout
 * A point is given by its derivative block, the layout used throughout the kernel:
 * `d[entry * 3 + xyz]` with entries `[S, Su, Sv, Suu, Suv, Svv]`, i.e. 18 doubles
 * (::C2B_CURV_BLOCK). `S` itself is not used but must be finite. All lengths are in the
 * surface's model units; curvatures are in 1/unit, Gaussian curvature in 1/unit^2.
 *
 * @par Sign conventions
 *  - The normal is n = Su x Sv / |Su x Sv|: the orientation follows the parametrisation.
 *    Swapping u and v flips n and the sign of L, M, N, H, k1, k2 (K is unchanged).
 *  - L = Suu.n, M = Suv.n, N = Svv.n. A curvature is positive when the surface bends
 *    towards n. Example: the sphere x = R cos u cos v, y = R sin u cos v, z = R sin v
 *    has the outward normal, so k1 = k2 = H = -1/R and K = 1/R^2.
 *  - K = (LN - M^2)/(EG - F^2), H = (EN - 2FM + GL)/(2(EG - F^2)).
 *  - k1 >= k2; k1,2 = H +- sqrt(H^2 - K) where H^2 - K is evaluated as the sum of squares
 *    ((s11 - s22)/2)^2 + s12^2 of the shape operator in an orthonormal tangent frame, so it
 *    is never negative and does not cancel near umbilics.
 *  - dir1, dir2 are unit tangent vectors with (dir1, dir2, normal) right-handed
 *    (dir2 = normal x dir1). Each is defined up to sign; the choice made is deterministic.
 *
 * @par Principal directions
 * The Weingarten matrix I^-1 II in the (Su, Sv) basis is not symmetric. The module
 * transforms it to the orthonormal frame e1 = Su/|Su|, e2 = n x e1 (Gram-Schmidt,
 * I = R^T R with R upper triangular, shape operator S = R^-T II R^-1, which is
 * symmetric and similar to I^-1 II), so the eigenvalues are real by construction and
 * the eigenvectors orthogonal. Of the two textbook eigenvector formulas
 * (s12, k1 - s11) and (k1 - s22, s12) the one without cancellation is used. At an
 * umbilic (k1 - k2 <= ::C2B_CURV_UMBILIC_REL * (|H| + (k1 - k2)/2), including a flat
 * point) every direction is principal and the module returns dir1 = e1 = Su/|Su| and
 * dir2 = n x e1.
 *
 * @par Scaling
 * The derivatives are scaled by an exact power of two before evaluation, so results do
 * not depend on the model scale and intermediate quantities neither overflow nor
 * underflow; only results that do not fit a double are reported.
 *
 * No allocation, no global state; all functions are reentrant.
 */
#ifndef C2B_CURV_H
#define C2B_CURV_H

#include <stddef.h>

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Number of doubles in one derivative block [S, Su, Sv, Suu, Suv, Svv]. */
#define C2B_CURV_BLOCK 18

/**
 * Default relative degeneracy tolerance, used when tol_rel <= 0 is passed.
 * A point is degenerate when (EG - F^2) <= tol_rel * E G, i.e. sin^2 of the angle
 * between Su and Sv is at most tol_rel (1e-14: angle below 1e-7 rad), or when
 * min(E, G) <= tol_rel * max(E, G) (one tangent vector vanishes relative to the other:
 * length ratio below 1e-7, as at a pole evaluated in floating point, where cos(pi/2) is
 * 6e-17 and not 0).
 */
#define C2B_CURV_TOL_REL_DEFAULT 1e-14

/**
 * A point is treated as umbilic when k1 - k2 <= C2B_CURV_UMBILIC_REL * (|H| + (k1-k2)/2),
 * i.e. when the principal curvatures agree to about 1e-12 relative (several thousand
 * rounding errors of the fundamental forms). Principal directions are then undetermined
 * and the deterministic pair (Su/|Su|, n x Su/|Su|) is returned.
 */
#define C2B_CURV_UMBILIC_REL 1e-12

/**
 * c2b_curv_normal_curvature_3d() rejects a direction whose tangential part is shorter
 * than C2B_CURV_TANGENT_REL times its length (angle to the normal below 1e-8 rad): the
 * tangential direction would carry fewer than half the significant digits.
 */
#define C2B_CURV_TANGENT_REL 1e-8

/** Differential geometry at one surface point (see the file comment for conventions). */
typedef struct c2b_curv_point {
    double normal[3];        /**< unit normal Su x Sv / |Su x Sv| */
    double E, F, G;          /**< first fundamental form: Su.Su, Su.Sv, Sv.Sv (unit^2) */
    double L, M, N;          /**< second fundamental form Suu.n, Suv.n, Svv.n (unit) */
    double K, H;             /**< Gaussian (1/unit^2) and mean (1/unit) curvature; H's
                                  sign follows the normal */
    double k1, k2;           /**< principal curvatures (1/unit), k1 >= k2 */
    double dir1[3], dir2[3]; /**< unit principal directions of k1 and k2 (3-D tangent
                                  vectors), dir2 = normal x dir1 */
    double metric_det;       /**< EG - F^2 (unit^4), computed as |Su x Sv|^2 (Lagrange's
                                  identity), which does not cancel */
} c2b_curv_point;

/**
 * @name Single point
 * @{
 */

/**
 * Differential geometry at one point.
 * @param d       derivative block, 18 doubles [S, Su, Sv, Suu, Suv, Svv] x (x, y, z).
 * @param tol_rel relative degeneracy tolerance (see ::C2B_CURV_TOL_REL_DEFAULT); pass a
 *                value <= 0 (or NaN) for the default 1e-14. Must be < 1.
 * @param out     result; written only on success.
 * @param err     optional error record.
 * @return C2B_OK;
 * @return C2B_ERR_ARG if d or out is NULL or tol_rel >= 1;
 * @return C2B_ERR_NUMERIC if an input entry is not finite (the message names it, e.g.
 *         "d[10] (Suu.y)"), if the point is degenerate — Su or Sv vanishes
 *         (absolutely or relative to the other), or Su x Sv vanishes
 *         (EG - F^2 <= tol_rel E G; the message gives EG-F^2 and the relative value) —
 *         or if a result does not fit a double. No division by a vanishing metric is
 *         ever performed and no NaN is returned.
 */
c2b_status c2b_curv_eval(const double *d, double tol_rel, c2b_curv_point *out, c2b_error *err);

/**
 * Normal curvature in the parameter-space direction (du, dv) = (a, b):
 * (L a^2 + 2 M a b + N b^2) / (E a^2 + 2 F a b + G b^2), in 1/unit, sign as in the file
 * comment. (a, b) need not be normalised (it is rescaled internally, so huge values do
 * not overflow). Equals Euler's k1 cos^2(t) + k2 sin^2(t), t the angle between
 * a Su + b Sv and dir1.
 * @return the normal curvature; NaN if p is NULL or (a, b) is (0, 0) or not finite (no
 *         direction). Use c2b_curv_normal_curvature_3d() for a checked variant.
 */
double c2b_curv_normal_curvature(const c2b_curv_point *p, double a, double b);

/**
 * Normal curvature in a 3-D direction t. t is first projected onto the tangent plane
 * (t - (t.n) n); the tangential part is expressed as a Su + b Sv and passed to
 * c2b_curv_normal_curvature().
 * @param d   the derivative block p was computed from (Su and Sv are used).
 * @param p   result of c2b_curv_eval() for d.
 * @param t   direction, 3 doubles; need not be unit or tangent.
 * @param kn  output normal curvature (1/unit); written only on success.
 * @return C2B_OK;
 * @return C2B_ERR_ARG if an argument is NULL or t is the zero vector;
 * @return C2B_ERR_NUMERIC if t or Su, Sv are not finite, or t is (nearly) normal to the
 *         surface: its tangential part is at most ::C2B_CURV_TANGENT_REL |t|.
 */
c2b_status c2b_curv_normal_curvature_3d(const double *d, const c2b_curv_point *p, const double *t,
                                        double *kn, c2b_error *err);

/** @} */

/**
 * @name Batch
 * @{
 */

/**
 * Differential geometry at n points whose derivative blocks start at d + i * stride.
 * A point that c2b_curv_eval() rejects with C2B_ERR_NUMERIC (degenerate or non-finite
 * input) does not fail the batch: flags[i] = 1 and every field of out[i] is NaN, so an
 * accidental use is visible. Valid points get flags[i] = 0.
 * @param n           number of points (0 is allowed; d may then be NULL).
 * @param d           first derivative block.
 * @param stride      distance between blocks in doubles, >= ::C2B_CURV_BLOCK.
 * @param tol_rel     as for c2b_curv_eval() (<= 0 selects the default).
 * @param out         n results (caller buffer).
 * @param flags       n flags (caller buffer), or NULL if not wanted.
 * @param ndegenerate receives the number of flagged points; may be NULL.
 * @return C2B_OK (also when points were flagged);
 * @return C2B_ERR_ARG if d (with n > 0) or out is NULL, stride < 18, tol_rel >= 1, or
 *         n * stride overflows size_t. Nothing is written then.
 */
c2b_status c2b_curv_eval_many(size_t n, const double *d, size_t stride, double tol_rel,
                              c2b_curv_point *out, unsigned char *flags, size_t *ndegenerate,
                              c2b_error *err);

/** @} */

#ifdef __cplusplus
}
#endif
#endif
