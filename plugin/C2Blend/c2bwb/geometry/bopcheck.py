# SPDX-License-Identifier: LGPL-2.1-or-later
"""OCCT's BOP argument check (TopoShape.check(True)) with a time limit, and trial
fillets (trial_fillet), both run in another process.

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
0.6 s, once); a shape goes to it by a file in OCCT's binary format, which is exact
where BREP text rounds.

Where the loop is, a check of the face's neighbourhood loops too. A check of a filleted
solid that runs long is therefore watched by a second server, which checks the
neighbourhoods of its plate fillings (the suspects) one by one: the first that passes
its own, shorter limit says where, and the whole check is stopped then. On a 20 x 20 x
10 box with every edge filleted at R = 0.5, the fillet took 58 s when the stuck filling
was found only after the whole check's limit (then 30 s on the clock), and takes 29 s
so.

The limits count the processor time of the check server, not the time on the clock: on
a busy machine a check gets a share of a processor, and a limit on the clock gave up
checks that would have passed (a pentagonal prism with 11 edges filleted at R = 0.863,
as shapes.pentagonal_prism, whose plate fillings' neighbourhoods take seconds to check,
had one given up as stuck with the test suite running beside it, and that filling made
again: the solid depended on the machine's load). Processor time measures the work
whatever the number of processors and the load: OCCT checks on several threads, and
processor time counts them all. A server that gets almost no processor time is given
up all the same after WALL_FACTOR times the limit on the clock.
"""
import atexit
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time

import Part

# seconds of the check server's processor time, for a whole solid (checks that passed
# took 1.6 to 10 s on the clock on a box with 12 blends and 8 plate fillings, R = 1 to
# 3, so up to twice that in processor time on two threads; the prism above 17.9 s) and
# for a face with its neighbours (0.3 to 1 s on the clock on boxes; at the prism's
# corners 0.4 to 6.7 s: tools/fillet_survey.py --bop-times). The whole check, watched
# from WATCH_AFTER on, must outlast the watch: the looping neighbourhood of the
# 20 x 20 x 10 box was the sixth checked, after 5 s of others.
LIMIT = 45.0
NEAR_LIMIT = 15.0
# a check is also given up after this many times its limit on the clock, whatever
# processor time it had (a server waiting for input, or starved of a processor)
WALL_FACTOR = 4.0
# s of processor time (or WALL_FACTOR times that on the clock): the suspects'
# neighbourhoods are checked alongside a whole shape's check that has not finished
# after this much (a second server slows the usual checks, which take up to 10 s, by
# 15 to 25 %); and s on the clock between looks at the checks
WATCH_AFTER = 10.0
WATCH_STEP = 0.05
NO_ERROR = "No error"  # FreeCAD's word for a sub-shape whose own status is clean
# the finding where FreeCAD names none: every sub-shape's own status is clean
IN_CONTEXT = "BRepCheck rejects the shape as a whole, though each of its parts passes alone"
# s of processor time for one trial fillet (OCCT's fillets of the parts tried took
# milliseconds)
TRIAL_LIMIT = 20.0
PENDING = object()  # _Server.answer: no answer yet
CRASHED = "OCCT's fillet crashed"  # trial_fillet: it closed the process that ran it
SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "checkserver.py")


class Unfinished(Exception):
    """The check did not finish within its time limit (_Server.overran). stuck: where
    problems() was given suspects, those of them whose neighbourhood's check did not
    finish either (each was checked, unless one was found while the whole shape was
    checked), else []."""

    def __init__(self, message, stuck=()):
        super().__init__(message)
        self.stuck = list(stuck)


