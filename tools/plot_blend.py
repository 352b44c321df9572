#!/usr/bin/python3
"""Plot a C2Blend blend surface together with strips of its primary surfaces.

usage: plot_blend.py SPEC.json -o OUT.png [--c2blend PATH] [--t T] [--n 61]
                     [--strip 0.15] [--title TEXT] [--view ELEV AZIM]
                     [--profile OUT2.png] [--v0 V]

The blend is evaluated by the c2blend CLI (`c2blend eval SPEC --u N --v N [--t T]`,
CSV on stdout).  The primaries ("primaries" in the spec) are evaluated here with
numpy from their libmatheval expressions.  For primary 0 (blend side u = 0) the strip
covers the primary's u in trim_u - direction*[0, L]; for primary 1 (blend side u = 1)
it covers trim_u + direction*[0, L]: both run away from the blend, since the blend's
boundary data are C_k = direction^k d^k S/du^k at u = trim_u.

Needs numpy and matplotlib (Debian: /usr/bin/python3 with python3-matplotlib).
Exit status: that of c2blend when it fails, 2 for bad usage or a bad spec, 1 otherwise.
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

try:
    import numpy as np
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
except ImportError as exc:  # pragma: no cover - environment problem
    sys.stderr.write(
        f"plot_blend: {exc}; run it with a Python that has numpy and matplotlib "
        "(e.g. /usr/bin/python3 with Debian's python3-matplotlib)\n")
    sys.exit(1)

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_CLI = REPO_ROOT / "build" / "tools" / "c2blend"

BLEND_COLOR = "#e0883a"                      # warm orange
PRIMARY_COLORS = ["#7d91ad", "#88a784"]      # grey-blue, grey-green
EDGE_COLOR = "#303030"


class PlotError(Exception):
    def __init__(self, msg, code=1):
        super().__init__(msg)
        self.code = code


# ---------------------------------------------------------------------------
# libmatheval expressions -> numpy
# ---------------------------------------------------------------------------

def _erf(x):
    return np.vectorize(math.erf, otypes=[float])(x)


def _step(x):
    return np.where(np.asarray(x) < 0, 0.0, 1.0)


def _delta(x):
    return np.where(np.asarray(x) == 0, np.inf, 0.0)


def _nandelta(x):
    return np.where(np.asarray(x) == 0, np.nan, 0.0)


# The function set libmatheval (and the kernel's scanner) accepts.
FUNCTIONS = {
    "exp": np.exp, "log": np.log, "sqrt": np.sqrt,
    "sin": np.sin, "cos": np.cos, "tan": np.tan,
    "cot": lambda x: 1.0 / np.tan(x), "sec": lambda x: 1.0 / np.cos(x),
    "csc": lambda x: 1.0 / np.sin(x),
    "asin": np.arcsin, "acos": np.arccos, "atan": np.arctan,
    "acot": lambda x: np.arctan(1.0 / x), "asec": lambda x: np.arccos(1.0 / x),
    "acsc": lambda x: np.arcsin(1.0 / x),
    "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
    "coth": lambda x: 1.0 / np.tanh(x), "sech": lambda x: 1.0 / np.cosh(x),
    "csch": lambda x: 1.0 / np.sinh(x),
    "asinh": np.arcsinh, "acosh": np.arccosh, "atanh": np.arctanh,
    "acoth": lambda x: 0.5 * np.log((x + 1.0) / (x - 1.0)),
    "asech": lambda x: np.arccosh(1.0 / x), "acsch": lambda x: np.arcsinh(1.0 / x),
    "abs": np.abs, "step": _step, "delta": _delta, "nandelta": _nandelta, "erf": _erf,
}

_TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)"
                    r"|(?P<name>[A-Za-z_]\w*)|(?P<op>[-+*/^()]))")


def _tokenize(text):
    toks, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise PlotError(f"cannot parse expression '{text}' at '{text[pos:]}'", 2)
        pos = m.end()
        kind = m.lastgroup
        toks.append((kind, m.group(kind)))
    toks.append(("end", ""))
    return toks


def translate(text):
    """Translate a libmatheval expression into a fully parenthesised Python expression.

    Precedence as in libmatheval: + - < * / < unary minus < ^, with ^ LEFT-associative
    (2^3^2 = 64) and a unary minus after ^ taking the power chain to its right
    (x^-y^2 = x^(-(y^2))).  Functions become F_name(...), identifiers V_name.
    """
    toks = _tokenize(text)
    pos = 0

    def peek():
        return toks[pos]

    def take(kind=None, value=None):
        nonlocal pos
        k, v = toks[pos]
        if (kind and k != kind) or (value is not None and v != value):
            want = value if value is not None else kind
            got = v or "end of expression"
            raise PlotError(f"expression '{text}': expected {want}, found {got}", 2)
        pos += 1
        return v

    def expr():
        left = term()
        while peek() in (("op", "+"), ("op", "-")):
            op = take()
            left = f"({left} {op} {term()})"
        return left

    def term():
        left = unary()
        while peek() in (("op", "*"), ("op", "/")):
            op = take()
            left = f"({left} {op} {unary()})"
        return left

    def unary():
        if peek() == ("op", "-"):
            take()
            return f"(-{unary()})"
        return power()

    def power():
        base = primary()
        while peek() == ("op", "^"):
            take()
            rhs = unary() if peek() == ("op", "-") else primary()
            base = f"({base} ** {rhs})"
        return base

    def primary():
        kind, val = peek()
        if kind == "num":
            take()
            return repr(float(val))
        if kind == "name":
            take()
            if peek() == ("op", "("):
                if val not in FUNCTIONS:
                    raise PlotError(f"expression '{text}': unknown function '{val}'", 2)
                take("op", "(")
                arg = expr()
                take("op", ")")
                return f"F_{val}({arg})"
            return f"V_{val}"
        if (kind, val) == ("op", "("):
            take()
            inner = expr()
            take("op", ")")
            return inner
        raise PlotError(f"expression '{text}': unexpected '{val or 'end of expression'}'", 2)

    out = expr()
    take("end")
    return out


def eval_expression(text, u, v, t, constants):
    """Evaluate a libmatheval expression on numpy arrays u, v (same shape) at time t."""
    code = translate(text)
    names = {f"F_{k}": f for k, f in FUNCTIONS.items()}
    for k, val in constants.items():
        names[f"V_{k}"] = float(val)
    # pi and e are libmatheval's own constants and win over spec constants.
    names.update(V_pi=math.pi, V_e=math.e, V_u=u, V_v=v, V_t=float(t))
    for ident in set(re.findall(r"\bV_(\w+)", code)):
        if f"V_{ident}" not in names:
            raise PlotError(f"expression '{text}': unknown identifier '{ident}'", 2)
    with np.errstate(all="ignore"):
        val = eval(compile(code, "<expr>", "eval"), {"__builtins__": {}}, names)
    return np.broadcast_to(np.asarray(val, dtype=float), np.shape(u)).copy()


# ---------------------------------------------------------------------------
# c2blend CLI
# ---------------------------------------------------------------------------

def run_cli(cli, args, stdin_text=None):
    cmd = [str(cli)] + [str(a) for a in args]
    try:
        proc = subprocess.run(cmd, input=stdin_text, capture_output=True, text=True)
    except FileNotFoundError:
        raise PlotError(f"c2blend not found at {cli} (build it, or pass --c2blend PATH)", 2)
    except PermissionError:
        raise PlotError(f"c2blend at {cli} is not executable", 2)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        if proc.stderr and not proc.stderr.endswith("\n"):
            sys.stderr.write("\n")
        raise PlotError(None, proc.returncode)
    return proc.stdout


def parse_csv(text, expect_rows):
    lines = text.splitlines()
    if not lines or [h.strip() for h in lines[0].split(",")][:5] != ["u", "v", "x", "y", "z"]:
        raise PlotError("c2blend output does not start with the header 'u,v,x,y,z'")
    rows = [ln for ln in lines[1:] if ln.strip()]
    if len(rows) != expect_rows:
        raise PlotError(f"c2blend printed {len(rows)} rows, expected {expect_rows}")
    try:
        data = np.array([[float(s) for s in ln.split(",")[:5]] for ln in rows], dtype=float)
    except ValueError as exc:
        raise PlotError(f"c2blend output: {exc}")
    if data.shape != (expect_rows, 5):
        raise PlotError("c2blend output rows do not have five columns")
    return data


# ---------------------------------------------------------------------------
# geometry for plotting
# ---------------------------------------------------------------------------

def quads(X, Y, Z):
    """Quadrilateral faces of a grid surface, dropping faces with non-finite corners."""
    P = np.stack([X, Y, Z], axis=-1)
    q = np.stack([P[:-1, :-1], P[1:, :-1], P[1:, 1:], P[:-1, 1:]], axis=2)
    q = q.reshape(-1, 4, 3)
    return q[np.all(np.isfinite(q), axis=(1, 2))]


def shade(faces, rgb, light):
    """Light two-sided Lambert shading: 0.62 .. 1.0 of the base colour."""
    n = np.cross(faces[:, 2] - faces[:, 0], faces[:, 3] - faces[:, 1])
    norm = np.linalg.norm(n, axis=1)
    norm[norm == 0] = 1.0
    k = np.abs(n @ light) / norm
    k = 0.62 + 0.38 * k
    cols = np.clip(np.outer(k, rgb), 0.0, 1.0)
    return np.hstack([cols, np.ones((len(cols), 1))])


def light_direction(elev, azim):
    """A light from up-left of the viewer, fixed relative to the view direction."""
    e, a = math.radians(elev + 35.0), math.radians(azim - 40.0)
    d = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])
    return d / np.linalg.norm(d)


def atomic_savefig(fig, out, dpi):
    out = Path(out)
    tmp = out.parent / f"{out.name}.tmp-{os.getpid()}"
    try:
        fig.savefig(tmp, dpi=dpi, format="png")
        os.replace(tmp, out)
    except BaseException:
        try:
            tmp.unlink()
        except OSError:
            pass
        raise


# ---------------------------------------------------------------------------
# main
# ---------------------------------------------------------------------------

def primary_strip(prim, index, strip_len, vgrid, t, constants, nu):
    try:
        surf = prim["surface"]
        trim = float(prim["trim_u"])
        direction = float(prim.get("direction", 1))
    except (KeyError, TypeError, ValueError):
        raise PlotError(f"primaries[{index}] needs 'surface' (3 expressions) and 'trim_u'", 2)
    if not isinstance(surf, list) or len(surf) != 3:
        raise PlotError(f"primaries[{index}].surface must be a list of 3 expressions", 2)
    if index == 0:
        ends = (trim - direction * strip_len, trim)   # away from blend side u = 0
    else:
        ends = (trim, trim + direction * strip_len)   # away from blend side u = 1
    lo, hi = sorted(ends)
    up = np.linspace(lo, hi, nu)
    U, V = np.meshgrid(up, vgrid, indexing="ij")
    X, Y, Z = (eval_expression(str(s), U, V, t, constants) for s in surf)
    return X, Y, Z, (lo, hi), trim


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Plot a C2Blend blend surface and strips of its primary surfaces.")
    ap.add_argument("spec", help="blend spec (JSON)")
    ap.add_argument("-o", "--output", required=True, help="output PNG")
    ap.add_argument("--c2blend", default=str(DEFAULT_CLI),
                    help=f"path of the c2blend CLI (default {DEFAULT_CLI})")
    ap.add_argument("--t", type=float, default=None, help="time (default: the spec's 'time', else 0)")
    ap.add_argument("--n", type=int, default=61, help="grid points in u and v (default 61)")
    ap.add_argument("--strip", type=float, default=0.15,
                    help="length of each primary strip in its own u units (default 0.15)")
    ap.add_argument("--title", default=None, help="title (default: the spec's name)")
    ap.add_argument("--view", nargs=2, type=float, metavar=("ELEV", "AZIM"), default=(22.0, -58.0),
                    help="camera elevation and azimuth in degrees (default 22 -58)")
    ap.add_argument("--profile", default=None, metavar="OUT2.png",
                    help="also plot the blend's cross-section r = sqrt(x^2+y^2) vs z along u at v = v0")
    ap.add_argument("--v0", type=float, default=None,
                    help="v of the profile (default: the start of the spec's v_range)")
    args = ap.parse_args(argv)

    try:
        return run(args)
    except PlotError as exc:
        if exc.args and exc.args[0]:
            sys.stderr.write(f"plot_blend: {exc.args[0]}\n")
        return exc.code


def run(args):
    if args.n < 2:
        raise PlotError("--n must be at least 2", 2)
    if not (math.isfinite(args.strip) and args.strip >= 0):
        raise PlotError("--strip must be a finite number >= 0", 2)
    try:
        with open(args.spec, "r", encoding="utf-8") as f:
            spec = json.load(f)
    except (OSError, ValueError) as exc:
        raise PlotError(f"{args.spec}: {exc}", 2)
    if not isinstance(spec, dict):
        raise PlotError(f"{args.spec}: not a JSON object", 2)

    t = args.t if args.t is not None else float(spec.get("time", 0.0) or 0.0)
    constants = spec.get("constants") or {}
    n = args.n

    cli_args = ["eval", args.spec, "--u", n, "--v", n]
    if args.t is not None:
        cli_args += ["--t", repr(float(args.t))]
    data = parse_csv(run_cli(args.c2blend, cli_args), n * n)
    U, V, X, Y, Z = (data[:, k].reshape(n, n) for k in range(5))
    vgrid = V[0, :]

    surfaces = [("blend", X, Y, Z, BLEND_COLOR)]
    legend = [Patch(color=BLEND_COLOR, label=f"blend ({spec.get('continuity', '')}, u in [0, 1])".replace("(, ", "("))]
    prims = spec.get("primaries") or []
    if not isinstance(prims, list):
        raise PlotError("'primaries' must be a list", 2)
    nu_strip = max(6, int(round(n * 0.4)))
    strips = []
    for i, prim in enumerate(prims[:2]):
        if args.strip == 0:
            break
        PX, PY, PZ, (lo, hi), trim = primary_strip(prim, i, args.strip, vgrid, t, constants, nu_strip)
        col = PRIMARY_COLORS[i % len(PRIMARY_COLORS)]
        surfaces.append((f"primary {i}", PX, PY, PZ, col))
        strips.append((PX, PY, PZ))
        legend.append(Patch(color=col, label=f"primary {i}, u in [{lo:.4g}, {hi:.4g}] (trim {trim:.4g})"))

    # -------- 3-D figure: all faces in one collection so depth sorting is global
    elev, azim = args.view
    light = light_direction(elev, azim)
    faces, colors = [], []
    for _, SX, SY, SZ, col in surfaces:
        q = quads(SX, SY, SZ)
        faces.append(q)
        colors.append(shade(q, np.array(matplotlib.colors.to_rgb(col)), light))
    faces = np.concatenate(faces)
    colors = np.concatenate(colors)
    if len(faces) == 0:
        raise PlotError("nothing finite to plot")

    fig = plt.figure(figsize=(8, 7))
    ax = fig.add_subplot(projection="3d")
    coll = Poly3DCollection(faces, facecolors=colors, edgecolors=colors, linewidths=0.15)
    ax.add_collection3d(coll)

    # Trimlines (blend boundaries) as thin dark curves.
    trim_lines = [np.stack([X[0], Y[0], Z[0]], axis=-1), np.stack([X[-1], Y[-1], Z[-1]], axis=-1)]
    ax.add_collection3d(Line3DCollection(trim_lines, colors=EDGE_COLOR, linewidths=0.9))

    pts = faces.reshape(-1, 3)
    mins, maxs = pts.min(axis=0), pts.max(axis=0)
    span = maxs - mins
    big = float(span.max()) if span.max() > 0 else 1.0
    span = np.maximum(span, 1e-3 * big)
    mid = 0.5 * (mins + maxs)
    pad = 0.02 * span
    lo3, hi3 = mid - 0.5 * span - pad, mid + 0.5 * span + pad
    ax.set_xlim(lo3[0], hi3[0])
    ax.set_ylim(lo3[1], hi3[1])
    ax.set_zlim(lo3[2], hi3[2])
    ax.set_box_aspect(tuple(hi3 - lo3))
    ax.view_init(elev=elev, azim=azim)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.tick_params(labelsize=8)
    title = args.title if args.title is not None else (spec.get("name") or Path(args.spec).stem)
    ax.set_title(title)
    fig.text(0.5, 0.02, f"t = {t:g},  grid {n} x {n},  strip length {args.strip:g}",
             ha="center", fontsize=8, color="#555555")
    ax.legend(handles=legend, loc="upper left", fontsize=8, framealpha=0.8)
    atomic_savefig(fig, args.output, dpi=110)
    plt.close(fig)

    # -------- optional cross-section profile
    if args.profile:
        v_range = spec.get("v_range") or [float(vgrid[0]), float(vgrid[-1])]
        v0 = args.v0 if args.v0 is not None else float(v_range[0])
        m = max(201, n)
        us = np.linspace(0.0, 1.0, m)
        pts_text = "".join(f"{u!r} {v0!r}\n" for u in us)
        pargs = ["eval", args.spec, "--points", "-"]
        if args.t is not None:
            pargs += ["--t", repr(float(args.t))]
        pd = parse_csv(run_cli(args.c2blend, pargs, stdin_text=pts_text), m)
        r = np.hypot(pd[:, 2], pd[:, 3])
        z = pd[:, 4]
        fig2, ax2 = plt.subplots(figsize=(7, 6))
        ax2.plot(r, z, color=BLEND_COLOR, lw=2, label="blend, u in [0, 1]")
        ax2.plot([r[0]], [z[0]], "o", color=PRIMARY_COLORS[0], label="u = 0")
        ax2.plot([r[-1]], [z[-1]], "s", color=PRIMARY_COLORS[1], label="u = 1")
        ax2.set_xlabel("r = sqrt(x^2 + y^2)")
        ax2.set_ylabel("z")
        ax2.set_aspect("equal", adjustable="datalim")
        ax2.grid(True, alpha=0.3)
        ax2.set_title(f"{title}: profile at v = {v0:g}, t = {t:g}")
        ax2.legend(fontsize=8)
        atomic_savefig(fig2, args.profile, dpi=110)
        plt.close(fig2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
