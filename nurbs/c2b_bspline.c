#include "c2b_bspline.h"

int c2b_bspline_span(int p, int n, const double *knots, double t)
{
    if (t >= knots[n]) {
        int i = n - 1;
        while (i > p && knots[i] == knots[i + 1])
            i--;
        return i;
    }
    if (t <= knots[p])
        return p;
    int lo = p, hi = n;
    while (hi - lo > 1) { /* knots[lo] <= t < knots[hi] */
        int mid = (lo + hi) / 2;
        if (t < knots[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

void c2b_bspline_basis_derivs(int p, const double *knots, int span, double t, int nd,
                              double *ders, double *work)
{
    int w = p + 1;
    double *ndu = work;          /* (p+1) x (p+1): basis values and knot differences */
    double *left = work + w * w; /* p + 1 */
    double *right = left + w;    /* p + 1 */
    ndu[0] = 1.0;
    for (int j = 1; j <= p; j++) {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; r++) {
            ndu[j * w + r] = right[r + 1] + left[j - r]; /* lower triangle: differences */
            double tmp = ndu[r * w + j - 1] / ndu[j * w + r];
            ndu[r * w + j] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        ndu[j * w + j] = saved;
    }
    for (int j = 0; j <= p; j++)
        ders[j] = ndu[j * w + p];
    for (int k = 1; k <= nd; k++)
        for (int j = 0; j <= p; j++)
            ders[k * w + j] = 0.0;
    /* Derivatives: two rows of coefficients a (s1, s2), P&T A2.3. */
    double a[2][64];
    for (int r = 0; r <= p && p < 64; r++) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= nd && k <= p; k++) {
            double d = 0.0;
            int rk = r - k, pk = p - k;
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[(pk + 1) * w + rk];
                d = a[s2][0] * ndu[rk * w + pk];
            }
            int j1 = rk >= -1 ? 1 : -rk;
            int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; j++) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[(pk + 1) * w + rk + j];
                d += a[s2][j] * ndu[(rk + j) * w + pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[(pk + 1) * w + r];
                d += a[s2][k] * ndu[r * w + pk];
            }
            ders[k * w + r] = d;
            int tmp = s1;
            s1 = s2;
            s2 = tmp;
        }
    }
    double f = p;
    for (int k = 1; k <= nd && k <= p; k++) {
        for (int j = 0; j <= p; j++)
            ders[k * w + j] *= f;
        f *= p - k;
    }
}
