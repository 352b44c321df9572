# SPDX-License-Identifier: LGPL-2.1-or-later
"""Errors of the C2Blend workbench. Every message names the object and the edge."""


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
