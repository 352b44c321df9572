# SPDX-License-Identifier: LGPL-2.1-or-later
"""OCCT's BOP argument check (TopoShape.check(True)) with a time limit.

OCCT 7.6's face-face intersection can walk without end on two B-spline faces that are
tangent along their shared edge: IntWalk_PWalking::ExtendLineInCommonZone allocates as
it goes, so the process grows until it is killed. Measured on a 10 mm box with all 12
edges filleted at R = 2 and tension 1.0008 (the task panel's tension slider at its
default, before the panel kept exact values): the check on a blend and the plate filling
of its corner patch ran for more than 250 s, where the same solid at tension 1.0 is
checked in 2 s. Run in FreeCAD's own process, such a check freezes FreeCAD.

So the check runs in another process, a check server (checkserver.py) started on first
use and kept for the next checks, which is killed when a check passes its time limit
(the next check starts a new one). A forked child of this process will not do: OCCT's
thread pool (OSD_ThreadPool), once used here, has no threads in a child, which then
waits for them for ever. The server is a fresh Python that imports FreeCAD (0.1 to
0.6 s, once); a shape goes to it as BREP text (a box with 26 faces: 1.1 MB, 25 ms).
"""
import json
import os
import select
import subprocess
import sys
import time

import Part

# seconds, for a whole solid (checks that passed took 1.6 to 10 s on a box with 12
# blends and 8 plate fillings, R = 1 to 3) and for a face with its neighbours (0.3 to
# 1 s)
LIMIT = 30.0
NEAR_LIMIT = 10.0
SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "checkserver.py")


class Unfinished(Exception):
    """The check did not finish within its time limit."""


def problems(shape, seconds=None, bop=True, meanwhile=None):
    """What BRepCheck and OCCT's BOP argument check (BRepCheck alone when not bop) find
    wrong with `shape`, one line, each finding with its count; None when both pass.
    meanwhile: a callable (no arguments; its result is dropped) run in this process
    while the check server checks, so that the caller's own work overlaps the check;
    run before the check when there is no server. Raises Unfinished when the BOP check
    takes longer than `seconds` (LIMIT), and what meanwhile raises."""
    if bop:
        found = _checked(shape, seconds or LIMIT, meanwhile)
    else:
        if meanwhile:
            meanwhile()
        found = _check_here(shape, False)
    if found is None:
        return None
    lines = [line.strip() for line in found.splitlines() if line.strip()]
    lines = lines[1:] if len(lines) > 1 and lines[0].endswith(":") else lines
    return "; ".join("%s (%d)" % (f, lines.count(f)) if lines.count(f) > 1 else f
                     for f in dict.fromkeys(lines))


def stuck(shape, faces, seconds):
    """Those of `faces` (faces of `shape`) whose neighbourhood is not checked within
    `seconds`: where the check of the whole shape is stuck."""
    out = []
    for f in faces:
        try:
            _checked(_neighbourhood(shape, f), seconds)
        except Unfinished:
            out.append(f)
    return out


def faulty(shape, faces, seconds):
    """Those of `faces` (faces of `shape`) in whose neighbourhood the BOP check finds
    something wrong (or does not finish within `seconds`): where the findings on the
    whole shape are."""
    out = []
    for f in faces:
        try:
            if _checked(_neighbourhood(shape, f), seconds) is not None:
                out.append(f)
        except Unfinished:
            out.append(f)
    return out


def _neighbourhood(shape, face):
    """A compound of `face` and the faces sharing an edge with it, in shape's order."""
    return Part.Compound([g for g in shape.Faces if g.isSame(face)
                          or any(e.isSame(x) for e in face.Edges for x in g.Edges)])


class _Server:
    """A running check server (checkserver.py) and the pipes to it."""

    def __init__(self):
        python = os.path.join(sys.base_prefix, "bin", "python%d.%d" % sys.version_info[:2])
        self.proc = subprocess.Popen(
            [python, SCRIPT, os.path.dirname(os.path.abspath(Part.__file__))],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)

    def send(self, shape):
        """Start checking shape. Raises OSError when the server has ended."""
        data = shape.exportBrepToString().encode()
        self.proc.stdin.write(b"%d\n" % len(data) + data)
        self.proc.stdin.flush()

    def receive(self, seconds):
        """OCCT's findings on the shape sent, None when it passes, waiting at most
        `seconds` from now. Raises Unfinished, and OSError when the server has ended."""
        out, end, fd = b"", time.monotonic() + seconds, self.proc.stdout.fileno()
        while not out.endswith(b"\n"):
            left = end - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                raise Unfinished("OCCT's BOP check did not finish within %.0f s" % seconds)
            chunk = os.read(fd, 65536)
            if not chunk:
                raise OSError("the check server ended")
            out += chunk
        return json.loads(out)["found"]

    def close(self):
        self.proc.kill()
        self.proc.wait()


_servers = []  # the check server of this process, once started


def _checked(shape, seconds, meanwhile=None):
    """The check's findings, None when it passes: by the check server, started when
    needed, killed when the check does not finish in time (`seconds` after meanwhile()
    returns), replaced once when it has ended. Where no server can start, the check
    runs in this process, without a time limit. Raises Unfinished."""
    meanwhile = meanwhile or (lambda: None)
    for fresh in (False, True):
        if fresh or not _servers or _servers[0].proc.poll() is not None:
            _stop()
            try:
                _servers.append(_Server())
            except OSError:
                meanwhile()
                return _check_here(shape, True)
            fresh = True
        try:
            _servers[0].send(shape)
            ended = False
        except OSError:
            ended = True
        if not ended:
            try:
                meanwhile()
            except BaseException:
                _stop()  # its answer would be taken for the next check's
                raise
            meanwhile = lambda: None  # noqa: E731 - once, whatever the server does next
            try:
                return _servers[0].receive(seconds)
            except Unfinished:
                _stop()
                raise
            except (OSError, ValueError):
                pass
        _stop()  # the server ended while checking
        if fresh:  # always so the second time round
            raise Unfinished("OCCT's BOP check ended without a result")


def _stop():
    """Kill the check server, if one runs."""
    while _servers:
        _servers.pop().close()


def _check_here(shape, bop):
    """The check in this process: OCCT's findings, None when it passes."""
    try:
        shape.check(bop)
    except Exception as ex:  # noqa: BLE001 - OCCT reports findings as an exception
        return str(ex) or type(ex).__name__
    return None