def problems(shape, seconds=None, bop=True, meanwhile=None, suspects=()):
    """What BRepCheck and OCCT's BOP argument check (BRepCheck alone when not bop) find
    wrong with `shape`, one line, each finding with its count; None when both pass.
    meanwhile: a callable (no arguments; its result is dropped) run in this process
    while the check server checks, so that the caller's own work overlaps the check;
    run before the check when there is no server. suspects: faces of `shape` where the
    check may loop (plate fillings, tangent to the blends around them): while the whole
    shape is checked, from WATCH_AFTER on, a second server checks their neighbourhoods
    one after another, each within NEAR_LIMIT, and where one does not finish the whole
    check, which runs into the same loop, is given up at once (_watched). Raises
    Unfinished when the BOP check takes longer than `seconds` (LIMIT) of processor time
    (_Server.overran), with the suspects found stuck, and what meanwhile raises."""
    if bop and suspects:
        found = _watched(shape, seconds or LIMIT, meanwhile, suspects)
    elif bop:
        found = _checked(shape, seconds or LIMIT, meanwhile)
    else:
        if meanwhile:
            meanwhile()
        found = _check_here(shape, False)
    if found is None:
        return None
    lines = _findings(found)
    return "; ".join("%s (%d)" % (f, lines.count(f)) if lines.count(f) > 1 else f
                     for f in dict.fromkeys(lines))


def _findings(found):
    """The lines of OCCT's findings (the text of a failed check), without its heading and
    without the "No error" that FreeCAD lists for each sub-shape whose own status is
    clean beside one that is not. Where every line says "No error", the fault is in how
    the sub-shapes fit together, which FreeCAD does not list: one line says so."""
    lines = [line.strip() for line in found.splitlines() if line.strip()]
    lines = lines[1:] if len(lines) > 1 and lines[0].endswith(":") else lines
    faults = [line for line in lines if line != NO_ERROR]
    if lines and not faults:
        return [IN_CONTEXT]
    return faults


def _watched(shape, seconds, meanwhile, suspects):
    """The whole shape's findings (_checked), its check watched by the suspects' (see
    problems). Raises Unfinished with the suspects whose neighbourhood check did not
    finish: the first found while the whole is checked, else, when the whole check
    passes its time limit, each of them found by checking the rest one by one."""
    queue = list(suspects)  # those whose neighbourhood is still to be checked

    def next_near():  # the suspect now checked on the "near" server, or None
        if not queue:
            return None
        try:
            _server("near").send(_neighbourhood(shape, queue[0]))
        except OSError:  # no second server: the suspects wait for the whole
            _stop("near")
            return None
        return queue.pop(0)

    try:
        whole = _server("whole")
        whole.send(shape)
    except OSError:  # as _checked: restarted once, or checked in this process
        return _checked(shape, seconds, meanwhile)
    try:
        (meanwhile or (lambda: None))()
    except BaseException:
        _stop("whole")  # its answer would be taken for the next check's
        raise
    near, idle = None, False  # idle: no second server can check
    try:
        while not whole.overran(seconds):
            found = whole.answer(WATCH_STEP)
            if found is not PENDING:
                if near is not None:
                    _stop("near")  # its answer would be taken for the next check's
                return found
            if near is None:
                if not idle and queue and whole.overran(WATCH_AFTER):
                    near = next_near()
                    idle = near is None
                continue
            try:
                done = _servers["near"].answer(0.0) is not PENDING
            except (OSError, ValueError):  # it ended, or its answer is garbled
                _stop("near")
                queue.insert(0, near)
                near, idle = None, True
                continue
            if done:
                near = next_near()
            elif _servers["near"].overran(NEAR_LIMIT):
                late = _servers["near"].late(NEAR_LIMIT)
                _stop()
                raise Unfinished("OCCT's BOP check did not finish %s on the neighbourhood "
                                 "of a plate filling" % late, [near])
    except (OSError, ValueError):  # the server ended while checking
        _stop()
        return _checked(shape, seconds, None)
    late = whole.late(seconds)
    _stop("whole")
    stuck = []
    if near is not None:
        try:
            _servers["near"].receive(NEAR_LIMIT)
        except Unfinished:
            stuck.append(near)
        except (OSError, ValueError):
            queue.insert(0, near)
        _stop("near")
    for face in queue:
        try:
            _checked(_neighbourhood(shape, face), NEAR_LIMIT)
        except Unfinished:
            stuck.append(face)
    raise Unfinished("OCCT's BOP check did not finish %s" % late, stuck)


