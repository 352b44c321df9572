#!/usr/bin/python3
"""Render the papers' figures that C2Blend reproduces, one PNG per paper figure.

The figures (docs/FIGURES.md says what each paper figure shows and how ours differs):
  thesis_fig09.png    thesis Fig. 9: eqs. 87-88 at t = 0.2, variable decomposition
                      (section 3.3) with M = 10, 15, 20 against the closed form (CFS)
  thesis_fig15.png    thesis Fig. 15: eqs. 127-129 at t = 0.1, eq. 126 (section 3.4)
                      with M = 10, 15, 20 against the CFS
  seed001_fig1.png    seed 001 Figs. 1a-f: eq. 17 by pseudo-Navier, closed form, Fourier
                      series (N = 20, 100) and pseudo-spectral (N = 2, 5)
  seed001_fig1_error.png  the same six solutions as error maps against the closed form
  seed000_fig2.png .. seed000_fig5.png  seed 000 ODE surfaces from two curves (approach 1,
                      w multiples) and from four control curves (approach 2), closed and open
  seed000_fig6.png    seed 000 Fig. 6: C2 patch joins in u and v, C1 against C2

Exact blends come from the `c2blend` Python module (Blend.eval_grid); the approximate
solvers ("solver": "thesis-approx" / "pseudo-navier") from `c2blend eval`, and the primary
strips from `c2blend mesh --with-primaries`. The Fourier-series and pseudo-spectral
solutions of seed 001 are built here as in bench/compare: the series data of eq. 20 solved
exactly by the kernel, plus the remainder of eq. 22 (w = 3 (N + 1)). Seed 000's curves are
hand-drawn in the paper and not published: its figures use the curves of
examples/seed000_*.json (and open halves of them). Every title names the paper figure and
the settings; the numbers (errors, joins) are measured on the rendered solutions and are
also printed, one line per PNG.

usage: plot_papers.py [-o DIR] [--build DIR] [--c2blend PATH] [--module-dir DIR]
                      [--only NAME [NAME ...]] [--dpi 100]
"""
import argparse
import copy
import io
import json
import os
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import colors  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
EXAMPLES = os.path.join(ROOT, "examples")

BLEND_RGB = (0.88, 0.48, 0.10)
PRIM1_RGB = (0.36, 0.62, 0.72)   # the thesis draws its primaries in cyan and brown
PRIM2_RGB = (0.60, 0.42, 0.30)
M_COLOURS = {10: "#d62728", 15: "#2ca02c", 20: "#1f77b4"}
PATCH_RGB = [(0.88, 0.48, 0.10), (0.36, 0.48, 0.63), (0.44, 0.60, 0.42), (0.70, 0.45, 0.65)]

# Published errors: thesis Table 1 (eqs. 87-88) and Table 3 (eqs. 127-129), E1 and E4 per M;
# seed 001 section 3, eq. 24.
THESIS_PUBLISHED = {
    "thesis_eq087_088": {10: (4.55e-2, 7.95e-3), 15: (4.85e-3, 7.65e-4), 20: (6.40e-5, 8.31e-6)},
    "thesis_eq127_129": {10: (4.35e-2, 4.63e-3), 15: (3.17e-3, 3.34e-4), 20: (2.22e-5, 2.80e-6)},
}
SEED001_PUBLISHED = {"navier": 6.637916e-4, "F20": 6.565263e-2, "F100": 6.513351e-2,
                     "P2": 5.845711e-2, "P5": 6.294766e-2}


def load_example(name):
    with open(os.path.join(EXAMPLES, name + ".json")) as f:
        return json.load(f)


class Kernel:
    """The two ways into the kernel: the Python module and the CLI."""

    def __init__(self, c2blend_cli, module):
        self.cli = c2blend_cli
        self.mod = module

    def run(self, args, spec):
        r = subprocess.run([self.cli] + args, input=json.dumps(spec), capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError("c2blend %s (%s): %s" % (args[0], spec.get("name", "spec"), r.stderr.strip()))
        return r.stdout

    def cli_grid(self, spec, nu, nv):
        """`c2blend eval` on the grid u_i = i/(nu-1), v_j over v_range (both ends): (nu, nv, 3).
        Used for the approximate solvers, which the Python module refuses."""
        out = self.run(["eval", "-", "--u", str(nu), "--v", str(nv)], spec)
        a = np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1, ndmin=2)
        return a[:, 2:5].reshape(nu, nv, 3)

    def grid(self, spec, u, v, derivs=False):
        """Exact blend on the tensor grid u x v (Python module)."""
        return np.asarray(self.mod.Blend(spec).eval_grid(np.asarray(u, float), np.asarray(v, float),
                                                          derivs=derivs))

    def strips(self, spec, n, width):
        """Primary strips from `c2blend mesh --with-primaries WIDTH`: two grids (rows, cols, 3),
        each including the shared trimline row. Periodic v: cols = n (v_j = j/n), seam closed here."""
        with tempfile.TemporaryDirectory() as tmp:
            ply = os.path.join(tmp, "m.ply")
            self.run(["mesh", "-", "--n", str(n), "--with-primaries", str(width), "-o", ply], spec)
            with open(ply) as f:
                lines = f.read().split("\n")
        end = lines.index("end_header")
        nv = int(next(ln for ln in lines if ln.startswith("element vertex")).split()[2])
        V = np.array([[float(x) for x in ln.split()[:3]] for ln in lines[end + 1:end + 1 + nv]])
        rows = nv // n
        strip = (rows - n) // 2
        G = V.reshape(rows, n, 3)
        if spec.get("periodic"):
            G = np.concatenate([G, G[:, :1]], axis=1)
        return G[:strip + 1], G[strip + n - 1:]


# ---------------------------------------------------------------- drawing helpers

def light_vector(elev, azim):
    e, a = np.radians(elev), np.radians(azim)
    lv = np.array([np.cos(e) * np.cos(a + 0.6), np.cos(e) * np.sin(a + 0.6), np.sin(e) + 0.5])
    return lv / np.linalg.norm(lv)


