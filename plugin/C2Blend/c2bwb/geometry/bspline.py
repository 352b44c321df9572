# SPDX-License-Identifier: LGPL-2.1-or-later
"""From a C2Blend spec to a FreeCAD B-spline surface, through the c2blend kernel."""
import Part

import c2blend

from ..errors import C2BlendError


def fit_surface(spec, tol_rel, where):
    """Solve the blend of `spec` and fit it at tol_rel (relative to its bounding-box
    diagonal). Returns (Part.BSplineSurface, fit dict, c2blend.Blend).
    Kernel errors become C2BlendError naming `where`."""
    try:
        blend = c2blend.Blend(spec)
        fit = blend.fit(tol=tol_rel)
    except c2blend.NumericalError as ex:
        raise C2BlendError("the blend cannot be computed: %s" % ex, where, "numeric") from ex
    except c2blend.Error as ex:
        raise C2BlendError("bad blend data: %s" % ex, where, "kernel") from ex
    surf = Part.BSplineSurface()
    surf.buildFromPolesMultsKnots(fit["poles"].tolist(), fit["umults"], fit["vmults"],
                                  fit["uknots"], fit["vknots"], fit["uperiodic"],
                                  fit["vperiodic"], fit["udegree"], fit["vdegree"])
    return surf, fit, blend
