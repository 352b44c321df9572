# SPDX-License-Identifier: LGPL-2.1-or-later
"""Task panel of C2 Blend faces: whether to make one solid (the two primaries' faces,
the blend and planar caps) above the shared rows of params_panel."""
from PySide import QtGui

from ..objects import features, make
from .params_panel import ParamsPanel


class BlendFacesPanel(ParamsPanel):
    """Create a C2BlendFaces object (sides given, each (object, ['FaceN', 'EdgeM'])) or
    edit one (obj given)."""

    TITLE = "C2 Blend faces"

    def __init__(self, side1=None, side2=None, obj=None):
        self.sides = (tuple(obj.Edge1), tuple(obj.Edge2)) if obj else (side1, side2)
        super().__init__(obj)

    def add_rows(self, lay):
        self.solid = QtGui.QCheckBox("Make one solid")
        self.solid.setToolTip("One solid of the two faces, the blend and planar caps; "
                              "unchecked, the blend face only")
        self.solid.setChecked(bool(self.obj.MakeSolid) if self.obj else False)
        lay.addRow(self.solid)
        self.watch(self.solid.toggled)

    def compute(self):
        cont, sp, tension = self.blend_parameters()
        shape, rep = features.blend_faces(*self.sides, cont, sp, tension,
                                          self.solid.isChecked())
        what = ("one solid, %s" % ("valid" if shape.isValid() else "NOT valid")) \
            if self.solid.isChecked() else "the blend face only"
        return shape, ("%s; %d samples, fit deviation %.2g, %.0f ms; %s"
                       % (rep["verdict"], rep["samples"], rep["fit_deviation"],
                          1e3 * rep["seconds"], what))

    def create(self):
        return make.make_blend(*self.sides, *self.blend_parameters(),
                               make_solid=self.solid.isChecked())

    def store(self, obj):
        obj.MakeSolid = self.solid.isChecked()