def quads(P):
    """The cells of a grid (nu, nv, 3) as quadrilaterals (k, 4, 3)."""
    a, b, c, d = P[:-1, :-1], P[1:, :-1], P[1:, 1:], P[:-1, 1:]
    return np.stack([a, b, c, d], axis=2).reshape(-1, 4, 3)


def draw_surfaces(ax, pieces, view=(20, -60), curves=(), alpha=1.0, title=None, zoom=1.0):
    """Render grids with two-sided Lambert shading in one collection (mplot3d sorts the
    polygons of one collection by depth, not across collections).
    pieces: [(grid (nu, nv, 3), rgb)]; curves: [(points (n, 3), colour, linewidth)], drawn on
    top (for edges and silhouettes only: they are not hidden behind the surface)."""
    polys, cols = [], []
    lv = light_vector(*view)
    for P, rgb in pieces:
        q = quads(P)
        n = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])
        n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
        shade = 0.35 + 0.65 * np.abs(n @ lv)
        c = np.clip(np.array(rgb)[None, :] * shade[:, None], 0, 1)
        polys.append(q)
        cols.append(np.concatenate([c, np.full((len(c), 1), alpha)], axis=1))
    allq = np.concatenate(polys)
    allc = np.concatenate(cols)
    edge = allc.copy() if alpha >= 1 else "none"
    ax.computed_zorder = False    # the curves below are drawn over the surfaces
    ax.add_collection3d(Poly3DCollection(allq, facecolors=allc, edgecolors=edge, linewidths=0.3, zorder=1))
    pts = [allq.reshape(-1, 3)]
    for xyz, colour, lw in curves:
        ax.add_collection3d(Line3DCollection([xyz], colors=[colour], linewidths=lw, zorder=2))
        pts.append(xyz)
    set_equal(ax, np.concatenate(pts), view, zoom)
    if title:
        ax.set_title(title, fontsize=8.5)


def set_equal(ax, pts, view, zoom=1.0):
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    mid, span = 0.5 * (lo + hi), np.maximum(hi - lo, 1e-6 * np.max(hi - lo))
    ax.set_xlim(mid[0] - span[0] / 2, mid[0] + span[0] / 2)
    ax.set_ylim(mid[1] - span[1] / 2, mid[1] + span[1] / 2)
    ax.set_zlim(mid[2] - span[2] / 2, mid[2] + span[2] / 2)
    ax.set_box_aspect(span, zoom=zoom)
    ax.view_init(elev=view[0], azim=view[1])
    ax.set_axis_off()


def draw_curves(ax, curves, view, title, labels=None):
    """3D line drawing of input curves [(points, colour, lw, label)]."""
    for xyz, colour, lw, label in curves:
        ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], color=colour, lw=lw, label=label)
    set_equal(ax, np.concatenate([c[0] for c in curves]), view)
    ax.set_title(title, fontsize=8.5)
    if labels:
        ax.legend(fontsize=6.5, loc="lower left", frameon=False)


def save(fig, path):
    tmp = "%s.tmp-%d.png" % (path, os.getpid())
    fig.savefig(tmp, dpi=fig.dpi)
    plt.close(fig)
    os.replace(tmp, path)


# ---------------------------------------------------------------- thesis Figs. 9 and 15