def trial_fillet(shape, edges, radius):
    """Whether OCCT's rolling-ball fillet of `edges` (edges of `shape`) at `radius` gives
    a valid solid: (True, None), or (False, why not). Tried in a check server's
    process, since OCCT's fillet builder can crash the process that runs it: a
    segmentation fault in ChFi3d_Builder::IntersectMoreCorner at one radius of the
    search for the radii OCCT accepts, on a block with a hole, a chamfer and a boss
    (at the radius the user gave, OCCT had only failed), would have closed FreeCAD.
    The server gets the shape exactly (_Server.fillet), once for successive trials on
    it. None where no server can start: the caller then fillets in its own process."""
    indices = [next(i for i, x in enumerate(shape.Edges) if x.isSame(e)) for e in edges]
    try:
        server = _server("trial")
        server.fillet(shape, radius, indices)
        found = server.receive(TRIAL_LIMIT)
    except Unfinished:
        _stop("trial")
        return False, "OCCT's fillet did not finish within %.0f s" % TRIAL_LIMIT
    except (OSError, ValueError):  # no server, or it ended: crashed, or could not start
        crashed = "trial" in _servers
        _stop("trial")
        return (False, CRASHED) if crashed else None
    return found is None, found


def faulty(shape, faces, seconds, ignore=None):
    """Those of `faces` (faces of `shape`) in whose neighbourhood the BOP check finds
    something wrong (or does not finish within `seconds`): where the findings on the
    whole shape are. Findings for which ignore(neighbourhood, finding) is true (the
    neighbourhood: a compound of faces; the finding: one line of OCCT's, such as
    'Error in Face: BOPAlgo GeomAbs_C0') do not count."""
    out = []
    for f in faces:
        try:
            near = _neighbourhood(shape, f)
            found = _checked(near, seconds)
            if found is not None and not all(ignore and ignore(near, x)
                                             for x in _findings(found)):
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
        self.buffer = b""  # the part of an answer read so far
        self.started = (time.monotonic(), None)  # (clock, processor time) at the last send
        self.filleted = None  # the shape of the last fillet request (held: its id stays)
        self.folder = None  # where shapes are written for the server to read

    def send(self, shape):
        """Start checking shape, which goes in OCCT's binary format, by a file: BREP text
        writes edges' parameter ranges to 15 digits, and the check found
        BOPAlgo_InvalidCurveOnSurface on a block made B-splines read back from it that
        the block itself has not (shapes.off_curve_block). Raises OSError when the
        server has ended."""
        path = os.path.join(self._folder(), "check.brp")
        shape.exportBinary(path)
        self.started = (time.monotonic(), _cpu(self.proc.pid))
        self.proc.stdin.write(("check %s\n" % path).encode())
        self.proc.stdin.flush()

    def _folder(self):
        """The folder of the files sent to the server, made on first use."""
        if self.folder is None:
            self.folder = tempfile.mkdtemp(prefix="c2blend-server-")
        return self.folder

    def fillet(self, shape, radius, indices):
        """Start filleting the edges `indices` (0-based, of shape.Edges) of shape at
        radius (checkserver.py). The shape goes in OCCT's binary format, by a file, and
        not again when the last fillet request had it: BREP text rounds coordinates to
        15 digits, and OCCT's fillet crashed on a solid where it only failed on that
        solid read back from BREP text. Raises OSError when the server has ended."""
        path = "-"
        if shape is not self.filleted:
            path = os.path.join(self._folder(), "shape.brp")
            shape.exportBinary(path)
            self.filleted = shape
        self.started = (time.monotonic(), _cpu(self.proc.pid))
        self.proc.stdin.write(("fillet %r %s %s\n" % (
            radius, ",".join(str(i) for i in indices), path)).encode())
        self.proc.stdin.flush()

    def used(self):
        """(processor seconds, seconds on the clock) spent on the shape sent last: the
        server's user and system time since then (the clock's time where the system
        does not say, as without /proc)."""
        wall = time.monotonic() - self.started[0]
        cpu = _cpu(self.proc.pid)
        if cpu is None or self.started[1] is None:
            return wall, wall
        return cpu - self.started[1], wall

    def overran(self, limit):
        """Whether the check of the shape sent last has used `limit` seconds of
        processor time, or WALL_FACTOR times that on the clock."""
        cpu, wall = self.used()
        return cpu >= limit or wall >= WALL_FACTOR * limit

    def late(self, limit):
        """'within N s of processor time' or, where the clock ran out first, 'within M s
        (with N s of processor time)', for messages on a check that overran `limit`."""
        cpu, wall = self.used()
        if cpu >= limit:
            return "within %.0f s of processor time" % limit
        return "within %.0f s (with %.1f s of processor time)" % (WALL_FACTOR * limit, cpu)

    def answer(self, seconds):
        """OCCT's findings on the shape sent, None when it passes, once they have come
        within `seconds` from now (0: only what has come), else PENDING. Raises OSError
        when the server has ended."""
        end, fd = time.monotonic() + seconds, self.proc.stdout.fileno()
        while not self.buffer.endswith(b"\n"):
            left = max(0.0, end - time.monotonic())
            if not select.select([fd], [], [], left)[0]:
                return PENDING
            chunk = os.read(fd, 65536)
            if not chunk:
                raise OSError("the check server ended")
            self.buffer += chunk
        out, self.buffer = self.buffer, b""
        return json.loads(out)["found"]

    def receive(self, limit):
        """OCCT's findings on the shape sent, None when it passes, waiting until the
        check has used `limit` seconds (overran). Raises Unfinished, and OSError when
        the server has ended."""
        while True:
            found = self.answer(WATCH_STEP)
            if found is not PENDING:
                return found
            if self.overran(limit):
                raise Unfinished("OCCT's BOP check did not finish %s" % self.late(limit))

    def close(self):
        self.proc.kill()
        self.proc.wait()
        if self.folder is not None:
            shutil.rmtree(self.folder, ignore_errors=True)


