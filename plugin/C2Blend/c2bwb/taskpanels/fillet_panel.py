# SPDX-License-Identifier: LGPL-2.1-or-later
"""Task panel of C2 Fillet: radius (or setback), continuity, gamma, eta, lambda, rho and
tension with a live preview (a view decoration, so the document is not touched until OK).
C1 takes gamma, eta, lambda as its b, c, d; C3 takes the four as a0..a3 with a4 = 1."""
import math

import FreeCADGui
from PySide import QtCore, QtGui
from pivy import coin

from ..errors import C2BlendError
from ..geometry import fillet as fl
from ..objects import features, make

# (name, low, high) of the sliders: shape parameters on a log scale (their effect grows
# with the v-frequency of the data, so useful values span decades), tension linear. The
# box beside each slider takes any value, negative shape parameters too.
SLIDERS = (("Gamma", 0.01, 100.0), ("Eta", 0.01, 100.0), ("Lambda", 0.01, 100.0),
           ("Rho", 0.01, 100.0), ("Tension", 0.2, 3.0))
DECIMALS = 6


class FilletPanel:
    """Create a C2Fillet (base, edges given) or edit one (obj given)."""

    def __init__(self, base=None, edges=None, obj=None):
        self.obj, self.base, self.edges = obj, base, edges
        if obj is not None:
            self.base, self.edges = obj.Base[0], list(obj.Base[1])
        self.form = QtGui.QWidget()
        self.form.setWindowTitle("C2 Fillet")
        lay = QtGui.QFormLayout(self.form)
        self.size = QtGui.QComboBox()  # what the number is: the radius or the setback
        self.size.addItems(["Radius", "Setback"])
        self.radius = QtGui.QDoubleSpinBox()
        self.radius.setRange(1e-4, 1e6)
        self.radius.setDecimals(4)
        self.radius.setValue(float(obj.Radius) if obj else 1.0)
        row = QtGui.QHBoxLayout()
        row.addWidget(self.size)
        row.addWidget(self.radius)
        lay.addRow("Size", row)
        self.cont = QtGui.QComboBox()
        self.cont.addItems(["C2", "C1", "C3"])
        if obj:
            self.cont.setCurrentIndex(["C2", "C1", "C3"].index(obj.Continuity))
        lay.addRow("Continuity", self.cont)
        self.sliders, self.spins = {}, {}
        for name, lo, hi in SLIDERS:
            s = QtGui.QSlider(QtCore.Qt.Horizontal)
            s.setRange(0, 1000)
            s.lo, s.hi = lo, hi
            box = QtGui.QDoubleSpinBox()  # the value; the slider moves it on its scale
            box.setDecimals(DECIMALS)
            box.setRange(1e-6 if name == "Tension" else -1e6, 1e6)
            box.setValue(getattr(obj, name) if obj else 1.0)
            s.setValue(self.position(s, box.value()))
            s.valueChanged.connect(lambda _v, s=s, box=box: box.setValue(self.value(s)))
            box.valueChanged.connect(lambda v, s=s: self.follow(s, v))
            row = QtGui.QHBoxLayout()
            row.addWidget(s)
            row.addWidget(box)
            lay.addRow(name, row)
            self.sliders[name], self.spins[name] = s, box
        self.status = QtGui.QLabel()
        self.status.setWordWrap(True)
        lay.addRow(self.status)
        self.preview_node = None
        self.timer = QtCore.QTimer()
        self.timer.setSingleShot(True)
        self.timer.timeout.connect(self.preview)
        for w in list(self.spins.values()):
            w.valueChanged.connect(lambda _v: self.timer.start(150))
        self.radius.valueChanged.connect(lambda _v: self.timer.start(150))
        self.size.currentIndexChanged.connect(lambda _v: self.timer.start(150))
        self.cont.currentIndexChanged.connect(lambda _v: self.timer.start(150))
        self.timer.start(10)

    @staticmethod
    def value(s):
        """Slider position (0..1000) to parameter value."""
        x = s.value() / 1000.0
        if s.lo > 0 and s.hi / s.lo > 100:
            return s.lo * (s.hi / s.lo) ** x
        return s.lo + (s.hi - s.lo) * x

    def follow(self, s, value):
        """Move slider s to a value typed in its box, without changing the value (a
        tension of 1 is at position 286, which is 1.0008: the box keeps 1)."""
        s.blockSignals(True)
        s.setValue(self.position(s, value))
        s.blockSignals(False)

    @staticmethod
    def position(s, value):
        """Parameter value to slider position (clamped)."""
        if s.lo > 0 and s.hi / s.lo > 100:
            x = math.log(max(value, s.lo) / s.lo) / math.log(s.hi / s.lo)
        else:
            x = (value - s.lo) / (s.hi - s.lo)
        return int(round(1000 * min(max(x, 0.0), 1.0)))

    def parameters(self):
        """(radius or setback, continuity, (Gamma, Eta, Lambda, Rho), tension) as shown."""
        v = {k: box.value() for k, box in self.spins.items()}
        return (self.radius.value(), self.cont.currentText(),
                (v["Gamma"], v["Eta"], v["Lambda"], v["Rho"]), v["Tension"])

    def fillet_parameters(self):
        """(radius, continuity, its shape parameters, tension): a setback becomes the
        radius (fillet.radius_for_setback); C1 takes the first three of Gamma..Rho, C3
        the four and 1 (features.shape_params). Raises C2BlendError."""
        size, cont, sp, tension = self.parameters()
        radius = size if self.size.currentText() == "Radius" else \
            fl.radius_for_setback(self.base.Shape, self.edges, size, self.base.Label)
        return radius, cont, features.shape_params(cont, sp), tension

    def preview(self):
        """Recompute the fillet for the current values and show it in the view."""
        self.clear_preview()
        try:
            radius, cont, sp, tension = self.fillet_parameters()
            solid, rep = fl.fillet(self.base.Shape, self.edges, radius, cont, sp, tension,
                                   self.base.Label, bop=False)  # OK runs the full check
        except C2BlendError as ex:
            self.status.setText("Cannot fillet: %s" % ex)
            return
        kept = "".join("\nKept as OCCT's G1 fillet at %s: %s" % (k["where"], k["reason"])
                       for k in rep["kept_occt_faces"])
        kept += "".join("\n%s filled, normals within %.1e rad (not G2)" % (c["where"], c["g1"])
                        for c in rep["corner_patches"])
        self.status.setText("%s; radius %.6g; %d blend face(s), fit deviation %.2g, %.0f ms%s"
                            % (rep["verdict"], radius, len(rep["blends"]),
                               max([b["fit_deviation"] for b in rep["blends"]] or [0.0]),
                               1e3 * rep["seconds"], kept))
        node = coin.SoSeparator()
        mat = coin.SoMaterial()
        mat.diffuseColor.setValue(0.85, 0.55, 0.2)
        node.addChild(mat)
        pts, tris = solid.tessellate(solid.BoundBox.DiagonalLength * 2e-3)
        c = coin.SoCoordinate3()
        c.point.setValues(0, len(pts), [(p.x, p.y, p.z) for p in pts])
        node.addChild(c)
        fs = coin.SoIndexedFaceSet()
        idx = [i for t in tris for i in (t[0], t[1], t[2], -1)]
        fs.coordIndex.setValues(0, len(idx), idx)
        node.addChild(fs)
        FreeCADGui.ActiveDocument.ActiveView.getSceneGraph().addChild(node)
        self.preview_node = node

    def clear_preview(self):
        if self.preview_node is not None:
            FreeCADGui.ActiveDocument.ActiveView.getSceneGraph().removeChild(self.preview_node)
            self.preview_node = None

    def accept(self):
        self.timer.stop()
        self.clear_preview()
        try:
            radius, cont, sp, tension = self.fillet_parameters()
            if self.obj is None:
                self.obj = make.make_fillet(self.base, self.edges, radius, cont, sp, tension)
            else:
                doc = self.obj.Document
                doc.openTransaction("C2 Fillet: edit")
                self.obj.Radius = radius
                self.obj.Continuity = cont
                self.obj.Gamma, self.obj.Eta, self.obj.Lambda, self.obj.Rho = \
                    features.object_values(cont, sp)
                self.obj.Tension = tension
                doc.recompute()
                if "Invalid" in self.obj.State:
                    doc.abortTransaction()
                    doc.recompute()
                    raise C2BlendError(getattr(self.obj.Proxy, "last_error", "recompute failed"),
                                       self.obj.Label)
                doc.commitTransaction()
        except C2BlendError as ex:
            QtGui.QMessageBox.critical(None, "C2 Fillet", str(ex))
            return False
        FreeCADGui.Control.closeDialog()
        if self.obj is not None:
            FreeCADGui.ActiveDocument.resetEdit()
        return True

    def reject(self):
        self.timer.stop()
        self.clear_preview()
        FreeCADGui.Control.closeDialog()
        if self.obj is not None:
            FreeCADGui.ActiveDocument.resetEdit()
        return True

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)


