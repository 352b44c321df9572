# SPDX-License-Identifier: LGPL-2.1-or-later
"""The process in which bopcheck.py runs OCCT's BOP check: a script, started by
bopcheck with FreeCAD's library folder as its argument (it imports no C2Blend module).

It reads requests from stdin, each a line with a byte count followed by that many bytes
of BREP text, checks the shape (TopoShape.check(True)) and answers each with one line of
JSON on its stdout: {"found": null} when the shape passes, {"found": "..."} with OCCT's
findings otherwise. It ends when stdin closes, that is when its parent ends, without
FreeCAD's clean-up (os._exit), so that it never saves FreeCAD's user settings over the
parent's.
"""
import json
import os
import sys


def main():
    answers = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)  # whatever FreeCAD or OCCT print goes to stderr, not into the answers
    sys.path.append(sys.argv[1])
    import FreeCAD  # noqa: F401 - FreeCAD before Part, or importing Part crashes
    import Part
    requests = sys.stdin.buffer
    while True:
        size = requests.readline()
        if not size:
            answers.flush()
            os._exit(0)
        shape = Part.Shape()
        shape.importBrepFromString(requests.read(int(size)).decode())
        try:
            shape.check(True)
            found = None
        except Exception as ex:  # noqa: BLE001 - OCCT reports findings as an exception
            found = str(ex) or type(ex).__name__
        answers.write(json.dumps({"found": found}) + "\n")
        answers.flush()


if __name__ == "__main__":
    main()
