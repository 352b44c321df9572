#!/usr/bin/python3
"""Curvature profiles across the trimlines of one or more blends.

Runs `c2blend profile SPEC --with-primaries W --at V` for each spec and plots the normal
curvature across the trimline (the u direction) and along it (the v direction) against
u, through the strips of both primaries (u < 0 and u > 1), one panel per spec.
Principal curvatures are dashed. A curvature-continuous (G2) blend joins its primaries
without a jump at u = 0 and u = 1; a C1 blend jumps there.

usage: plot_profile.py SPEC [SPEC ...] -o OUT.png [--c2blend PATH] [--width 0.2] [--at V]
"""
import argparse
import csv
import io
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def profile(c2b, spec, width, at):
    args = [c2b, "profile", spec, "--with-primaries", str(width), "--at", str(at)]
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode:
        sys.stderr.write(r.stderr)
        sys.exit(r.returncode)
    return list(csv.DictReader(io.StringIO(r.stdout)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("specs", nargs="+")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--c2blend", default=os.path.join(HERE, "..", "build", "tools", "c2blend"))
    ap.add_argument("--width", type=float, default=0.2, help="primary strip width (default 0.2)")
    ap.add_argument("--at", type=float, default=None, help="v of the profile (default: v_range start)")
    a = ap.parse_args()
    fig, axes = plt.subplots(1, len(a.specs), figsize=(6.2 * len(a.specs), 4.8), squeeze=False)
    for ax, spec in zip(axes[0], a.specs):
        meta = json.load(open(spec))
        at = a.at if a.at is not None else meta.get("v_range", [0, 1])[0]
        rows = profile(a.c2blend, spec, a.width, at)
        for region, style in ((1, "#5b7aa0"), (0, "#e07b1a"), (2, "#6f9a6a")):
            rs = [r for r in rows if int(r["region"]) == region]
            u = [float(r["u"]) for r in rs]
            label = None if region else "%s"
            ax.plot(u, [float(r["k_across"]) for r in rs], "-", color=style, lw=2,
                    label=(label % "across the trimline (u direction)") if label else None)
            ax.plot(u, [float(r["k_along"]) for r in rs], ":", color=style, lw=2,
                    label=(label % "along the trimline (v direction)") if label else None)
            ax.plot(u, [float(r["k1"]) for r in rs], "--", color=style, lw=0.8, alpha=0.7,
                    label=(label % "principal k1, k2") if label else None)
            ax.plot(u, [float(r["k2"]) for r in rs], "--", color=style, lw=0.8, alpha=0.7)
        for x in (0.0, 1.0):
            ax.axvline(x, color="0.3", lw=0.8)
        ax.set_xlabel("u (blend in [0, 1]; primary 1 at u < 0, primary 2 at u > 1)")
        ax.set_ylabel("normal curvature (1 / model unit)")
        ax.set_title("%s (%s), v = %g" % (meta.get("name", os.path.basename(spec)),
                                          meta.get("continuity", "C2"), at))
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    tmp = "%s.tmp-%d.png" % (a.output, os.getpid())
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, a.output)


if __name__ == "__main__":
    main()
