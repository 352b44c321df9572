#!/usr/bin/python3
"""Render a blend with strips of its primaries from `c2blend mesh` output.

Runs `c2blend mesh SPEC --n N --with-primaries WIDTH -o tmp.ply` and draws the triangles
with Lambert shading, coloured by region (blend, primary 1, primary 2) or by a curvature
(k1, k2, mean H or Gaussian K, from the analytic values in the PLY) with a colour bar.
Works for expression and NURBS primaries alike.

usage: plot_mesh.py SPEC -o OUT.png [--c2blend PATH] [--n 48] [--width 0.15]
                    [--color-by region|k1|k2|H|K] [--view ELEV AZIM] [--title T] [--t T]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import cm, colors  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REGION_RGB = {0: (0.88, 0.48, 0.10), 1: (0.36, 0.48, 0.63), 2: (0.44, 0.60, 0.42)}


def read_ply(path):
    with open(path) as f:
        lines = f.read().split("\n")
    end = lines.index("end_header")
    nv = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
    nt = int(next(l for l in lines if l.startswith("element face")).split()[2])
    V = np.array([[float(x) for x in l.split()] for l in lines[end + 1:end + 1 + nv]])
    T = np.array([[int(x) for x in l.split()[1:4]] for l in lines[end + 1 + nv:end + 1 + nv + nt]])
    return V, T


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("spec")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--c2blend", default=os.path.join(HERE, "..", "build", "tools", "c2blend"))
    ap.add_argument("--n", type=int, default=48)
    ap.add_argument("--width", type=float, default=0.15)
    ap.add_argument("--t", type=float, default=None)
    ap.add_argument("--color-by", default="region", choices=["region", "k1", "k2", "H", "K"])
    ap.add_argument("--view", type=float, nargs=2, default=(22, -58), metavar=("ELEV", "AZIM"))
    ap.add_argument("--title", default=None)
    a = ap.parse_args()
    meta = json.load(open(a.spec))
    with tempfile.TemporaryDirectory() as tmp:
        ply = os.path.join(tmp, "m.ply")
        args = [a.c2blend, "mesh", a.spec, "--n", str(a.n), "-o", ply]
        if "primaries" in meta and a.width > 0:
            args += ["--with-primaries", str(a.width)]
        if a.t is not None:
            args += ["--t", str(a.t)]
        r = subprocess.run(args, capture_output=True, text=True)
        if r.returncode:
            sys.stderr.write(r.stderr)
            sys.exit(r.returncode)
        V, T = read_ply(ply)
    xyz, k1, k2, region = V[:, 0:3], V[:, 6], V[:, 7], V[:, 8].astype(int)
    tri = xyz[T]
    # Lambert shading from the face normal (two-sided), light from the viewer's upper left.
    fn = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    fn /= np.linalg.norm(fn, axis=1)[:, None] + 1e-300
    elev, azim = np.radians(a.view[0]), np.radians(a.view[1])
    light = np.array([np.cos(elev) * np.cos(azim + 0.6), np.cos(elev) * np.sin(azim + 0.6), np.sin(elev) + 0.5])
    light /= np.linalg.norm(light)
    shade = 0.35 + 0.65 * np.abs(fn @ light)
    if a.color_by == "region":
        face_region = np.max(region[T], axis=1)
        base = np.array([REGION_RGB[int(g)] for g in face_region])
        mappable = None
    else:
        val = {"k1": k1, "k2": k2, "H": 0.5 * (k1 + k2), "K": k1 * k2}[a.color_by]
        fval = val[T].mean(axis=1)
        lo, hi = np.percentile(fval, [1, 99])
        norm = colors.Normalize(vmin=lo, vmax=hi)
        cmap = cm.get_cmap("viridis")
        base = cmap(norm(fval))[:, :3]
        mappable = cm.ScalarMappable(norm=norm, cmap=cmap)
    fc = np.clip(base * shade[:, None], 0, 1)
    fig = plt.figure(figsize=(8, 7))
    ax = fig.add_subplot(111, projection="3d")
    # Edges in the face colour hide the light seams between faces.
    ax.add_collection3d(Poly3DCollection(tri, facecolors=fc, edgecolors=fc, linewidths=0.5))
    lo3, hi3 = xyz.min(axis=0), xyz.max(axis=0)
    ax.set_xlim(lo3[0], hi3[0])
    ax.set_ylim(lo3[1], hi3[1])
    ax.set_zlim(lo3[2], hi3[2])
    ax.set_box_aspect(np.maximum(hi3 - lo3, 1e-9 * np.max(hi3 - lo3)))
    ax.view_init(elev=a.view[0], azim=a.view[1])
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    title = a.title or meta.get("name", os.path.basename(a.spec))
    ax.set_title(title + ("" if a.color_by == "region" else "  (colour: %s)" % a.color_by))
    if mappable is not None:
        fig.colorbar(mappable, ax=ax, shrink=0.6, label={"k1": "k1", "k2": "k2", "H": "mean curvature H",
                                                          "K": "Gaussian curvature K"}[a.color_by])
    else:
        from matplotlib.patches import Patch
        ax.legend(handles=[Patch(color=REGION_RGB[0], label="blend (%s)" % meta.get("continuity", "C2")),
                           Patch(color=REGION_RGB[1], label="primary 1"),
                           Patch(color=REGION_RGB[2], label="primary 2")], loc="upper left", fontsize=9)
    tmpout = "%s.tmp-%d.png" % (a.output, os.getpid())
    fig.savefig(tmpout, dpi=110)
    os.replace(tmpout, a.output)


if __name__ == "__main__":
    main()
