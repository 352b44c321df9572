#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Alternative readings of thesis eqs. 120-125 on the eqs. 127-129 example (t = 0.1) and
eqs. 87-88 (t = 0.2). Errors E1-E4 (sec. 3.3.2.1) on 101 x 101 vertices vs the closed form."""
import numpy as np, sys
from approx import *

beta0 = -4 * PI ** 2

def herm_corr(psi):
    """psi(k,u) -> trial column T(k,u) = Hermite(psi) - psi (vanishes with T',T'' at 0,1)."""
    vals = [psi(k, np.array(s)) for s in (0.0, 1.0) for k in range(3)]
    return lambda k, u: sum(vals[l] * pder(G[l], k, u) for l in range(6)) - psi(k, u)

def bases(name, M):
    if name == "thesis":      # m pi f_m - sin(m pi u), eq. 120
        return [lambda k, u, m=m: phi(m, k, u) for m in range(1, M + 1)]
    if name == "sin(m u)":    # no pi, Hermite-corrected
        return [herm_corr(lambda k, u, m=m: sin_d(m, k, u)) for m in range(1, M + 1)]
    if name == "sin(2m pi u)":
        return [herm_corr(lambda k, u, m=m: sin_d(2 * m * PI, k, u)) for m in range(1, M + 1)]
    if name == "sin(m pi u/2)":
        return [herm_corr(lambda k, u, m=m: sin_d(m * PI / 2, k, u)) for m in range(1, M + 1)]
    if name == "poly u^3(1-u)^3 u^m":  # polynomial bubble basis, Chebyshev-like in the bubble
        out = []
        for m in range(M):
            c = P.polymul(P.polymul(P.polypow([0, 1], 3), P.polypow([1, -1], 3)), [0] * m + [1])
            out.append(lambda k, u, c=c: pder(c, k, u))
        return out
    raise ValueError(name)

def solve(bc, beta, M, ui, basis="thesis", method="lsq", w=None, shape=(1, 1, 1, 1), rho_typo=False):
    T = bases(basis, M)
    g = lambda k, u: sum(b * pder(G[l], k, u) for l, b in enumerate(bc))
    ga, et, la, rh = shape
    rb = beta if rho_typo else beta ** 3
    L = lambda f, u: ga * f(6, u) + et * beta * f(4, u) + la * beta ** 2 * f(2, u) + rh * rb * f(0, u)
    A = np.stack([L(t, ui) for t in T], axis=1)
    r = L(g, ui)
    if method == "lsq":
        ww = np.ones_like(ui) if w is None else w
        Aw = A * ww[:, None]
        sc = np.linalg.norm(Aw, axis=0)
        c = np.linalg.lstsq(Aw / sc, r * ww, rcond=None)[0] / sc
    elif method == "normal":
        c = np.linalg.solve(A.T @ A, A.T @ r)
    elif method.startswith("galerkin"):
        q = np.full_like(ui, ui[1] - ui[0]); q[0] *= .5; q[-1] *= .5
        if method == "galerkin":   # test functions = trial functions
            V = np.stack([t(0, ui) for t in T], axis=1)
        else:                      # test functions sin(k pi u)
            V = np.stack([np.sin(k * PI * ui) for k in range(1, M + 1)], axis=1)
        c = np.linalg.lstsq(V.T @ (A * q[:, None]), V.T @ (r * q), rcond=None)[0]
    elif method == "bestfit":      # not a PDE method: L2 fit of the exact H (ceiling of the space)
        E = exact_H(bc, beta, shape)
        B = np.stack([t(0, ui) for t in T], axis=1)
        c = np.linalg.lstsq(B, g(0, ui) - E(0, ui), rcond=None)[0]
    H = lambda k, u: g(k, u) - sum(ci * t(k, u) for ci, t in zip(c, T))
    return H

def run(label, which="127", Ms=(10, 15, 20), beta=beta0, ref=None, **kw):
    bx, by = example(which)
    shape = kw.get("shape", (1, 1, 1, 1))
    Ex, Ey = (exact_H(bx, beta, shape), exact_H(by, beta, shape)) if ref is None else ref
    res = []
    ui = kw.get("ui", np.linspace(0, 1, 101))
    k2 = {k: v for k, v in kw.items() if k != "ui"}
    for M in Ms:
        Hx = solve(bx, beta, M, ui, **k2); Hy = solve(by, beta, M, ui, **k2)
        res.append(errors(Hx, Hy, Ex, Ey))
    e4 = [r[3] for r in res]
    print("%-48s " % label + " | ".join("E1 %.3g E4 %.3g" % (r[0], r[3]) for r in res) +
          " | E4(10)/E4(20) %.3g" % (e4[0] / e4[-1]))
    sys.stdout.flush()
    return res

if __name__ == "__main__":
    u101 = np.linspace(0, 1, 101)
    print("eqs. 127-129, t = 0.1 (Table 3: E1 4.35e-2 3.17e-3 2.22e-5 ; E4 4.63e-3 3.34e-4 2.80e-6)")
    run("R0 baseline lsq, 101 u pts")
    run("R1 eq.123 rho typo (rho*beta instead of rho*beta^3)", rho_typo=True)
    run("R2 normal equations eq.125 (no scaling)", method="normal")
    for I in (10, 20, 50, 200, 1000):
        run("R3 lsq, I = %d" % I, ui=np.linspace(0, 1, I + 1))
    run("R4 lsq, interior points only (I=100)", ui=u101[1:-1])
    run("R5 Galerkin (test = trial functions)", method="galerkin", ui=np.linspace(0, 1, 2001))
    run("R6 Petrov-Galerkin (test = sin k pi u)", method="galerkin-sin", ui=np.linspace(0, 1, 2001))
    for p in (1, 2, 3, 6):
        ww = (u101 * (1 - u101)) ** p
        run("R7 lsq, row weight (u(1-u))^%d" % p, w=ww)
    run("R8 best L2 fit of exact H (ceiling, not a PDE method)", method="bestfit", ui=np.linspace(0, 1, 1001))
    for b in ("sin(m u)", "sin(2m pi u)", "sin(m pi u/2)", "poly u^3(1-u)^3 u^m"):
        run("R9 basis %s, lsq" % b, basis=b)
    run("R9 basis poly, bestfit", basis="poly u^3(1-u)^3 u^m", method="bestfit", ui=np.linspace(0, 1, 1001))
    # v scaled: data written sin(v) on [0, 2 pi] -> beta = -1 (reference = matching closed form)
    run("R10 beta = -1 (v in [0,2pi], sin v)", beta=-1.0)
    L = 0.15
    run("R10 beta = -4pi^2 L^2, L = u1-u0 = 0.15", beta=beta0 * L * L)
    # reference = the same method at large M (self-convergence)
    bx, by = example("127")
    for Mref in (30, 40):
        ref = (solve(bx, beta0, Mref, u101), solve(by, beta0, Mref, u101))
        run("R11 ref = thesis-approx at M = %d" % Mref, ref=ref)
    print("\neqs. 87-88, t = 0.2 (Table 1: E1 4.55e-2 4.85e-3 6.40e-5 ; E4 7.95e-3 7.65e-4 8.31e-6)")
    run("R0 baseline", which="87")
    run("R5 Galerkin", which="87", method="galerkin", ui=np.linspace(0, 1, 2001))
    run("R8 bestfit", which="87", method="bestfit", ui=np.linspace(0, 1, 1001))
    run("R9 sin(m u) lsq", which="87", basis="sin(m u)")
    run("R10 beta=-1", which="87", beta=-1.0)
