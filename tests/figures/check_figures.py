#!/usr/bin/python3
"""ctest `figures_papers` (label figures): tools/plot_papers.py renders every paper figure
into a temporary directory; each expected PNG must exist, be the only output, not be blank,
and be listed in docs/FIGURES.md.

Not blank: the grey-level variance is above VAR_MIN and at least COLOUR_MIN of the pixels
are coloured (surfaces and curves; titles and axes alone are black on white).

usage: check_figures.py PLOT_PAPERS C2BLEND_CLI MODULE_DIR [FIGURES_MD]
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402

EXPECTED = ["thesis_fig09.png", "thesis_fig15.png", "seed001_fig1.png", "seed001_fig1_error.png",
            "seed000_fig2.png", "seed000_fig3.png", "seed000_fig4.png", "seed000_fig5.png",
            "seed000_fig6.png"]
VAR_MIN = 1e-3
COLOUR_MIN = 0.02


def check_png(path):
    """Problems with one PNG (empty list when it is fine)."""
    if not os.path.isfile(path):
        return ["missing"]
    img = mpimg.imread(path)
    if img.ndim != 3 or img.shape[2] < 3 or min(img.shape[:2]) < 200:
        return ["unexpected image shape %s" % (img.shape,)]
    rgb = img[:, :, :3].astype(float)
    if rgb.max() > 1.0:
        rgb /= 255.0
    problems = []
    var = float(np.var(rgb.mean(axis=2)))
    if var <= VAR_MIN:
        problems.append("blank: grey-level variance %.2e <= %.0e" % (var, VAR_MIN))
    coloured = float(np.mean(rgb.max(axis=2) - rgb.min(axis=2) > 0.15))
    if coloured < COLOUR_MIN:
        problems.append("blank plots: only %.1f%% coloured pixels (< %.0f%%)" % (100 * coloured, 100 * COLOUR_MIN))
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("plot_papers")
    ap.add_argument("c2blend")
    ap.add_argument("module_dir")
    ap.add_argument("figures_md", nargs="?", default=None)
    a = ap.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as out:
        t0 = time.time()
        r = subprocess.run([sys.executable, a.plot_papers, "-o", out, "--c2blend", a.c2blend,
                            "--module-dir", a.module_dir], capture_output=True, text=True)
        sys.stdout.write(r.stdout)
        if r.returncode:
            sys.stderr.write(r.stderr)
            print("FAIL: plot_papers.py exited with %d" % r.returncode)
            return 1
        print("plot_papers.py took %.1f s" % (time.time() - t0))
        produced = sorted(f for f in os.listdir(out))
        extra = sorted(set(produced) - set(EXPECTED))
        if extra:
            failures.append("unexpected output (add it to EXPECTED and docs/FIGURES.md): %s" % ", ".join(extra))
        for name in EXPECTED:
            for p in check_png(os.path.join(out, name)):
                failures.append("%s: %s" % (name, p))
    if a.figures_md:
        with open(a.figures_md) as f:
            md = f.read()
        for name in EXPECTED:
            if "images/papers/" + name not in md:
                failures.append("%s is not linked from %s" % (name, a.figures_md))
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        print("OK: %d figures, none blank" % len(EXPECTED))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
