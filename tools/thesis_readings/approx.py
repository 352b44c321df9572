#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Independent re-implementation of thesis sec. 3.4.1 (eq. 120-125) for the eqs. 127-129
example (t=0.1) and eqs. 87-88 (t=0.2), with alternative readings. numpy only."""
import numpy as np
from numpy.polynomial import polynomial as P
PI = np.pi

# quintic Hermite basis eq. 107, coefficients low->high
G = [np.array(c, float) for c in (
    [1, 0, 0, -10, 15, -6], [0, 1, 0, -6, 8, -3], [0, 0, .5, -1.5, 1.5, -.5],
    [0, 0, 0, 10, -15, 6], [0, 0, 0, -4, 7, -3], [0, 0, 0, .5, -1, .5])]

def pder(c, k, u):
    u = np.asarray(u, float)
    return P.polyval(u, P.polyder(c, k)) if k < len(c) else 0 * u

def hermite_check():
    for l in range(6):
        for s, u in enumerate((0.0, 1.0)):
            for k in range(3):
                v = pder(G[l], k, np.array(u))
                assert abs(v - (1.0 if l == 3 * s + k else 0.0)) < 1e-12
hermite_check()

def sin_d(w, k, u):  # d^k/du^k sin(w u)
    return w ** k * np.sin(w * u + k * PI / 2)

def phi(m, k, u):  # eq. 120 correction: m pi f_m - sin(m pi u), f_m = g2 + (-1)^m g5
    w = m * PI
    return w * (pder(G[1], k, u) + (-1) ** m * pder(G[4], k, u)) - sin_d(w, k, u)

def Lop(fun, u, beta, shape=(1, 1, 1, 1)):
    """L[H f] / f for f'' = beta f: gamma H6 + eta beta H4 + lambda beta^2 H2 + rho beta^3 H"""
    ga, et, la, rh = shape
    return ga * fun(6, u) + et * beta * fun(4, u) + la * beta ** 2 * fun(2, u) + rh * beta ** 3 * fun(0, u)

def exact_H(bc, beta, shape=(1, 1, 1, 1)):
    """closed form of ga H6 + et b H4 + la b^2 H2 + rh b^3 H = 0 with bc = [H(0),H'(0),H''(0),H(1),H'(1),H''(1)]"""
    ga, et, la, rh = shape
    s = np.roots([ga, et * beta, la * beta ** 2, rh * beta ** 3])  # s = r^2
    r = np.concatenate([np.sqrt(s.astype(complex)), -np.sqrt(s.astype(complex))])
    # basis exp(r (u - u_ref)) with u_ref chosen to avoid overflow: use exp(r u) for Re r<=0, exp(r(u-1)) else
    ref = np.where(r.real > 0, 1.0, 0.0)
    A = np.zeros((6, 6), complex)
    for j, (rr, u0) in enumerate(zip(r, ref)):
        for s_, uu in enumerate((0.0, 1.0)):
            for k in range(3):
                A[3 * s_ + k, j] = rr ** k * np.exp(rr * (uu - u0))
    coef = np.linalg.solve(A, np.asarray(bc, complex))
    def H(k, u):
        u = np.asarray(u, float)
        out = np.zeros(u.shape, complex)
        for c, rr, u0 in zip(coef, r, ref):
            out += c * rr ** k * np.exp(rr * (u - u0))
        return out.real
    return H

def approx_H(bc, beta, M, ui, mode="lsq", shape=(1, 1, 1, 1), weights=None, rho_typo=False,
             basis="thesis"):
    """H = sum bc_l g_l - sum c_m phi_m, c from least squares of the ODE residual at ui."""
    g = lambda k, u: sum(b * pder(G[l], k, u) for l, b in enumerate(bc))
    if basis == "thesis":
        ph = lambda m, k, u: phi(m, k, u)
    elif basis == "sin":   # plain sin(m pi u) (violates first-derivative BCs; for reference)
        ph = lambda m, k, u: -sin_d(m * PI, k, u)
    def Lph(m, u):
        f = lambda k, uu: ph(m, k, uu)
        if rho_typo:  # eq. 123 as printed: rho term multiplies f^(2) (=beta f) instead of f^(6)
            ga, et, la, rh = shape
            return ga * f(6, u) + et * beta * f(4, u) + la * beta ** 2 * f(2, u) + rh * beta * f(0, u)
        return Lop(f, u, beta, shape)
    rhs = Lop(g, ui, beta, shape)
    A = np.stack([Lph(m, ui) for m in range(1, M + 1)], axis=1)
    if mode == "lsq":
        w = np.ones_like(ui) if weights is None else weights
        Aw, bw = A * w[:, None], rhs * w
        sc = np.linalg.norm(Aw, axis=0)
        c = np.linalg.lstsq(Aw / sc, bw, rcond=None)[0] / sc
    elif mode == "normal":  # eq. 125 literally: normal equations, no scaling
        c = np.linalg.solve(A.T @ A, A.T @ rhs)
    elif mode == "galerkin":  # int L(H) phi_k du = 0 (trapezoid on ui)
        w = np.full_like(ui, ui[1] - ui[0]); w[0] *= .5; w[-1] *= .5
        T = np.stack([ph(k, 0, ui) for k in range(1, M + 1)], axis=1)
        c = np.linalg.solve(T.T @ (A * w[:, None]), T.T @ (rhs * w))
    def H(k, u):
        return g(k, u) - sum(c[m - 1] * ph(m, k, u) for m in range(1, M + 1))
    return H, c

def example(which):
    if which == "127":
        # eq. 127's x and y data (its z data, h1 to h3 = 2, 6, 20, are not needed here)
        a, b, c, d, t = 3.6, 5.5, 6.0, 3.0, 0.1
        u0, u1 = 0.4, 0.55
        bx = [a * u0 * np.exp(t), -a * np.exp(t), 0, c * u1 * np.exp(-t), c * np.exp(-t), 0]
        by = [b * u0 * np.exp(-t), -b * np.exp(-t), 0, d * u1 * np.exp(t), d * np.exp(t), 0]
    else:  # eqs. 87-88, t = 0.2
        a, b, c, d, t = 1.6, 1.0, 0.8, 0.6, 0.2
        bx = [a * np.exp(t), 0, 0, c * np.exp(-t), 0, 0]
        by = [b * np.exp(-t), 0, 0, d * np.exp(t), 0, 0]
    return bx, by

def errors(Hx, Hy, Ex, Ey, n=101, Dfrom="exact"):
    u = np.linspace(0, 1, n); v = np.linspace(0, 1, n)
    S, C = np.sin(2 * PI * v), np.cos(2 * PI * v)
    ex, ey = Hx(0, u) - Ex(0, u), Hy(0, u) - Ey(0, u)
    d = np.sqrt((ex[:, None] * S[None, :]) ** 2 + (ey[:, None] * C[None, :]) ** 2)
    X, Y = Ex(0, u), Ey(0, u)
    # largest chord of the ellipse (X sin, Y cos) at fixed u = 2 max(|X|,|Y|); z is constant in v
    D = np.max(2 * np.maximum(np.abs(X), np.abs(Y)))
    return d.max(), d.mean(), d.max() / D, d.mean() / D, D

if __name__ == "__main__":
    beta = -4 * PI ** 2
    for which in ("127", "87"):
        bx, by = example(which)
        Ex, Ey = exact_H(bx, beta), exact_H(by, beta)
        # sanity: exact satisfies BCs and ODE
        uu = np.linspace(0, 1, 7)
        assert np.max(np.abs(Lop(Ex, uu, beta))) < 1e-6 * np.max(np.abs(beta ** 3 * Ex(0, uu)))
        ui = np.linspace(0, 1, 101)
        for M in (10, 15, 20):
            Hx, _ = approx_H(bx, beta, M, ui); Hy, _ = approx_H(by, beta, M, ui)
            print(which, M, "E1-E4 = %.3g %.3g %.3g %.3g  D=%.4f" % errors(Hx, Hy, Ex, Ey))
