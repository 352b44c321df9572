# SPDX-License-Identifier: LGPL-2.1-or-later
"""From a C2Blend spec to a FreeCAD B-spline surface, through the c2blend kernel.
Kernel errors become C2BlendError naming `where` (object and edge)."""
import math

import Part

import c2blend

from ..errors import C2BlendError


def _kernel(fn, where):
    try:
        return fn()
    except c2blend.NumericalError as ex:
        raise C2BlendError("the blend cannot be computed: %s" % ex, where, "numeric") from None
    except c2blend.Error as ex:
        raise C2BlendError("bad blend data: %s" % ex, where, "kernel") from None


def solve(spec, where):
    """The kernel's blend (c2blend.Blend) of a spec dict."""
    return _kernel(lambda: c2blend.Blend(spec), where)


# Poles per direction the fit may use (the kernel's default is 400). An elliptic boss's
# top edge (12 x 6, R = 2) needs 30 x 599: with 400 its trimline rows stopped at 1.3e-10
# of the 1e-10 their contact needs, and OCCT's G1 face was kept.
MAX_POLES = 1000


def fit_surface(blend, tol_rel, where):
    """Fit blend at tol_rel (relative to its bounding-box diagonal), with at most
    MAX_POLES poles per direction; returns (Part.BSplineSurface, fit dict)."""
    fit = _kernel(lambda: blend.fit(tol=tol_rel, max_poles=MAX_POLES), where)
    surf = Part.BSplineSurface()
    surf.buildFromPolesMultsKnots(fit["poles"].tolist(), fit["umults"], fit["vmults"],
                                  fit["uknots"], fit["vknots"], fit["uperiodic"],
                                  fit["vperiodic"], fit["udegree"], fit["vdegree"])
    return surf, fit


def data_error(blend):
    """Largest truncation error of the blend's boundary data, relative to the scale of
    the same datum (S, S_u, ...) over the three components. The scale of S_uu and
    higher is at least that of S_u on the same side (all are lengths: u is
    dimensionless), so data that vanish across a straight face (zero normal
    curvature: S_uu is rounding noise) are not measured against their own noise."""
    info = blend.info()
    scale = {}
    for comp in info["components"]:
        for bd in comp["boundary_data"]:
            key = (bd["side"], bd["datum"])
            scale[key] = max(scale.get(key, 0.0), bd["scale"])
    for (side, datum), s in list(scale.items()):
        if datum not in ("S", "S_u"):
            scale[(side, datum)] = max(s, scale.get((side, "S_u"), 0.0))
    worst = 0.0
    for comp in info["components"]:
        for bd in comp["boundary_data"]:
            s = scale[(bd["side"], bd["datum"])]
            if bd["truncation_error"] > 0.0:
                worst = max(worst, bd["truncation_error"] / s if s > 0 else float("inf"))
    return worst


def solve_sampled(rows_at, spec_of, where, samples, max_samples, target, hopeless,
                  smooth=False):
    """Sample boundary rows (rows_at(n) -> (rows0, rows1)), doubling n from `samples`
    until the kernel's measured data error is below `target`, stops improving (less
    than 2x on each of two doublings in a row: one slow doubling can be the start of
    algebraic convergence, as where a face's seam is only G2), or n reaches
    max_samples. It also stops where convergence is algebraic (the gain per doubling no
    longer grows, as where data that are not smooth cross a spline's knot) and, at the
    last gain, the error would still be above `hopeless` at max_samples. `smooth` data,
    analytic by construction, are not taken to stop improving: their error may stay
    flat until the samples resolve their finest feature (a piece of a free-form boss's
    rim at R = 0.8, between knot lines, measured 1.6e-2, 2.0e-2 and 1.9e-2 with 32 to
    128 samples, then 3.6e-4, 4.4e-7 and 8.5e-9 up to 1024). Returns (blend, n, error)
    of the smallest error found."""
    n, errs, best = samples, [], None
    while True:
        rows0, rows1 = rows_at(n)
        blend = solve(spec_of(rows0, rows1), where)
        err = data_error(blend)
        errs.append(err)
        if best is None or err < best[2]:
            best = (blend, n, err)
        stalled = not smooth and len(errs) > 2 and err > 0.5 * errs[-2] and \
            errs[-2] > 0.5 * errs[-3]
        if err <= target or 2 * n > max_samples or stalled:
            return best
        if len(errs) > 2:
            gain, before = errs[-2] / err, errs[-3] / errs[-2]
            if gain <= before and err / gain ** math.log2(max_samples / n) > hopeless:
                return best
        n *= 2