def thesis_figure(K, out, fig_no, example, eqs, approach, widths, n_zoom, dpi):
    """Four blends (M = 10, 15, 20 by thesis-approx, and the CFS) with the primaries, their
    profile curves in the plane y = 0 (v = 1/4 and 3/4), magnifications, and the distance to
    the CFS along u."""
    spec = load_example(example)
    t = spec["time"]
    Ms = (10, 15, 20)
    nu, nv = 41, 61                      # 3D grids; v = 1/4, 3/4 are grid columns
    u = np.linspace(0, 1, nu)
    v = np.linspace(0, 1, nv)
    cfs = K.grid(spec, u, v)
    s1 = K.strips(spec, 40, widths[0])[0]
    s2 = K.strips(spec, 40, widths[1])[1]
    approx = {M: dict(spec, solver="thesis-approx", M=M, collocation=[100, 100], approach=approach)
              for M in Ms}
    grids = {M: K.cli_grid(approx[M], nu, nv) for M in Ms}
    # errors as in section 3.3.2.1 on 101 x 101 vertices: D = largest distance between two
    # points of equal u
    ue = np.linspace(0, 1, 101)
    ref = K.grid(spec, ue, ue)
    D = max(np.max(np.linalg.norm(r[:, None, :] - r[None, :, :], axis=2)) for r in ref)
    err, dist_u = {}, {}
    for M in Ms:
        d = np.linalg.norm(K.cli_grid(approx[M], 101, 101) - ref, axis=2)
        err[M] = (d.max(), d.mean() / D)
        dist_u[M] = d.max(axis=1)
    # profiles: fine u, v in {0, 1/4, 1/2, 3/4, 1}
    up = np.linspace(0, 1, 201)
    vp = np.linspace(0, 1, 5)
    prof = {M: K.cli_grid(approx[M], 201, 5) for M in Ms}
    prof["CFS"] = K.grid(spec, up, vp)
    pub = THESIS_PUBLISHED[example]

    fig = plt.figure(figsize=(15, 9.4), dpi=dpi)
    gs = fig.add_gridspec(2, 12, height_ratios=[1.15, 1])
    view = (12, -62)
    labels = {M: "M = %d" % M for M in Ms}
    labels["CFS"] = "CFS"
    for k, key in enumerate(Ms + ("CFS",)):
        ax = fig.add_subplot(gs[0, 3 * k:3 * k + 3], projection="3d")
        g = cfs if key == "CFS" else grids[key]
        if key == "CFS":
            ttl = "(%s) closed form (CFS)" % "abcd"[k]
        else:
            ttl = "(%s) M = %d: E1 %.3g, E4 %.3g\n(thesis: E1 %.3g, E4 %.3g)" % (
                "abcd"[k], key, err[key][0], err[key][1], pub[key][0], pub[key][1])
        draw_surfaces(ax, [(s1, PRIM1_RGB), (g, BLEND_RGB), (s2, PRIM2_RGB)], view=view, title=ttl,
                      zoom=1.2)
    # profile curves: x against z at v = 1/4 (x > 0) and v = 3/4 (x < 0); the primaries' too
    style = {10: dict(color=M_COLOURS[10], lw=1.3), 15: dict(color=M_COLOURS[15], lw=1.3),
             20: dict(color=M_COLOURS[20], lw=1.3), "CFS": dict(color="k", lw=1.3, ls="--")}
    c14, c34 = s1.shape[1] // 4, 3 * (s1.shape[1] - 1) // 4

    def profiles(ax):
        for S in (s1, s2):
            for c in (c14, c34):
                ax.plot(S[:, c, 0], S[:, c, 2], color="0.55", lw=2.5, solid_capstyle="butt")
        for key in Ms + ("CFS",):
            P = prof[key]
            for j in (1, 3):
                ax.plot(P[:, j, 0], P[:, j, 2], label=labels[key] if j == 1 else None, **style[key])
        ax.set_xlabel("x")
        ax.set_ylabel("z")
        ax.grid(alpha=0.3)

    nz = n_zoom + 1
    w = 12 // (nz + 1)
    ax_e = fig.add_subplot(gs[1, 0:w])
    profiles(ax_e)
    ax_e.set_aspect("equal")
    ax_e.set_title("(e) profile curves in the plane y = 0 (v = 1/4, 3/4);\nprimaries in grey", fontsize=8.5)
    ax_e.legend(fontsize=7, loc="best")
    # magnifications around the waist (u = 1/2, v = 1/4): the middle part, then closer
    i_mid = np.argmin(np.abs(up - 0.5))
    prev = ax_e
    for z in range(n_zoom):
        span_u = (0.25, 0.08)[z]
        sel = np.abs(up - 0.5) <= span_u
        xs = np.concatenate([prof[k][sel, 1, 0] for k in prof])
        zs = np.concatenate([prof[k][sel, 1, 2] for k in prof])
        if z == 0:
            x0, x1, z0, z1 = xs.min(), xs.max(), zs.min(), zs.max()
        else:
            xc, zc = prof["CFS"][i_mid, 1, 0], prof["CFS"][i_mid, 1, 2]
            h = 0.6 * (max(prof[k][i_mid, 1, 0] for k in prof) - min(prof[k][i_mid, 1, 0] for k in prof))
            x0, x1, z0, z1 = xc - h * 0.2, xc + h * 1.8, zc - h, zc + h
        pad = 0.08 * max(x1 - x0, z1 - z0)
        x0, x1, z0, z1 = x0 - pad, x1 + pad, z0 - pad, z1 + pad
        ax = fig.add_subplot(gs[1, w * (z + 1):w * (z + 2)])
        profiles(ax)
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        prev.add_patch(Rectangle((x0, z0), x1 - x0, z1 - z0, fill=False, ec="m", lw=1))
        ax.set_title("(%s) magnified (magenta box in %s)" % ("fg"[z], "(e)" if z == 0 else "(f)"), fontsize=8.5)
        prev = ax
    ax = fig.add_subplot(gs[1, w * nz:12])
    for M in Ms:
        ax.semilogy(ue, np.maximum(dist_u[M], 1e-17), color=M_COLOURS[M],
                    label="M = %d: E1 %.3g (thesis %.3g)" % (M, err[M][0], pub[M][0]))
    ax.set_xlabel("u")
    ax.set_ylabel("max over v of |S_M - S_CFS|")
    ax.set_title("(%s, ours) distance to the CFS along u" % "fgh"[n_zoom], fontsize=8.5)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower center")
    what = {"decomposition": "variable decomposition (section 3.3, eqs. 89a-c)",
            "differential": "differential property (section 3.4.1, eq. 126)"}[approach]
    fig.suptitle("Thesis Fig. %d: the blend of eqs. %s at t = %g by the %s with M = 10, 15, 20 (I = J = 100)\n"
                 "against the closed form (CFS); all shape parameters 1. E1 = max distance, E4 = mean distance / D "
                 "(D = %.4g), on 101 x 101 vertices" % (fig_no, eqs, t, what, D), fontsize=10)
    fig.subplots_adjust(left=0.05, right=0.99, top=0.93, bottom=0.06, wspace=1.6, hspace=0.1)
    name = "thesis_fig%02d.png" % fig_no
    save(fig, os.path.join(out, name))
    return name, "; ".join("M = %d: E1 %.3g E4 %.3g (thesis %.3g, %.3g)" % (M, err[M][0], err[M][1], pub[M][0],
                                                                          pub[M][1]) for M in Ms)


# ---------------------------------------------------------------- seed 001 Fig. 1

