/**
 * @file c2b_vseries.h
 * Functions of v as finite sums of modes (MATH.md section 3).
 *
 * The local coordinate is s = v - v0 on [0, L], L = v1 - v0 (v_range is not
 * normalised). Every term is a function with f'' = beta f or a power of s:
 *   POW  s^m                     beta 0 (exact polynomial recursion)
 *   COS  cos(omega s)            beta -omega^2
 *   SIN  sin(omega s)            beta -omega^2
 *   EXPP exp(omega (s - L))      beta +omega^2 (<= 1 on [0, L])
 *   EXPM exp(-omega s)           beta +omega^2 (<= 1 on [0, L])
 */
#ifndef C2B_VSERIES_H
#define C2B_VSERIES_H

#include "c2b_error.h"
#include "c2b_tolerance.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum c2b_vkind {
    C2B_VF_POW = 0,
    C2B_VF_COS = 1,
    C2B_VF_SIN = 2,
    C2B_VF_EXPP = 3,
    C2B_VF_EXPM = 4
} c2b_vkind;

/** One mode function of v. */
typedef struct c2b_vfunc {
    c2b_vkind kind;
    int power;    /**< POW only */
    double omega; /**< COS, SIN, EXPP, EXPM: angular frequency in 1/unit v (> 0) */
} c2b_vfunc;

/** One term amp * f(s). */
typedef struct c2b_vterm {
    c2b_vfunc f;
    double amp;
} c2b_vterm;

/** How a function was represented. */
typedef enum c2b_vmethod {
    C2B_VM_ZERO = 0,    /**< identically zero on the check points */
    C2B_VM_POLY = 1,    /**< polynomial in v, exact */
    C2B_VM_MODE = 2,    /**< f'' = beta f (differential property) plus a cubic, closed form */
    C2B_VM_FFT = 3,     /**< periodic: real FFT, truncated */
    C2B_VM_DST = 4      /**< open: end polynomial + sine series (DST-I), truncated */
} c2b_vmethod;

/** Name of a method ("zero", "polynomial", "mode", "fft", "dst"). */
const char *c2b_vmethod_name(c2b_vmethod m);

/** Name of a kind ("pow", "cos", "sin", "expp", "expm"). */
const char *c2b_vkind_name(c2b_vkind k);

/** beta of a mode function (f'' = beta f; 0 for POW). */
double c2b_vfunc_beta(const c2b_vfunc *f);

/** f(s); L is the range length (EXPP is exp(omega (s - L))). */
double c2b_vfunc_value(const c2b_vfunc *f, double s, double L);

/** f^{(q)}(s), q = 0..maxd (maxd <= 3), into out[q]; L is the range length. */
void c2b_vfunc_eval(const c2b_vfunc *f, double s, double L, int maxd, double *out);

/** 1 when two mode functions are the same (omega equal to 1e-13 relative). */
int c2b_vfunc_same(const c2b_vfunc *a, const c2b_vfunc *b);

/**
 * The q-th derivative of f as a multiple of a function of the same family:
 * f^{(q)} = factor * g (POW s^m: m!/(m-q)! s^(m-q), factor 0 for q > m; COS and SIN:
 * +-omega^q times COS or SIN; EXPP, EXPM: (+-omega)^q times itself). Fills *g and
 * returns factor.
 */
double c2b_vfunc_derivative(const c2b_vfunc *f, int q, c2b_vfunc *g);

/**
 * Exact order of mode functions (for sorting): powers first by power, then by omega,
 * then kind, so that COS and SIN of one omega are neighbours. Returns <0, 0 or >0.
 */
int c2b_vfunc_compare(const c2b_vfunc *a, const c2b_vfunc *b);

/** A function of v expanded into modes; owns `terms`. Zero-initialise before use. */
typedef struct c2b_vseries {
    c2b_vterm *terms;
    int n, cap;
    c2b_vmethod method;
    int n_samples;   /**< samples used (FFT/DST), or evaluations for exact methods */
    double scale;    /**< max |f| seen */
    double err_abs;  /**< measured truncation error (max over check points) */
} c2b_vseries;

/** Free the terms and reset to empty. NULL-safe. */
void c2b_vseries_clear(c2b_vseries *s);

/** The v-domain of the trimlines. */
typedef struct c2b_vdomain {
    double v0, v1;
    int periodic;
} c2b_vdomain;

/** A scalar boundary function f(v, t) supplied by the caller. */
typedef double (*c2b_vt_fn)(void *ctx, double v, double t);

/**
 * Expand f(., t) over the domain. Tries, in order: zero; a polynomial of degree <=
 * tol->max_poly_degree (exact); on open domains the differential property
 * f'' = beta f plus a polynomial of degree <= 3 (exact pair of modes and powers);
 * otherwise periodic data by real FFT and open
 * data by a quintic (matching f, f'' and, where the samples resolve it, f'''' at
 * both ends; f2 is the exact second v-derivative, or NULL for one-sided finite
 * differences; f'''' always comes from one-sided differences) plus a DST-I sine
 * series, doubling the samples until the error at the midpoints and at 33 points off
 * the dyadic grid (which an aliased mode cannot match) is below
 * tol->truncation_rel * scale or tol->max_samples is reached. The error actually
 * reached is in out->err_abs.
 * @return C2B_OK; C2B_ERR_SPEC when f is not finite somewhere (message gives v);
 *         C2B_ERR_NOMEM.
 */
c2b_status c2b_vseries_project(const c2b_vdomain *dom, c2b_vt_fn f, c2b_vt_fn f2, void *ctx,
                               double t, const c2b_tolerances *tol, c2b_vseries *out,
                               c2b_error *err);

/**
 * Expand uniform samples: periodic data are n samples at v0 + i L / n (end not
 * repeated); open data are n >= 7 samples at v0 + i L / (n-1). err_abs is the larger
 * of the error at the samples (after small modes are dropped) and a leave-half-out
 * estimate: the series built from every other sample, checked at the samples left
 * out (an even count on an open range: of the first n - 1 samples, over the range
 * they span; an odd count on a periodic range: no estimate). The latter bounds the
 * error between samples (conservatively, since it is measured at half the resolution).
 * @return C2B_OK; C2B_ERR_SPEC for too few or non-finite samples; C2B_ERR_LIMIT for
 *         more than 4 * tol->max_samples samples; C2B_ERR_NOMEM.
 */
c2b_status c2b_vseries_project_samples(const c2b_vdomain *dom, const double *samples,
                                       int stride, int n, const c2b_tolerances *tol,
                                       c2b_vseries *out, c2b_error *err);

/** Value of the series at v (derivatives q = 0..maxd into out). */
void c2b_vseries_eval(const c2b_vseries *s, const c2b_vdomain *dom, double v, int maxd,
                      double *out);

#ifdef __cplusplus
}
#endif
#endif
