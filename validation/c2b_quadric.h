/**
 * @file c2b_quadric.h
 * Discrete normal and curvature of a triangle mesh (or point cloud) by implicit
 * quadric fitting: the estimator of seed 002 (Xie and Qin, "A Physics-based Framework
 * for Subdivision Surface Design with Automatic Rules Control", section 6.2 and
 * appendix A). It is the second curvature estimator of C2Blend, independent of the
 * analytic module c2b_curv.h, and is used to validate meshes of blends.
 *
 * @par Method (seed 002, section 6.2)
 * For a vertex p0 with neighbours p1..pn (its n-ring, section 6.2 "1-neighbors" or
 * "2-neighbors"):
 *  1. translate so that p0 = 0 (step 1) and scale by an exact power of two 2^e >=
 *     max_i |pi - p0|_inf, so the local coordinates lie in [-1, 1] (conditioning only;
 *     curvatures are scaled back exactly: K by 2^-2e, H, k1, k2 by 2^-e);
 *  2. fit the quadric
 *     F(x, y, z) = a x^2 + b y^2 + c z^2 + d xy + e yz + f zx + g x + h y + i z + j,
 *     with j = 0 (F interpolates p0, step 2) and the coefficient of the dominant
 *     component of a tentative normal fixed to 1 (steps 3-4: g = 1, h = 1 or i = 1),
 *     which leaves the "equation of only 8 unknowns" (step 5);
 *  3. solve the over-determined system A d = c (eqs. 20-21), one row F(pi) = 0 per
 *     neighbour, in the least-squares sense (eq. 22). The normal equations of eq. 22 are
 *     not formed: the system is solved by an SVD (LAPACK dgelss), which also yields its
 *     numerical rank and condition number;
 *  4. evaluate eq. 23 with grad F(0) = (g, h, i), the Hessian M (eq. 42) and its adjoint
 *     M* (eq. 43): D = |grad F|, n = grad F / D (eq. 46),
 *     K = n^T M* n / D^2 = grad F^T M* grad F / D^4 (eqs. 44, 47),
 *     H = n^T (M - trace(M) I) n / (2 D)
 *       = (grad F^T M grad F - |grad F|^2 trace M) / (2 D^3) (eqs. 45, 48).
 *
 * @par Choices where the seed leaves room (documented reading)
 *  - Tentative normal (step 3): the seed suggests "a cross-product between two adjacent
 *    edges". c2b_quadric_estimate() has no connectivity, so it uses the caller's
 *    normal_hint when given and otherwise the normal of the least-squares plane through p0
 *    (the right singular vector of the smallest singular value of the n x 3 matrix of
 *    the pi - p0, i.e. the eigenvector of the smallest eigenvalue of their scatter).
 *    c2b_quadric_estimate_mesh() passes the caller's normals, or else the area-weighted
 *    sum of the cross products of the edges of the triangles around the vertex. The
 *    tentative normal only selects which of g, h, i is fixed (and, for a hint, the
 *    orientation of the result); for data on a quadric the fit does not depend on it.
 *  - Step 4 says "assign 1.0"; the sign of F is immaterial (F and -F have the same zero
 *    set). The normal returned is grad F / D, flipped if needed so that it agrees with
 *    normal_hint (n . hint >= 0). Without a hint its orientation is the one of the fit:
 *    its component on the fixed axis is positive.
 *  - Because one coefficient is fixed along a coordinate axis (not along the normal), the
 *    fit is not rotation invariant for data that do not lie on a quadric, and where two
 *    components of the tentative normal tie the rounding of the input decides between
 *    two constraints. The two fits differ by much less than the discretisation error
 *    (measured: 2e-5 rad of normal, K unchanged to 1e-14, on a 64 x 32 torus whose
 *    normal error is 1.5e-2); quadrics are reproduced either way.
 *  - The seed's appendix A divides by f_z (a Monge graph over the xy-plane); eqs. 44-48
 *    are free of f_z and hold for any non-zero gradient, which is how they are used here.
 *  - k1, k2 (not given in the seed) are H +- sqrt(H^2 - K). H^2 - K is evaluated as
 *    ((s11 - s22)/2)^2 + s12^2, with s the shape operator -t_a^T M t_b / D in an
 *    orthonormal tangent frame (t1, t2) of n; it equals H^2 - K exactly in real
 *    arithmetic, is never negative and does not cancel at umbilics (sphere).
 *
 * @par Sign conventions (the same as c2b_curv.h)
 * A curvature is positive when the surface bends towards the returned normal:
 * k(t) = -t^T M t / D for a unit tangent t. Example: a sphere of radius R with the
 * outward normal has k1 = k2 = H = -1/R and K = 1/R^2. Flipping the normal flips H, k1,
 * k2 (and exchanges k1 and k2); K does not depend on the orientation. k1 >= k2.
 *
 * @par Exactness and accuracy
 * A sphere, a cylinder, a hyperbolic paraboloid and every other quadric through the
 * neighbourhood are reproduced exactly (up to rounding amplified by the condition
 * number; measured <= 2.5e-12 relative at condition 2.4e4 on 2-rings of a 128 x 128 grid)
 * whenever the system has full rank. For other smooth surfaces sampled on a
 * regular grid the error of K and H is O(h^2) with 2-ring neighbourhoods (measured in
 * tests/validation/test_quadric.c).
 *
 * @par Degenerate neighbourhoods
 * A quadric has 8 unknowns, so at least ::C2B_QUADRIC_MIN_NEIGHBOURS neighbours are
 * needed: a 1-ring of valence 6 (regular triangle grid) is not enough; use 2-rings there
 * (18 neighbours). Coplanar (flat) and collinear neighbourhoods do not determine the
 * quadric (every quadric containing the plane fits), nor do some grid-aligned 1-rings
 * (for instance a 3x3 stencil on three generators of a cylinder); all of these are
 * reported as C2B_ERR_NUMERIC, never as NaN. With exactly 8 neighbours the fit is an
 * interpolation and cannot detect a wrong quadric: on a torus's parabolic circle
 * (K = 0) the 3x3 stencil of a union-jack grid lies on two parallel planes, and the
 * unique interpolant is that plane pair (H = 0 instead of -1/2r). Prefer 2-rings.
 *
 * @par Memory
 * c2b_quadric_estimate() allocates O(n_nbrs) doubles of workspace per call;
 * c2b_quadric_estimate_mesh() allocates one workspace for the whole mesh. No global
 * state; all functions are reentrant.
 */
