#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Large-M behaviour of the literal reading, float32 normal equations, and the mechanism."""
from readings import *
bx, by = example("127")
Ex, Ey = exact_H(bx, beta0), exact_H(by, beta0)
u2k = np.linspace(0, 1, 2001)
print("baseline lsq, I = 2000, large M:")
for M in (10, 20, 40, 80):
    e = errors(solve(bx, beta0, M, u2k), solve(by, beta0, M, u2k), Ex, Ey)
    print("  M = %3d  E1 %.3g  E4 %.3g" % (M, e[0], e[3]))

def solve_f32(bc, M, ui):
    T = bases("thesis", M)
    g = lambda k, u: sum(b * pder(G[l], k, u) for l, b in enumerate(bc))
    L = lambda f, u: f(6, u) + beta0 * f(4, u) + beta0 ** 2 * f(2, u) + beta0 ** 3 * f(0, u)
    A = np.stack([L(t, ui) for t in T], axis=1).astype(np.float32); r = L(g, ui).astype(np.float32)
    c = np.linalg.solve(A.T @ A, A.T @ r).astype(float)
    return lambda k, u: g(k, u) - sum(ci * t(k, u) for ci, t in zip(c, T))
u101 = np.linspace(0, 1, 101)
res = [errors(solve_f32(bx, M, u101), solve_f32(by, M, u101), Ex, Ey) for M in (10, 15, 20)]
print("R15 float32 normal equations: " + " | ".join("E1 %.3g E4 %.3g" % (r[0], r[3]) for r in res))

# mechanism: 4th derivative at the ends. Every trial function g_l - sum c_m phi_m has
# H''''(0) = sum_l a_l g_l''''(0) - sum_m c_m m pi f_m''''(0) with f_m'''' = g2'''' + (-1)^m g5''''
# i.e. H''''(0), H''''(1) are tied to the same c's that fix nothing else at the ends; the exact H's are not.
for M in (10, 20):
    Hb = solve(bx, beta0, M, np.linspace(0, 1, 1001), method="bestfit")
    Hl = solve(bx, beta0, M, u101)
    for nm, H in (("bestfit", Hb), ("lsq", Hl)):
        Lr = lambda u: H(6, u) + beta0 * H(4, u) + beta0 ** 2 * H(2, u) + beta0 ** 3 * H(0, u)
        print("  x, M=%d %-8s H''''(0)=%10.4g H''''(1)=%10.4g  rms residual(101 pts)=%.3g  max|H-Hexact|=%.3g"
              % (M, nm, H(4, np.array(0.)), H(4, np.array(1.)), np.sqrt(np.mean(Lr(u101) ** 2)),
                 np.max(np.abs(H(0, u101) - Ex(0, u101)))))
print("  exact   H''''(0)=%10.4g H''''(1)=%10.4g" % (Ex(4, np.array(0.)), Ex(4, np.array(1.))))