_servers = {}  # this process's check servers, once started: "whole", "near", "trial"


def _cpu(pid):
    """The processor seconds (user and system) that process `pid` has used, or None
    where /proc does not say."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()  # after the command's name
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


def _server(slot):
    """The running check server in `slot`, started when needed. Raises OSError when
    none can start."""
    if slot not in _servers or _servers[slot].proc.poll() is not None:
        _stop(slot)
        _servers[slot] = _Server()
    return _servers[slot]


def _checked(shape, seconds, meanwhile=None):
    """The check's findings, None when it passes: by the check server, started when
    needed, killed when the check does not finish in time (`seconds` of its processor
    time, _Server.overran), replaced once when it has ended. Where no server can start,
    the check runs in this process, without a time limit. Raises Unfinished."""
    meanwhile = meanwhile or (lambda: None)
    for fresh in (False, True):
        if fresh:
            _stop("whole")
        started = "whole" not in _servers or _servers["whole"].proc.poll() is not None
        try:
            server = _server("whole")
        except OSError:
            meanwhile()
            return _check_here(shape, True)
        fresh = fresh or started
        try:
            server.send(shape)
            ended = False
        except OSError:
            ended = True
        if not ended:
            try:
                meanwhile()
            except BaseException:
                _stop("whole")  # its answer would be taken for the next check's
                raise
            meanwhile = lambda: None  # noqa: E731 - once, whatever the server does next
            try:
                return server.receive(seconds)
            except Unfinished:
                _stop("whole")
                raise
            except (OSError, ValueError):
                pass
        _stop("whole")  # the server ended while checking
        if fresh:  # always so the second time round
            raise Unfinished("OCCT's BOP check ended without a result")


def _stop(slot=None):
    """Kill the check server in `slot` (all of them when None), where one runs, and
    remove its files."""
    for key in [slot] if slot else list(_servers):
        server = _servers.pop(key, None)
        if server is not None:
            server.close()


atexit.register(_stop)  # the trial server's folder, too


def _check_here(shape, bop):
    """The check in this process: OCCT's findings, None when it passes."""
    try:
        shape.check(bop)
    except Exception as ex:  # noqa: BLE001 - OCCT reports findings as an exception
        return str(ex) or type(ex).__name__
    return None