def seed001_solutions(K, u, v):
    """Eq. 17 on the grid u x v (v over [0, 2 pi]) by the six methods of Fig. 1: a pseudo-Navier,
    b closed form, c/d Fourier series N = 20/100, e/f pseudo-spectral N = 2/5."""
    full = load_example("seed001_eq17")
    k = full["constants"]
    group1 = copy.deepcopy(full)
    group1["constants"]["a2"] = 0.0
    navier = load_example("seed001_eq17_navier")
    sol = {"b": K.grid(full, u, v)}
    # eq. 18: the first-group data in closed form plus pseudo-Navier for a2 e^v
    sol["a"] = K.grid(group1, u, v) + K.cli_grid(navier, len(u), len(v))

    def fourier_spec(N):
        """Eq. 20: v and e^v replaced by their N-term Fourier series; the data become
        trigonometric polynomials, sampled exactly enough for the kernel's FFT."""
        ns = max(64, 8 * N)
        w = 2 * np.pi * np.arange(ns) / ns
        n = np.arange(1, N + 1)[:, None]
        sv = np.pi - np.sum(2.0 / n * np.sin(n * w), axis=0)
        terms = (np.cos(n * w) - n * np.sin(n * w)) / (1.0 + n * n)
        se = (np.exp(2 * np.pi) - 1) / np.pi * (0.5 + np.sum(terms, axis=0))
        x = k["a0"] + k["a1"] * sv + k["a2"] * se
        y = k["a3"] + k["a4"] * sv
        z = np.full(ns, k["h0"])
        f = copy.deepcopy(full)
        f["periodic"] = True
        f["boundary"]["u0"][0] = {"samples": np.stack([x, y, z], axis=1).tolist()}
        return f

    for key, N in (("c", 20), ("d", 100)):
        sol[key] = K.grid(fourier_spec(N), u, v)
    ends = np.array([0.0, 1.0])
    true_ends = K.grid(full, ends, v, derivs=True)      # the closed form meets the data
    uu = np.asarray(u)[:, None, None]
    for key, N in (("e", 2), ("f", 5)):
        f = fourier_spec(N)
        X = K.grid(f, u, v)
        fe = K.grid(f, ends, v, derivs=True)
        # eq. 22: R = r1 e^{wu} + r2 u e^{wu} + r3 e^{-wu} + r4 u e^{-wu} restores S and S_u
        w = 3.0 * (N + 1)
        ep, em = np.exp(w), np.exp(-w)
        A = np.array([[1, 0, 1, 0], [w, 1, -w, 1], [ep, ep, em, em], [w * ep, ep + w * ep, -w * em, em - w * em]])
        rhs = np.stack([true_ends[0, :, 0] - fe[0, :, 0], true_ends[0, :, 1] - fe[0, :, 1],
                        true_ends[1, :, 0] - fe[1, :, 0], true_ends[1, :, 1] - fe[1, :, 1]])
        r = np.linalg.solve(A, rhs.reshape(4, -1)).reshape(rhs.shape)
        eu, ed = np.exp(w * uu), np.exp(-w * uu)
        sol[key] = X + r[0] * eu + r[1] * uu * eu + r[2] * ed + r[3] * uu * ed
    return sol


def e24(a, ref):
    """Seed 001 eq. 24: mean relative distance."""
    return float(np.mean(np.linalg.norm(a - ref, axis=2) / np.linalg.norm(ref, axis=2)))


SEED001_PANELS = [
    ("a", "pseudo-Navier, M = N = 3, 7 x 7 interior points", "navier"),
    ("b", "closed form (C2Blend, eq. 19)", None),
    ("c", "Fourier series, N = 20", "F20"),
    ("d", "Fourier series, N = 100", "F100"),
    ("e", "pseudo-spectral, N = 2, w = 9", "P2"),
    ("f", "pseudo-spectral, N = 5, w = 18", "P5"),
]


