# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the task panels of C2 Fillet and C2 Blend faces share: continuity, gamma, eta,
lambda, rho and tension, each a slider with a box holding its value, and a live preview
(a view decoration, so the document is not touched until OK). C1 takes gamma, eta,
lambda as its b, c, d; C3 takes the four as a0..a3 with a4 = 1 (features.shape_params).

A panel creates an object (obj None) or edits one; subclasses add their own rows
(add_rows) and say how to compute the preview (compute), create the object (create) and
store their own values in it (store)."""
import math

import FreeCADGui
from PySide import QtCore, QtGui
from pivy import coin

from ..errors import C2BlendError
from ..objects import features, make

# (name, low, high) of the sliders: shape parameters on a log scale (their effect grows
# with the v-frequency of the data, so useful values span decades), tension linear. The
# box beside each slider takes any value, negative shape parameters too.
SLIDERS = (("Gamma", 0.01, 100.0), ("Eta", 0.01, 100.0), ("Lambda", 0.01, 100.0),
           ("Rho", 0.01, 100.0), ("Tension", 0.2, 3.0))
DECIMALS = 6
CONTINUITIES = ["C2", "C1", "C3"]


class ParamsPanel:
    """Task panel base: TITLE, the shared rows and the preview/OK/Cancel logic."""

    TITLE = ""

    def __init__(self, obj=None):
        self.obj = obj
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(self.TITLE)
        lay = QtGui.QFormLayout(self.form)
        # the Combo view is narrow: a row whose slider and box do not fit beside the
        # label goes below it, so that the slider keeps a usable length
        lay.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        self.timer = QtCore.QTimer()
        self.timer.setSingleShot(True)
        self.timer.timeout.connect(self.preview)
        self.add_rows(lay)
        self.cont = QtGui.QComboBox()
        self.cont.addItems(CONTINUITIES)
        if obj:
            self.cont.setCurrentIndex(CONTINUITIES.index(obj.Continuity))
        lay.addRow("Continuity", self.cont)
        self.watch(self.cont.currentIndexChanged)
        self.sliders, self.spins = {}, {}
        for name, lo, hi in SLIDERS:
            s = QtGui.QSlider(QtCore.Qt.Horizontal)
            s.setRange(0, 1000)
            s.lo, s.hi = lo, hi
            box = QtGui.QDoubleSpinBox()  # the value; the slider moves it on its scale
            box.setDecimals(DECIMALS)
            box.setRange(1e-6 if name == "Tension" else -1e6, 1e6)
            box.setValue(getattr(obj, name) if obj else 1.0)
            s.setMinimumWidth(120)
            s.setValue(self.position(s, box.value()))
            s.valueChanged.connect(lambda _v, s=s, box=box: box.setValue(self.value(s)))
            box.valueChanged.connect(lambda v, s=s: self.follow(s, v))
            self.watch(box.valueChanged)
            row = QtGui.QHBoxLayout()
            row.addWidget(s, 1)
            row.addWidget(box)
            lay.addRow(name, row)
            self.sliders[name], self.spins[name] = s, box
        self.status = QtGui.QPlainTextEdit()  # the preview's report; it can be long
        self.status.setReadOnly(True)
        self.status.setMinimumHeight(6 * self.status.fontMetrics().lineSpacing())
        lay.addRow(self.status)
        self.preview_node = None
        self.timer.start(10)

    def watch(self, signal):
        """Preview again 150 ms after signal (a widget's change) stops firing."""
        signal.connect(lambda *_a: self.timer.start(150))

    # subclasses
    def add_rows(self, lay):
        """Add the subclass's rows to the form layout lay, above Continuity."""

    def compute(self):
        """(shape, status text) for the values shown. Raises C2BlendError."""
        raise NotImplementedError

    def create(self):
        """A new document object for the values shown. Raises C2BlendError."""
        raise NotImplementedError

    def store(self, obj):
        """Set the subclass's own properties of obj to the values shown."""

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

    def shape_values(self):
        """(continuity, (Gamma, Eta, Lambda, Rho), tension) as shown."""
        v = {k: box.value() for k, box in self.spins.items()}
        return (self.cont.currentText(), (v["Gamma"], v["Eta"], v["Lambda"], v["Rho"]),
                v["Tension"])

    def blend_parameters(self):
        """(continuity, its shape parameters, tension) as shown (features.shape_params)."""
        cont, sp, tension = self.shape_values()
        return cont, features.shape_params(cont, sp), tension

    def preview(self):
        """Compute the result for the values shown and draw it in the view."""
        self.clear_preview()
        try:
            shape, text = self.compute()
        except C2BlendError as ex:
            self.status.setPlainText("Cannot %s: %s" % (self.TITLE.split()[-1].lower(), ex))
            return
        self.status.setPlainText(text)
        node = coin.SoSeparator()
        mat = coin.SoMaterial()
        mat.diffuseColor.setValue(0.85, 0.55, 0.2)
        node.addChild(mat)
        pts, tris = shape.tessellate(shape.BoundBox.DiagonalLength * 2e-3)
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
        """Create the object, or store the values in the edited one and recompute it
        in one transaction (aborted, previous shape kept, when it fails). Returns False
        and shows why when it fails, leaving the panel open."""
        self.timer.stop()
        self.clear_preview()
        try:
            if self.obj is None:
                self.obj = self.create()
            else:
                doc = self.obj.Document
                doc.openTransaction("%s: edit" % self.TITLE)
                try:
                    self.store(self.obj)
                    make.set_params(self.obj, *self.blend_parameters())
                    doc.recompute()
                    if "Invalid" in self.obj.State:
                        raise C2BlendError(getattr(self.obj.Proxy, "last_error", "")
                                           or "recompute failed", self.obj.Label)
                except (C2BlendError, ValueError) as ex:
                    doc.abortTransaction()
                    doc.recompute()
                    if isinstance(ex, ValueError):
                        raise C2BlendError(str(ex), self.obj.Label) from None
                    raise
                doc.commitTransaction()
        except C2BlendError as ex:
            QtGui.QMessageBox.critical(None, self.TITLE, str(ex))
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
