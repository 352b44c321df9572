# SPDX-License-Identifier: LGPL-2.1-or-later
"""Task panel of C2 Fillet: the size (a radius or a setback) above the shared rows of
params_panel."""
from PySide import QtGui

from ..geometry import fillet as fl, inputs
from ..objects import make
from .params_panel import ParamsPanel


class FilletPanel(ParamsPanel):
    """Create a C2Fillet (base, edges given) or edit one (obj given)."""

    TITLE = "C2 Fillet"

    def __init__(self, base=None, edges=None, obj=None):
        self.base, self.edges = (obj.Base[0], list(obj.Base[1])) if obj else (base, edges)
        super().__init__(obj)

    def add_rows(self, lay):
        self.size = QtGui.QComboBox()  # what the number is: the radius or the setback
        self.size.addItems(["Radius", "Setback"])
        self.radius = QtGui.QDoubleSpinBox()
        self.radius.setRange(1e-4, 1e6)
        self.radius.setDecimals(4)
        self.radius.setValue(float(self.obj.Radius) if self.obj else 1.0)
        row = QtGui.QHBoxLayout()
        row.addWidget(self.size)
        row.addWidget(self.radius)
        lay.addRow("Size", row)
        self.watch(self.size.currentIndexChanged)
        self.watch(self.radius.valueChanged)

    def parameters(self):
        """(radius or setback, continuity, (Gamma, Eta, Lambda, Rho), tension) as shown."""
        return (self.radius.value(),) + self.shape_values()

    def fillet_parameters(self):
        """(radius, continuity, its shape parameters, tension): a setback becomes the
        radius (inputs.radius_for_setback). Raises C2BlendError."""
        size = self.radius.value()
        radius = size if self.size.currentText() == "Radius" else \
            inputs.radius_for_setback(self.base.Shape, self.edges, size, self.base.Label)
        return (radius,) + self.blend_parameters()

    def compute(self):
        radius, cont, sp, tension = self.fillet_parameters()
        solid, rep = fl.fillet(self.base.Shape, self.edges, radius, cont, sp, tension,
                               self.base.Label, bop=False)  # OK runs the full check
        kept = "".join("\nKept as OCCT's G1 fillet at %s: %s" % (k["where"], k["reason"])
                       for k in rep["kept_occt_faces"])
        kept += "".join("\n%s filled, normals within %.1e rad (not G2)" % (c["where"], c["g1"])
                        for c in rep["corner_patches"])
        kept += "".join("\nLeft out %s: %s" % (k["where"], k["reason"])
                        for k in rep["skipped_edges"])
        return solid, ("%s; radius %.6g; %d blend face(s), fit deviation %.2g, %.0f ms%s"
                       % (rep["verdict"], radius, len(rep["blends"]),
                          max([b["fit_deviation"] for b in rep["blends"]] or [0.0]),
                          1e3 * rep["seconds"], kept))

    def create(self):
        return make.make_fillet(self.base, self.edges, *self.fillet_parameters())

    def store(self, obj):
        obj.Radius = self.fillet_parameters()[0]
