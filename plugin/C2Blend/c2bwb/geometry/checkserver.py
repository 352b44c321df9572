# SPDX-License-Identifier: LGPL-2.1-or-later
"""The process in which bopcheck.py runs OCCT's BOP check: a script, started by
bopcheck with FreeCAD's library folder as its argument (it imports no C2Blend module).

It reads requests from stdin and answers each with one line of JSON on its stdout:
- a line "check PATH", PATH a file holding a shape in OCCT's binary format: it checks
  the shape (TopoShape.check(True)) and answers {"found": null} when the shape passes,
  {"found": "..."} with OCCT's findings otherwise;
- a line "fillet RADIUS I,J,... PATH", PATH a file holding a shape in OCCT's binary
  format ("-": the shape of the last such request): it fillets the shape's edges I, J,
  ... (0-based, in shape.Edges' order) at RADIUS (TopoShape.makeFillet) and answers
  {"found": null} when that gives a valid solid, {"found": "..."} with why not
  otherwise.

It ends when stdin closes, that is when its parent ends, without FreeCAD's clean-up
(os._exit), so that it never saves FreeCAD's user settings over the parent's.
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
    filleted = None  # the shape of the last fillet request

    while True:
        line = requests.readline().strip()
        words = line.split(maxsplit=3)
        if not words:
            answers.flush()
            os._exit(0)
        try:
            if words[0] == b"fillet":
                if words[3] != b"-":
                    filleted = Part.Shape()
                    filleted.importBinary(words[3].decode())
                edges = [filleted.Edges[int(i)] for i in words[2].split(b",")]
                result = filleted.makeFillet(float(words[1]), edges)
                found = None if not result.isNull() and result.isValid() else \
                    "the result is not a valid solid"
            else:
                shape = Part.Shape()
                shape.importBinary(line.split(maxsplit=1)[1].decode())
                shape.check(True)
                found = None
        except Exception as ex:  # noqa: BLE001 - OCCT reports findings as an exception
            found = str(ex) or type(ex).__name__
        answers.write(json.dumps({"found": found}) + "\n")
        answers.flush()


if __name__ == "__main__":
    main()
