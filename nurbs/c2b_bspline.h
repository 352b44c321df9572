/**
 * @file c2b_bspline.h
 * B-spline basis functions and their derivatives for a knot vector (Piegl & Tiller
 * A2.1 and A2.3), for building collocation matrices.
 */
#ifndef C2B_BSPLINE_H
#define C2B_BSPLINE_H

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Knot span index i with knots[i] <= t < knots[i+1] for a spline of degree p with n
 * basis functions (knots has n + p + 1 entries); t at or beyond knots[n] maps to the
 * last non-empty span, t at or before knots[p] to the first.
 */
int c2b_bspline_span(int p, int n, const double *knots, double t);

/**
 * Values of the p + 1 non-zero basis functions N_{span-p..span, p}(t) and their
 * derivatives up to order nd (nd <= p allowed larger: higher ones are zero) into
 * ders[k * (p + 1) + j] for derivative k of function span - p + j.
 * work: caller scratch of at least (p + 1) * (p + 1) + 2 * (p + 1) doubles.
 */
void c2b_bspline_basis_derivs(int p, const double *knots, int span, double t, int nd,
                              double *ders, double *work);

#ifdef __cplusplus
}
#endif
#endif
