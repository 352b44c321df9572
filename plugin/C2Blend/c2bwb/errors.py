# SPDX-License-Identifier: LGPL-2.1-or-later
"""Errors of the C2Blend workbench, and the wording shared by their messages (occt_message,
listing). Every message names the object and the edge."""


class C2BlendError(Exception):
    """A C2Blend operation failed; the message says what, where, and what to try.

    Attributes: `message` (without `where`), `where` (object/sub-element, e.g.
    "Box.Edge3", or ""), `kind` ("selection", "radius", "numeric", "sewing", "validity",
    "kernel").
    """

    def __init__(self, message, where="", kind="selection"):
        super().__init__(("%s: %s" % (where, message)) if where else message)
        self.message = message
        self.where = where
        self.kind = kind


def occt_message(ex):
    """The message of an exception from FreeCAD or OCCT, for a user: FreeCAD 0.20's
    Part exceptions carry a dict ({'sclassname': ..., 'sErrMsg': 'MultiFusion failed',
    ...}) whose repr is no message; its sErrMsg is taken, and an empty message is
    replaced by the exception's class name."""
    arg = ex.args[0] if ex.args else None
    if isinstance(arg, dict):
        return str(arg.get("sErrMsg") or arg.get("sclassname") or type(ex).__name__)
    return str(ex) or type(ex).__name__


def listing(names, most=None):
    """'A, B and C' for a list of names; with `most`, the first `most` of a longer one
    then 'and N more'."""
    if most is not None and len(names) > most:
        return "%s and %d more" % (", ".join(names[:most]), len(names) - most)
    return " and ".join([", ".join(names[:-1]), names[-1]]) if len(names) > 1 else names[0]