#ifndef C2B_QUADRIC_H
#define C2B_QUADRIC_H

#include <stddef.h>

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Number of unknown coefficients of the fitted quadric (seed 002, section 6.2, step 5). */
#define C2B_QUADRIC_UNKNOWNS 8

/** Fewest neighbours (besides the vertex itself) for which the fit is attempted. */
#define C2B_QUADRIC_MIN_NEIGHBOURS 8

/**
 * Relative rank threshold. (1) Neighbourhoods whose n x 3 matrix of local coordinates
 * pi - p0 has a second or third singular value below C2B_QUADRIC_RCOND times the first
 * are collinear or coplanar with p0. (2) In the 8-column least-squares system, singular
 * values below C2B_QUADRIC_RCOND times the largest count as zero (LAPACK dgelss rcond),
 * and numerical rank < 8 is rejected. In the scaled local frame the smallest singular
 * value of a curved neighbourhood is about (kappa rho)^2 (kappa a principal curvature,
 * rho the radius of the neighbourhood), so neighbourhoods flatter than kappa rho ~ 1e-6
 * are reported as rank-deficient, while the rounding noise of an exactly planar
 * neighbourhood (~1e-16) is always caught. Accepted fits lose about log10(condition)
 * digits (measured on sphere caps: error 2e-6 at condition 4e10, kappa rho ~ 4e-5).
 */
#define C2B_QUADRIC_RCOND 1e-12

/** Largest number of rings accepted by c2b_quadric_neighbourhoods_create(). */
#define C2B_QUADRIC_MAX_RINGS 16

/**
 * A triangle mesh, viewed (not owned): vertex i is xyz[3i..3i+2]; triangle t is
 * tri[3t..3t+2] (vertex indices, 0-based). Orientation of the triangles matters only
 * for the default normal hints of c2b_quadric_estimate_mesh().
 */
typedef struct c2b_quadric_mesh {
    size_t nv;         /**< number of vertices */
    size_t nt;         /**< number of triangles */
    const double *xyz; /**< nv x 3 coordinates (model units) */
    const size_t *tri; /**< nt x 3 vertex indices */
} c2b_quadric_mesh;

