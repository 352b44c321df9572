"""The workbench's CGAL cross-check: CGAL's jet fitting on a tessellation of the C2 fillet
(no code shared with C2Blend) agrees with the analytic curvature of the blend face, and
the comparison fails when the analytic curvature is wrong (fault injected)."""
import os

import pytest

import C2Blend
import shapes
from c2bwb.geometry import cgalcheck
from c2bwb.geometry.surface import Frame

TOOL = os.environ.get("C2B_CGAL_TOOL")
pytestmark = pytest.mark.skipif(not TOOL, reason="C2B_CGAL_TOOL not set (ctest sets it)")


def fillet_faces():
    s, edge = shapes.shaft_on_plate()
    solid, rep = C2Blend.fillet_report(s, [edge], 2.0)
    blend = [solid.getElement(n) for n in sorted({r["blend_face"] for r in rep["trimlines"]})]
    other = [solid.getElement(n) for n in sorted({r["faces"][1] for r in rep["trimlines"]})]
    return solid, blend, other


def blend_errors(summary):
    r = summary["regions"]["blend"]["smooth"]
    return r["k1"], r["k2"], max(abs(summary["estimates"]["k1_max"]),
                                 abs(summary["estimates"]["k2_min"]))


def test_cgal_agrees_with_analytic_curvature():
    solid, blend, other = fillet_faces()
    summary = cgalcheck.cross_check(solid, blend, other, tool=TOOL)
    assert "error" not in summary, summary
    k1, k2, kmax = blend_errors(summary)
    assert summary["regions"]["blend"]["smooth"]["count"] > 1000
    # jet fits on a 17 x 129 grid: a few per cent of the largest curvature (1/R ~ 0.5)
    assert k1["mean_abs"] < 0.03 * kmax and k2["mean_abs"] < 0.03 * kmax
    assert k1["max_abs"] < 0.1 * kmax and k2["max_abs"] < 0.1 * kmax


def test_cgal_cross_check_can_fail(monkeypatch):
    solid, blend, other = fillet_faces()
    true_principal = Frame.principal
    monkeypatch.setattr(Frame, "principal",
                        lambda self: tuple(1.5 * x for x in true_principal(self)))
    summary = cgalcheck.cross_check(solid, blend, other, tool=TOOL)
    k1, k2, kmax = blend_errors(summary)
    assert max(k1["mean_abs"], k2["mean_abs"]) > 0.1 * kmax