def seed001_figures(K, out, dpi):
    n = 100                                        # eq. 24 grid: u_i = i/99, v_j = 2 pi j/99
    ue, ve = np.linspace(0, 1, n), np.linspace(0, 2 * np.pi, n)
    big = seed001_solutions(K, ue, ve)
    E = {p: e24(big[p], big["b"]) for p, _, _ in SEED001_PANELS}
    # v clustered at both ends, where the Fourier series' Gibbs oscillations are
    u, v = np.linspace(0, 1, 31), np.pi * (1 - np.cos(np.linspace(0, np.pi, 97)))
    sol = seed001_solutions(K, u, v)
    view = (24, -35)
    fig = plt.figure(figsize=(13.5, 9.4), dpi=dpi)
    for k, (p, what, key) in enumerate(SEED001_PANELS):
        ax = fig.add_subplot(2, 3, k + 1, projection="3d")
        g = sol[p]
        if key:
            ttl = "(%s) %s\nE (eq. 24) %.4g, seed 001: %.4g" % (p, what, E[p], SEED001_PUBLISHED[key])
        else:
            ttl = "(%s) %s\nreference (E = 0)" % (p, what)
        top = g[0]
        draw_surfaces(ax, [(g, BLEND_RGB)], view=view, title=ttl, zoom=1.2,
                      curves=[(top, "k", 1.0), (K.grid(load_example("seed001_eq17"), [0.0], v)[0], "#1f77b4", 1.0)])
    fig.legend(handles=[Line2D([], [], color="k", lw=1, label="the method's curve at u = 0"),
                        Line2D([], [], color="#1f77b4", lw=1, label="the upper boundary curve of eq. 17")],
               loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.suptitle("Seed 001 Fig. 1: eq. 17 (C1, b = 1, c = 18, d = 81) by six methods; E = eq. 24 against the "
                 "closed form on 100 x 100 points", fontsize=10)
    fig.subplots_adjust(left=0.01, right=0.99, top=0.91, bottom=0.05, wspace=0.02, hspace=0.12)
    save(fig, os.path.join(out, "seed001_fig1.png"))

    # error maps |X - X_CFS| over (v, u), one log colour scale
    fig, axes = plt.subplots(2, 3, figsize=(13.5, 7.6), dpi=dpi, sharex=True, sharey=True, layout="constrained")
    norm = colors.LogNorm(vmin=1e-7, vmax=1.0)
    im = None
    for ax, (p, what, key) in zip(axes.flat, SEED001_PANELS):
        d = np.linalg.norm(big[p] - big["b"], axis=2)
        if key:
            im = ax.pcolormesh(ve, ue, np.maximum(d, 1e-12), norm=norm, cmap="magma", shading="auto")
            ax.set_title("(%s) %s\nmax %.3g, E %.4g (seed 001: %.4g)" % (p, what, d.max(), E[p],
                                                                       SEED001_PUBLISHED[key]), fontsize=8.5)
        else:
            zz = big[p][:, :, 2]
            ax.pcolormesh(ve, ue, zz, cmap="Greys", shading="auto", alpha=0.25)
            ax.text(np.pi, 0.5, "(b) closed form:\nthe reference", ha="center", va="center", fontsize=10)
            ax.set_title("(b) closed form (C2Blend)", fontsize=8.5)
        ax.set_xticks([0, np.pi / 2, np.pi, 3 * np.pi / 2, 2 * np.pi], ["0", "π/2", "π", "3π/2", "2π"])
    for ax in axes[1]:
        ax.set_xlabel("v")
    for ax in axes[:, 0]:
        ax.set_ylabel("u (0: upper curve, 1: circle)")
    fig.colorbar(im, ax=axes, shrink=0.85, label="|X - X_CFS| (model units)")
    fig.suptitle("Seed 001 Fig. 1, as error maps: distance of each method's blend to the closed form "
                 "(100 x 100 points of eq. 24)", fontsize=10)
    save(fig, os.path.join(out, "seed001_fig1_error.png"))
    return [("seed001_fig1.png", "; ".join("%s %.4g (paper %.4g)" % (p, E[p], SEED001_PUBLISHED[key])
                                           for p, _, key in SEED001_PANELS if key)),
            ("seed001_fig1_error.png", "max |X - X_CFS|: " + ", ".join(
                "%s %.3g" % (p, np.linalg.norm(big[p] - big["b"], axis=2).max())
                for p, _, key in SEED001_PANELS if key))]


# ---------------------------------------------------------------- seed 000 Figs. 2-6

def open_version(spec):
    """An open variant of a closed seed 000 example: half of each curve (2 pi v -> pi v)."""
    s = json.loads(json.dumps(spec).replace("2*pi*v", "pi*v"))
    s["periodic"] = False
    s["name"] = spec["name"] + "_open"
    return s


def ode_spec(base, shape=None, w=None, controls=None, v_range=None):
    s = copy.deepcopy(base)
    if shape is not None:
        s["shape"] = list(shape)
    if w is not None:
        s["curves"].pop("controls", None)
        s["curves"]["w"] = list(w)
    if controls is not None:
        s["curves"].pop("w", None)
        s["curves"]["controls"] = controls
    if v_range is not None:
        s["v_range"] = list(v_range)
        s["periodic"] = False
    return s


def curve_points(K, base, expr, v):
    """A curve given as three expressions in v, sampled by the kernel: an ODE spec whose two
    boundary curves are both this curve (and zero derivatives) is that curve at u = 0."""
    s = {"continuity": "ODE", "shape": [1, 1, 1], "v_range": base["v_range"], "periodic": base["periodic"],
         "constants": base.get("constants", {}),
         "curves": {"c1": expr, "c4": expr, "w": [0, 0, 0, 0]}}
    return K.grid(s, [0.0], v)[0]


def scaled_controls(controls, k, centres):
    """The four control curves scaled by k in x and y about the given centres (Fig. 4e-h)."""
    outc = []
    for c, (cx, cy) in zip(controls, centres):
        x, y, z = c["curve"]
        outc.append({"u": c["u"], "curve": ["%r+%r*((%s)-%r)" % (cx, k, x, cx),
                                            "%r+%r*((%s)-%r)" % (cy, k, y, cy), z]})
    return outc


def seed000_approach1(K, out, fig_no, closed, dpi):
    """Figs. 2 (closed) and 3 (open): two boundary curves, derivatives as multiples of them."""
    base = load_example("seed000_multiples")
    if not closed:
        base = open_version(base)
    v = np.linspace(base["v_range"][0], base["v_range"][1], 61 if closed else 41)
    u = np.linspace(0, 1, 31)
    c1 = curve_points(K, base, base["curves"]["c1"], v)
    c4 = curve_points(K, base, base["curves"]["c4"], v)
    view = (22, -62)
    panels = [("c", (0, 0, 0, 0), "w = 0 (the paper: like Maya's loft)"),
              ("d", (-1, 0, 10, 0), "w1 = -1, w3 = 10, w2 = w4 = 0"),
              ("e", (0, 1, 0, -10), "w1 = w3 = 0, w2 = 1, w4 = -10")]
    fig = plt.figure(figsize=(16, 4.8), dpi=dpi)
    gs = fig.add_gridspec(1, 5, width_ratios=[1, 1, 1, 1, 0.9])
    ax = fig.add_subplot(gs[0, 0], projection="3d")
    draw_curves(ax, [(c1, "#1f77b4", 1.6, "c1 (u = 0)"), (c4, "#d62728", 1.6, "c4 (u = 1)")], view,
                "(a) the two boundary curves (ours)\n(b) Maya's loft: not reproduced", labels=True)
    info = []
    v0, v1 = base["v_range"]
    vs = np.array([v0, v0 + (v1 - v0) * (0.5 if closed else 1.0)])
    ax_side = fig.add_subplot(gs[0, 4])
    for k, (p, w, what) in enumerate(panels):
        s = ode_spec(base, w=w)
        g = K.grid(s, u, v)
        ax = fig.add_subplot(gs[0, k + 1], projection="3d")
        draw_surfaces(ax, [(g, PATCH_RGB[k])], view=view, title="(%s) %s" % (p, what))
        info.append("%s: z range %.2f..%.2f" % (p, g[:, :, 2].min(), g[:, :, 2].max()))
        side = K.grid(s, np.linspace(0, 1, 201), vs)
        for j in range(2):
            ax_side.plot(side[:, j, 0], side[:, j, 2], color=PATCH_RGB[k], lw=1.8,
                         label="(%s)" % p if j == 0 else None)
    for key in ("c1", "c4"):
        pc = curve_points(K, base, base["curves"][key], vs)
        ax_side.plot(pc[:, 0], pc[:, 2], "s", color="k", ms=4, label="boundary curves" if key == "c1" else None)
    ax_side.set_xlabel("x")
    ax_side.set_ylabel("z")
    ax_side.set_aspect("equal")
    ax_side.grid(alpha=0.3)
    ax_side.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, frameon=False)
    ax_side.set_title("(ours) side view of (c)-(e):\nu-curves at v = %g, %g" % (vs[0], vs[1]), fontsize=8.5)
    fig.suptitle("Seed 000 Fig. %d: %s surface from two boundary curves, approach 1 (eq. 24: c2 = w1 c1, "
                 "c3 = w2 c1, c5 = w3 c4, c6 = w4 c4), rho = eta = lambda = 1.\nThe paper's curves are "
                 "hand-drawn and not published: ours are the %s of examples/seed000_multiples.json"
                 % (fig_no, "closed" if closed else "open",
                    "ellipses" if closed else "half ellipses (v in [0, 1] -> half turn)"), fontsize=9.5)
    fig.subplots_adjust(left=0.0, right=0.99, top=0.83, bottom=0.2, wspace=0.05)
    name = "seed000_fig%d.png" % fig_no
    save(fig, os.path.join(out, name))
    return name, "; ".join(info)


