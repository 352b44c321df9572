/**
 * @file c2b_vec3.h
 * Small inline helpers for 3-vectors stored as double[3].
 */
#ifndef C2B_VEC3_H
#define C2B_VEC3_H

#include <math.h>

/** a . b */
static inline double c2b_vec3_dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/** c = a x b (c must not alias a or b). */
static inline void c2b_vec3_cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/** |a| */
static inline double c2b_vec3_norm(const double *a) { return sqrt(c2b_vec3_dot(a, a)); }

/** |a - b| */
static inline double c2b_vec3_dist(const double *a, const double *b)
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return c2b_vec3_norm(d);
}

#endif
