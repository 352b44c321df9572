# SPDX-License-Identifier: LGPL-2.1-or-later
"""Animation of time-dependent blends: step a time property, recompute, verify the
continuity of every target at every frame, and write one file per frame."""
import json
import os

from ..errors import C2BlendError


def write_shape(shape, path):
    """Export shape to STEP (.step/.stp) or BREP (.brep) atomically: a temporary file in
    the same folder is renamed over path only when complete."""
    folder, name = os.path.split(os.path.abspath(path))
    tmp = os.path.join(folder, ".%s.%d.tmp%s" % (name, os.getpid(), os.path.splitext(name)[1]))
    try:
        if path.lower().endswith(".brep"):
            shape.exportBrep(tmp)
        else:
            shape.exportStep(tmp)
        if not os.path.exists(tmp) or os.path.getsize(tmp) == 0:
            raise OSError("nothing was written")
        os.replace(tmp, path)
    except Exception as ex:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise C2BlendError("cannot write %s: %s" % (path, ex), "", "io") from None


def save_view_png(view, path, width=800, height=600):
    """Save a 3D view as PNG atomically (temporary file in the same folder, renamed)."""
    folder, name = os.path.split(os.path.abspath(path))
    tmp = os.path.join(folder, ".%s.%d.tmp.png" % (name, os.getpid()))
    view.saveImage(tmp, width, height, "White")
    if not os.path.exists(tmp) or os.path.getsize(tmp) == 0:
        raise C2BlendError("cannot write %s: the view was not saved" % path, "", "io")
    os.replace(tmp, path)


# spreadsheet aliases the Animate command looks for ("t" is the unit tonne in expressions)
TIME_ALIASES = ("Time", "time")


def clock_property(obj):
    """The name of obj's time: 'Time' for an object with a Time property (a C2Clock), the
    first alias of TIME_ALIASES a spreadsheet has, or None."""
    if obj.TypeId == "Spreadsheet::Sheet":
        return next((a for a in TIME_ALIASES if obj.getCellFromAlias(a)), None)
    return "Time" if "Time" in obj.PropertiesList else None


def _get_time(clock, prop):
    if clock.TypeId == "Spreadsheet::Sheet":
        cell = clock.getCellFromAlias(prop) or prop
        return clock.getContents(cell)
    return getattr(clock, prop)


def _set_time(clock, prop, value):
    if clock.TypeId == "Spreadsheet::Sheet":  # prop is an alias (e.g. "time") or a cell
        cell = clock.getCellFromAlias(prop) or prop
        clock.set(cell, value if isinstance(value, str) else repr(float(value)))
        clock.recompute()
    else:
        setattr(clock, prop, value)


def animate(doc, clock, times, targets, out_dir=None, fmt="step", prop="Time",
            snapshot=None):
    """Step clock.<prop> through times (clock: an object with a float property such as a
    C2Clock's Time, or a spreadsheet with prop an alias or cell, e.g. "time"); after each
    recompute every target (C2Fillet, C2Blend or C2Check object) must be valid and report
    its verdict. Writes out_dir/<target>_frame_NNN.<fmt> per frame and target with a
    shape, and calls snapshot(path) (GUI PNG) if given. The clock is restored
    afterwards. Returns a list of frame dicts
    {"t", "verdicts": {label: verdict}, "worst_g2_rel", "worst_g1", "files"}."""
    start = _get_time(clock, prop)
    frames = []
    try:
        for k, t in enumerate(times):
            _set_time(clock, prop, float(t))
            doc.recompute()
            frame = {"t": float(t), "verdicts": {}, "worst_g2_rel": 0.0, "worst_g1": 0.0,
                     "files": []}
            for obj in targets:
                shape = getattr(obj, "Shape", None)  # a C2Check has none
                if "Invalid" in obj.State or (shape is not None and not shape.isValid()):
                    raise C2BlendError("frame %d (t = %g) failed to recompute" % (k, t),
                                       obj.Label, "numeric")
                rep = json.loads(obj.Report)
                frame["verdicts"][obj.Label] = rep["verdict"]
                for r in rep["trimlines"] if "trimlines" in rep else rep["edges"]:
                    frame["worst_g2_rel"] = max(frame["worst_g2_rel"], r["g2_rel"])
                    frame["worst_g1"] = max(frame["worst_g1"], r["g1"])
                if out_dir and shape is not None:
                    path = os.path.join(out_dir, "%s_frame_%03d.%s" % (obj.Name, k, fmt))
                    write_shape(obj.Shape, path)
                    frame["files"].append(path)
            if snapshot is not None and out_dir:
                png = os.path.join(out_dir, "frame_%03d.png" % k)
                snapshot(png)
                frame["files"].append(png)
            frames.append(frame)
    finally:
        _set_time(clock, prop, start)
        doc.recompute()
    return frames
