# SPDX-License-Identifier: LGPL-2.1-or-later
"""CGAL cross-check of the analytic curvature on a tessellation of a shape.

A tessellation is written as a PLY mesh carrying, per
vertex, the oriented normal and the analytic principal curvatures of its face; the
C2Blend CGAL tool (`c2blend-cgal-curvature`, CGAL's jet fitting, no code shared with
the kernel) estimates k1, k2 from the mesh alone and reports the differences per region
(0: blend faces, 1: the other faces). Optional: when the tool is not found, the check
is skipped and says so.
"""
import json
import os
import shutil
import subprocess
import tempfile

import c2blend

from .surface import Vector, frame_or_none, tessellation

TOOL = "c2blend-cgal-curvature"


def find_tool():
    """Path of the CGAL tool: $C2B_CGAL_TOOL, next to the c2blend module, or PATH."""
    cands = [os.environ.get("C2B_CGAL_TOOL", ""),
             os.path.join(os.path.dirname(os.path.abspath(c2blend.__file__)), TOOL),
             shutil.which(TOOL) or ""]
    return next((c for c in cands if c and os.access(c, os.X_OK)), None)


def write_ply(path, shape, blend_faces, other_faces, deflection):
    """ASCII PLY: x y z nx ny nz k1 k2 region valid. Each face is its own sheet (its
    vertices are merged within the face only): a jet fit across a trimline is only O(h)
    even for G2, so the faces are compared one by one."""
    tol = 1e-9 * shape.BoundBox.DiagonalLength
    index, verts, tris = {}, [], []
    for fi, face in enumerate(list(blend_faces) + list(other_faces)):
        region = 0 if fi < len(blend_faces) else 1
        # an untrimmed blend face: a uv grid (parameters known, no projection);
        # trimmed faces: OCCT's tessellation
        pts, ts, uvs = _grid(face) if region == 0 else tessellation(face, deflection)
        local = []
        for p, uv in zip(pts, uvs):
            key = (fi, round(p.x / tol), round(p.y / tol), round(p.z / tol))
            if key not in index:
                fr = frame_or_none(face, *uv)
                k1, k2, _, _ = fr.principal() if fr else (0.0, 0.0, 0.0, 0.0)
                n = fr.n if fr else Vector(0, 0, 0)  # invalid: the tool skips the vertex
                index[key] = len(verts)
                verts.append((p.x, p.y, p.z, n.x, n.y, n.z, k1, k2, region, int(fr is not None)))
            local.append(index[key])
        tris.extend((local[a], local[b], local[c]) for a, b, c in ts)
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\n" % len(verts))
        for name in ("x", "y", "z", "nx", "ny", "nz", "k1", "k2"):
            f.write("property double %s\n" % name)
        f.write("property int region\nproperty int valid\n")
        f.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(tris))
        for v in verts:
            f.write("%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %d\n" % v)
        for t in tris:
            f.write("3 %d %d %d\n" % t)
    return len(verts), len(tris)


def _grid(face, nu=17, nv=129):
    """Points, triangles and (u, v) of an nu x nv grid over the face's parameter range
    (v wraps around on periodic surfaces)."""
    u0, u1, v0, v1 = face.ParameterRange
    periodic = face.Surface.isVPeriodic()
    mv = nv if periodic else nv + 1
    uvs = [(u0 + (u1 - u0) * i / (nu - 1), v0 + (v1 - v0) * j / nv)
           for i in range(nu) for j in range(mv)]
    pts = [face.Surface.value(u, v) for u, v in uvs]
    tris = []
    for i in range(nu - 1):
        for j in range(nv):
            a, b = i * mv + j, i * mv + (j + 1) % mv
            c, d = a + mv, b + mv
            tris += [(a, b, d), (a, d, c)]
    return pts, tris, uvs


def cross_check(shape, blend_faces, other_faces, deflection=None, tool=None):
    """Run the CGAL tool on a tessellation of the blend faces (region 0) and other faces
    of shape (region 1, e.g. the faces across the trimlines). Returns its JSON summary (per region
    max/mean/rms of |k_est - k_exact| for all, interior and smooth vertices), None when
    the tool is not available, or {"error": message} when it rejects the mesh."""
    tool = tool or find_tool()
    if tool is None:
        return None
    deflection = deflection or 4e-3 * shape.BoundBox.DiagonalLength
    with tempfile.TemporaryDirectory(prefix="c2b_cgal_") as tmp:
        mesh, summary = os.path.join(tmp, "mesh.ply"), os.path.join(tmp, "summary.json")
        write_ply(mesh, shape, blend_faces, other_faces, deflection)
        run = subprocess.run([tool, mesh, "--summary", summary], capture_output=True, text=True)
        if run.returncode != 0:
            return {"error": run.stderr.strip() or "exit status %d" % run.returncode}
        with open(summary) as f:
            return json.load(f)