def control_distance(K, spec, v):
    """Largest distance between the surface at u_k and control curve k, over v and k."""
    g = K.grid(spec, [c["u"] for c in spec["curves"]["controls"]], v)
    d = 0.0
    for i, c in enumerate(spec["curves"]["controls"]):
        d = max(d, np.max(np.linalg.norm(g[i] - curve_points(K, spec, c["curve"], v), axis=1)))
    return d


def seed000_approach2(K, out, fig_no, closed, dpi):
    """Figs. 4 (closed) and 5 (open): two boundary curves and four control curves (eqs. 3-7)."""
    base = load_example("seed000_controls")
    if not closed:
        base = open_version(base)
    v0, v1 = base["v_range"]
    v = np.linspace(v0, v1, 61 if closed else 41)
    u = np.linspace(0, 1, 31)
    ctrl = base["curves"]["controls"]
    stiff, soft = (1, 3, 1), (1e-4, 3, 1e-4)
    view = (18, -62)
    # the side view: u-curves at the angles 0 and pi of the (half) ellipses
    vs = np.array([v0, v0 + (v1 - v0) * (0.5 if closed else 1.0)])

    def curves_of(spec):
        cv = [(curve_points(K, spec, spec["curves"]["c1"], v), "#1f77b4", 1.4, "boundary curves"),
              (curve_points(K, spec, spec["curves"]["c4"], v), "#1f77b4", 1.4, None)]
        for i, c in enumerate(spec["curves"]["controls"]):
            cv.append((curve_points(K, spec, c["curve"], v), "#d62728", 0.9, "control curves" if i == 0 else None))
        return cv

    sets = [("abcd", base, "")]
    if closed:
        centres = [(0.0, 0.0), (0.0, 0.0), (0.0, 0.2), (0.0, 0.2)]
        sets.append(("efgh", ode_spec(base, controls=scaled_controls(ctrl, 0.8, centres)),
                     "controls scaled by 0.8 in x, y"))
    fig = plt.figure(figsize=(14, 4.5 * len(sets) + 0.6), dpi=dpi)
    info = []
    for row, (letters, spec, note) in enumerate(sets):
        cv = curves_of(spec)
        ax = fig.add_subplot(len(sets), 4, 4 * row + 1, projection="3d")
        draw_curves(ax, cv, view, "(%s) boundary and control curves (ours)%s;\nMaya's loft through them: "
                    "not reproduced" % (letters[0], (",\n" + note) if note else ""), labels=True)
        g, side = {}, {}
        for k, sh in enumerate((stiff, soft)):
            s = ode_spec(spec, shape=sh)
            g[k] = K.grid(s, u, v)
            side[k] = K.grid(s, np.linspace(0, 1, 201), vs)
            dc = control_distance(K, s, v)
            ax = fig.add_subplot(len(sets), 4, 4 * row + 2 + k, projection="3d")
            draw_surfaces(ax, [(g[k], BLEND_RGB if k == 0 else PATCH_RGB[1])], view=view,
                          title="(%s) rho = %g, eta = %g, lambda = %g\nmax distance to the control curves %.3f"
                          % (letters[1 + k], sh[0], sh[1], sh[2], dc))
            info.append("%s: control distance %.3f" % (letters[1 + k], dc))
        ax = fig.add_subplot(len(sets), 4, 4 * row + 4)
        for k, colour in ((0, BLEND_RGB), (1, PATCH_RGB[1])):
            for j in range(2):
                ax.plot(side[k][:, j, 0], side[k][:, j, 2], color=colour, lw=1.8,
                        label="(%s)" % letters[1 + k] if j == 0 else None)
        for i, c in enumerate(spec["curves"]["controls"]):
            pc = curve_points(K, spec, c["curve"], vs)
            ax.plot(pc[:, 0], pc[:, 2], "o", color="#d62728", ms=4, label="control curves" if i == 0 else None)
        for key in ("c1", "c4"):
            pc = curve_points(K, spec, spec["curves"][key], vs)
            ax.plot(pc[:, 0], pc[:, 2], "s", color="#1f77b4", ms=4, label="boundary curves" if key == "c1" else None)
        dmax = np.max(np.linalg.norm(g[0] - g[1], axis=2))
        ax.set_xlabel("x")
        ax.set_ylabel("z")
        ax.set_aspect("equal")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="center")
        ax.set_title("(%s) side view of (%s), (%s): u-curves at v = %g, %g;\nlargest distance between the "
                     "surfaces %.3f" % (letters[3], letters[1], letters[2], vs[0], vs[1], dmax),
                     fontsize=8.5)
        info.append("%s: (%s)-(%s) distance %.3f" % (letters[3], letters[1], letters[2], dmax))
    fig.suptitle("Seed 000 Fig. %d: %s surface from two boundary curves and four control curves at u = %s, "
                 "approach 2 (derivatives by eqs. 3-7).\nThe paper's curves are hand-drawn and not published: "
                 "ours are the %s of examples/seed000_controls.json" % (
                     fig_no, "closed" if closed else "open", ", ".join("%g" % c["u"] for c in ctrl),
                     "ellipses" if closed else "half ellipses (v in [0, 1] -> half turn)"), fontsize=9.5)
    fig.subplots_adjust(left=0.01, right=0.99, top=0.87 if closed else 0.8, bottom=0.06, wspace=0.12, hspace=0.2)
    name = "seed000_fig%d.png" % fig_no
    save(fig, os.path.join(out, name))
    return name, "; ".join(info)