/** Result of one fit (see the file comment for the conventions). */
typedef struct c2b_quadric_result {
    double normal[3]; /**< unit normal grad F / |grad F| at the vertex, oriented to agree
                           with the normal hint when one is given */
    double K;         /**< Gaussian curvature (1/unit^2), eq. 44 */
    double H;         /**< mean curvature (1/unit), eq. 45; sign follows the normal */
    double k1, k2;    /**< principal curvatures (1/unit), k1 >= k2 */
    double residual;  /**< RMS over the neighbours of F(pi) / |grad F(p0)|, in model units:
                           a first-order estimate of their distance to the fitted quadric
                           (0 up to rounding when the data lie on a quadric) */
    double condition; /**< 2-norm condition number (largest / smallest singular value) of
                           the scaled 8-column least-squares matrix */
    double coef[9];   /**< a, b, c, d, e, f, g, h, i of F in the scaled local frame
                           x = (q - p0) / scale, signed so that grad F(0) / |grad F(0)|
                           = normal; coef[6 + axis] = +-1 */
    int axis;         /**< 0, 1, 2: which of g, h, i was fixed (step 4) */
    double scale;     /**< power of two used to scale the local coordinates (model units) */
} c2b_quadric_result;

/**
 * @name Neighbourhoods
 * n-ring neighbourhoods of all vertices of a mesh, in compressed rows. The 1-ring of v
 * is the set of vertices that share a triangle with v; the n-ring adds the 1-rings of the
 * (n-1)-ring. v itself is excluded. The object depends only on the connectivity, so it
 * can be reused while the vertices move.
 * @{
 */

/** Opaque neighbourhood table. */
typedef struct c2b_quadric_neighbourhoods c2b_quadric_neighbourhoods;

/**
 * Build the n-ring neighbourhoods of every vertex.
 * Triangles with a repeated vertex index, or whose two edge vectors have an exactly zero
 * cross product, are degenerate: they are accepted (their distinct vertices are still
 * adjacent) and counted (c2b_quadric_neighbourhoods_ndegenerate()).
 * @param m     mesh; m->xyz may be NULL only if m->nv is 0, m->tri only if m->nt is 0.
 * @param rings number of rings, 1 .. ::C2B_QUADRIC_MAX_RINGS.
 * @param out   receives the new object (NULL on failure); free with
 *              c2b_quadric_neighbourhoods_destroy().
 * @param err   optional error record.
 * @return C2B_OK;
 * @return C2B_ERR_ARG if m, out or a needed array is NULL, or rings < 1;
 * @return C2B_ERR_LIMIT if rings > ::C2B_QUADRIC_MAX_RINGS or a size overflows;
 * @return C2B_ERR_SPEC if a triangle has a vertex index >= nv (the message names the
 *         triangle, the corner and the index) or a vertex coordinate is not finite (the
 *         message names the vertex);
 * @return C2B_ERR_NOMEM if an allocation fails.
 */
c2b_status c2b_quadric_neighbourhoods_create(const c2b_quadric_mesh *m, int rings,
                                             c2b_quadric_neighbourhoods **out, c2b_error *err);

/** Free the object. NULL-safe. */
void c2b_quadric_neighbourhoods_destroy(c2b_quadric_neighbourhoods *nb);

/** Number of vertices of the mesh the object was built from (0 for NULL). */
size_t c2b_quadric_neighbourhoods_nv(const c2b_quadric_neighbourhoods *nb);

/** Number of rings (0 for NULL). */
int c2b_quadric_neighbourhoods_rings(const c2b_quadric_neighbourhoods *nb);

/** Number of neighbours of vertex v (0 for NULL or v >= nv). */
size_t c2b_quadric_neighbourhoods_count(const c2b_quadric_neighbourhoods *nb, size_t v);

/**
 * Neighbours of vertex v, ordered by ring distance (the whole 1-ring first, in
 * ascending index order; the order within later rings is deterministic). The pointer
 * refers to storage owned by nb and stays valid until nb is destroyed; the list has
 * c2b_quadric_neighbourhoods_count() entries. NULL for NULL or v >= nv.
 */
const size_t *c2b_quadric_neighbourhoods_list(const c2b_quadric_neighbourhoods *nb, size_t v);