def normal_curvature_u(d):
    """Normal curvature in the u direction from derivs (.., 10, 3): S_uu . n / |S_u|^2."""
    Su, Sv, Suu = d[..., 1, :], d[..., 2, :], d[..., 3, :]
    n = np.cross(Su, Sv)
    n /= np.linalg.norm(n, axis=-1)[..., None]
    return np.sum(Suu * n, axis=-1) / np.sum(Su * Su, axis=-1)


def seed000_fig6(K, out, dpi):
    """Fig. 6: (a) two patches joined in u (eqs. 24-25), (b) joined in v, (c) four patches
    joined in u and v, (d) C1 against C2 joins."""
    p1 = load_example("seed000_multiples")            # c1 -> c4, w = (w1, w2, w3, w4)
    cv = p1["curves"]
    w = cv["w"]
    c4hat = ["0.9*cos(2*pi*v)", "0.75*sin(2*pi*v)", "3.5"]
    w56 = [-0.5, 1.0]
    p2 = copy.deepcopy(p1)                               # eq. 25: c4 -> c4hat
    p2["curves"] = {"c1": cv["c4"], "c4": c4hat, "w": [w[2], w[3]] + w56}
    p2["shape"] = [1, 3, 1]
    ue = np.array([0.0, 1.0])
    vv = np.linspace(0, 1, 201)
    # (a) u-join: S, S_u, S_uu of patch 1 at u = 1 against patch 2 at u = 0
    d1 = K.grid(p1, ue, vv, derivs=True)
    d2 = K.grid(p2, ue, vv, derivs=True)
    jump_u = [np.max(np.linalg.norm(d1[1, :, k] - d2[0, :, k], axis=1)) for k in (0, 1, 3)]
    # (b) v-join: two open patches on v in [0, 1/2] and [1/2, 1] of the open curves, with the
    # paper's shapes (1, 1, 3) and (0.1, 0.1, 3), and with equal shapes
    po = open_version(p1)
    va, vb = ode_spec(po, shape=(1, 1, 3), v_range=(0, 0.5)), ode_spec(po, shape=(0.1, 0.1, 3), v_range=(0.5, 1))
    vb_eq = ode_spec(po, shape=(1, 1, 3), v_range=(0.5, 1))
    uu = np.linspace(0, 1, 101)

    def vjump(a, b, vj, vk=None):
        da = K.grid(a, uu, [vj], derivs=True)[:, 0]
        db = K.grid(b, uu, [vj if vk is None else vk], derivs=True)[:, 0]
        return [np.max(np.linalg.norm(da[:, k] - db[:, k], axis=1)) for k in (0, 2, 5)]
    jump_v_paper = vjump(va, vb, 0.5)
    jump_v_equal = vjump(va, vb_eq, 0.5)
    # (c) four patches: patch 1 and patch 2 (closed, u-join), each split at v = 1/2 (v-join);
    # equal shapes across the v-joins
    quarters = [ode_spec(p, v_range=r) for p in (p1, p2) for r in ((0, 0.5), (0.5, 1))]
    jumps_c = max(max(vjump(quarters[2 * i], quarters[2 * i + 1], 0.5) + vjump(quarters[2 * i + 1],
                                                                            quarters[2 * i], 1.0, 0.0))
                  for i in range(2))
    for i in range(2):                                   # the u-joins of the halves
        vh = np.linspace(0.5 * i, 0.5 * i + 0.5, 51)
        da = K.grid(quarters[i], ue, vh, derivs=True)[1]
        db = K.grid(quarters[2 + i], ue, vh, derivs=True)[0]
        jumps_c = max([jumps_c] + [np.max(np.linalg.norm(da[:, k] - db[:, k], axis=1)) for k in (0, 1, 3)])
    # (d) C1 joins: cubic Hermite patches ("C1", b = 1, c = d = 0: S_uuuu = 0) with the same
    # S and S_u data; S_uu is free and jumps

    def mul(k, e):
        return ["(%r)*(%s)" % (float(k), x) for x in e]

    def c1_patch(a, b, wa, wb):
        return {"continuity": "C1", "shape": [1, 0, 0], "v_range": [0, 1], "periodic": True,
                "boundary": {"u0": [a, mul(wa, a)], "u1": [b, mul(wb, b)]}}
    q1 = c1_patch(cv["c1"], cv["c4"], w[0], w[2])
    q2 = c1_patch(cv["c4"], c4hat, w[2], w56[0])
    us = np.linspace(0, 1, 101)
    vk = 0.0
    k2 = np.concatenate([normal_curvature_u(K.grid(p, us, [vk], derivs=True)[:, 0]) for p in (p1, p2)])
    k1 = np.concatenate([normal_curvature_u(K.grid(p, us, [vk], derivs=True)[:, 0]) for p in (q1, q2)])
    s = np.concatenate([us, 1 + us])
    jump_k2 = abs(k2[101] - k2[100])
    jump_k1 = abs(k1[101] - k1[100])

    u = np.linspace(0, 1, 31)
    v = np.linspace(0, 1, 61)
    view = (16, -62)
    fig = plt.figure(figsize=(14, 10.6), dpi=dpi)
    ax = fig.add_subplot(2, 2, 1, projection="3d")
    draw_surfaces(ax, [(K.grid(p1, u, v), PATCH_RGB[0]), (K.grid(p2, u, v), PATCH_RGB[1])], view=view, zoom=1.2,
                  curves=[(curve_points(K, p1, cv["c4"], v), "k", 1.5)],
                  title="(a) C2 join in u (eqs. 24-25): patch 1 (orange, rho, eta, lambda = 1, 1, 1) and patch 2\n"
                  "(blue, 1, 3, 1) share c4 (black), w3 c4, w4 c4. Across the join: |dS| %.1e, |dS_u| %.1e, "
                  "|dS_uu| %.1e" % tuple(jump_u))
    ax = fig.add_subplot(2, 2, 2, projection="3d")
    vv2 = np.linspace(0, 0.5, 31)
    ga = K.grid(va, u, vv2)
    gb = K.grid(vb, u, vv2 + 0.5)
    draw_surfaces(ax, [(ga, PATCH_RGB[0]), (gb, PATCH_RGB[1])], view=(22, -70), zoom=1.2,
                  curves=[(ga[:, -1], "k", 1.5)],
                  title="(b) join in v at v = 1/2 (black) of open half-curves; the paper's shapes (1, 1, 3) and "
                  "(0.1, 0.1, 3):\n|dS| %.1e, |dS_v| %.1e, |dS_vv| %.1e; with equal shapes: %.1e, %.1e, %.1e"
                  % tuple(jump_v_paper + jump_v_equal))
    ax = fig.add_subplot(2, 2, 3, projection="3d")
    pieces = []
    for i, q in enumerate(quarters):
        vr = np.linspace(q["v_range"][0], q["v_range"][1], 31)
        pieces.append((K.grid(q, u, vr), PATCH_RGB[i]))
    draw_surfaces(ax, pieces, view=view, zoom=1.2,
                  title="(c) four patches joined in u and in v: patches 1 and 2 of (a), each split at v = 1/2;\n"
                  "largest jump across the joins (S, S_v, S_vv at v = 0, 1/2; S, S_u, S_uu at the u-join): %.1e"
                  % jumps_c)
    ax = fig.add_subplot(2, 2, 4)
    ax.plot(s[:101], k2[:101], color=PATCH_RGB[0], lw=2, label="C2 (sixth-order ODE), jump %.2g" % jump_k2)
    ax.plot(s[101:], k2[101:], color=PATCH_RGB[0], lw=2)
    ax.plot(s[:101], k1[:101], color="k", lw=1.4, ls="--", label="C1 (cubic Hermite, same S, S_u), jump %.2g"
            % jump_k1)
    ax.plot(s[101:], k1[101:], color="k", lw=1.4, ls="--")
    ax.axvline(1.0, color="0.5", lw=0.8)
    near = (s >= 0.6) & (s <= 1.4)
    lo = min(k1[near].min(), k2[near].min())
    hi = max(k1[near].max(), k2[near].max())
    ax.set_xlim(0.6, 1.4)
    ax.set_ylim(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo))
    ax.set_xlabel("u across both patches (patch 1: 0..1, patch 2: 1..2) near the join, v = %g" % vk)
    ax.set_ylabel("normal curvature in the u direction")
    ax.set_title("(d) C1 against C2 joins of the two patches of (a) (ours: the paper decomposes a mesh\n"
                 "that is not available); the C1 join keeps S and S_u but its curvature jumps", fontsize=8.5)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle("Seed 000 Fig. 6: patches joined with C2 continuity in u (section 5.1) and v (section 5.2). "
                 "The paper's curves are not published: ours are those of examples/seed000_multiples.json",
                 fontsize=10)
    fig.subplots_adjust(left=0.01, right=0.98, top=0.92, bottom=0.06, wspace=0.08, hspace=0.15)
    save(fig, os.path.join(out, "seed000_fig6.png"))
    return "seed000_fig6.png", ("u-join %.1e %.1e %.1e; v-join paper shapes %.1e %.1e %.1e, equal %.1e %.1e %.1e; "
                                "4 patches %.1e; curvature jump C2 %.2g, C1 %.2g"
                                % tuple(jump_u + jump_v_paper + jump_v_equal + [jumps_c, jump_k2, jump_k1]))