/** Largest neighbour count over all vertices (0 for NULL). */
size_t c2b_quadric_neighbourhoods_max_count(const c2b_quadric_neighbourhoods *nb);

/** Number of degenerate triangles found by c2b_quadric_neighbourhoods_create(). */
size_t c2b_quadric_neighbourhoods_ndegenerate(const c2b_quadric_neighbourhoods *nb);

/**
 * 1 if vertex v or one of its neighbours is a border vertex, else 0 (also for NULL or
 * v >= nv). A border vertex is an endpoint of an edge used by exactly one triangle, or by
 * more than two (non-manifold). Vertices with 0 returned have complete rings: the
 * interior vertices of convergence studies.
 */
int c2b_quadric_neighbourhoods_touches_border(const c2b_quadric_neighbourhoods *nb, size_t v);

/** @} */

/**
 * @name Estimation
 * @{
 */

/**
 * Normal and curvature at p from its neighbours (seed 002, section 6.2, eq. 23).
 * @param p           query point (3 doubles), interpolated by the quadric.
 * @param n_nbrs      number of neighbours, >= ::C2B_QUADRIC_MIN_NEIGHBOURS.
 * @param nbr_xyz     n_nbrs x 3 coordinates; p itself must not be repeated among them.
 * @param normal_hint tentative normal (3 doubles, any non-zero length) used to choose the
 *                    fixed coefficient and to orient the result; may be NULL.
 * @param out         result; written only on success.
 * @param err         optional error record.
 * @return C2B_OK;
 * @return C2B_ERR_ARG if p, out or (with n_nbrs > 0) nbr_xyz is NULL, or normal_hint is
 *         zero or not finite;
 * @return C2B_ERR_LIMIT if n_nbrs exceeds the size LAPACK can index;
 * @return C2B_ERR_NUMERIC if there are fewer than 8 neighbours, a coordinate is not finite
 *         (the message names it), all neighbours coincide with p, the neighbours are
 *         collinear or coplanar with p, the 8-unknown system has numerical rank < 8
 *         (::C2B_QUADRIC_RCOND; the message gives the rank and the singular values), or a
 *         result does not fit a double;
 * @return C2B_ERR_NOMEM if the workspace cannot be allocated.
 */
c2b_status c2b_quadric_estimate(const double *p, size_t n_nbrs, const double *nbr_xyz,
                                const double *normal_hint, c2b_quadric_result *out, c2b_error *err);

/**
 * Normal and curvature at every vertex of a mesh.
 * @param m       mesh; nb must have been built from the same connectivity (nv, nt and
 *                tri); the coordinates may have changed since.
 * @param nb      neighbourhoods of m.
 * @param normals nv x 3 normal hints, or NULL. A zero row means "no hint" for that
 *                vertex. Without normals, the hint of a vertex is the sum over its
 *                triangles of (b - a) x (c - a) (area-weighted, following the triangle
 *                orientation), so a consistently oriented mesh gets consistent normals.
 * @param out     nv results (caller buffer).
 * @param ok      nv flags (caller buffer) or NULL: 1 where the fit succeeded, 0 where it
 *                failed (out[v] is then all NaN so that an accidental use is visible).
 * @param err     optional error record.
 * @return C2B_OK if every vertex succeeded;
 * @return C2B_ERR_NUMERIC if some vertices failed with a numerical error; every vertex
 *         has still been processed and out and ok are fully written. The message is the
 *         one of the first failed vertex, prefixed with "vertex <index>: " and followed by
 *         the number of failed vertices;
 * @return C2B_ERR_ARG if m, nb or out is NULL, m->xyz is NULL with nv > 0, nv or nt
 *         differ from nb's, or a normals entry is not finite (the message names the
 *         vertex). Nothing is written then;
 * @return C2B_ERR_LIMIT if a neighbourhood is too large for LAPACK;
 * @return C2B_ERR_NOMEM if the workspace cannot be allocated. Nothing is written then.
 */
c2b_status c2b_quadric_estimate_mesh(const c2b_quadric_mesh *m, const c2b_quadric_neighbourhoods *nb,
                                     const double *normals, c2b_quadric_result *out, unsigned char *ok,
                                     c2b_error *err);

/** @} */

#ifdef __cplusplus
}
#endif
#endif