# ---------------------------------------------------------------- main

FIGURES = ["thesis_fig09", "thesis_fig15", "seed001_fig1", "seed000_fig2", "seed000_fig3",
           "seed000_fig4", "seed000_fig5", "seed000_fig6"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--output", default=os.path.join(ROOT, "docs", "images", "papers"))
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (default build/)")
    ap.add_argument("--c2blend", default=None, help="the c2blend CLI (default BUILD/tools/c2blend)")
    ap.add_argument("--module-dir", default=None, help="directory of the c2blend module (default BUILD/plugin/ext)")
    ap.add_argument("--only", nargs="+", choices=FIGURES, default=FIGURES)
    ap.add_argument("--dpi", type=int, default=100)
    a = ap.parse_args()
    sys.path.insert(0, a.module_dir or os.path.join(a.build, "plugin", "ext"))
    import c2blend
    K = Kernel(a.c2blend or os.path.join(a.build, "tools", "c2blend"), c2blend)
    os.makedirs(a.output, exist_ok=True)
    jobs = {
        # Fig. 9: strips 0.3 long (not stated); Fig. 15: the extents of Fig. 14
        "thesis_fig09": lambda: [thesis_figure(K, a.output, 9, "thesis_eq087_088", "87-88", "decomposition",
                                               (0.3, 0.3), 1, a.dpi)],
        "thesis_fig15": lambda: [thesis_figure(K, a.output, 15, "thesis_eq127_129", "127-129", "differential",
                                               (0.35, 0.1), 2, a.dpi)],
        "seed001_fig1": lambda: seed001_figures(K, a.output, a.dpi),
        "seed000_fig2": lambda: [seed000_approach1(K, a.output, 2, True, a.dpi)],
        "seed000_fig3": lambda: [seed000_approach1(K, a.output, 3, False, a.dpi)],
        "seed000_fig4": lambda: [seed000_approach2(K, a.output, 4, True, a.dpi)],
        "seed000_fig5": lambda: [seed000_approach2(K, a.output, 5, False, a.dpi)],
        "seed000_fig6": lambda: [seed000_fig6(K, a.output, a.dpi)],
    }
    t_all = time.time()
    for key in a.only:
        t0 = time.time()
        for name, summary in jobs[key]():
            print("%-24s %5.1f s  %s" % (name, time.time() - t0, summary))
            t0 = time.time()
    print("all figures in %.1f s -> %s" % (time.time() - t_all, a.output))


if __name__ == "__main__":
    main()
