// NURBS evaluation with second derivatives: C2Blend (c2b_nurbs_surface_eval, order 2)
// against OpenCASCADE's Geom_BSplineSurface::D2 on the same surfaces and parameters, in
// one run. Prints medians of repeated runs and the ratio; asserts nothing about time.
// It also checks that both evaluators agree, so the comparison is of equal work.
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "c2b_nurbs.h"

namespace {

struct Case {
    const char *name;
    int p, q, nu, nv, inner_u, inner_v;
    bool rational;
};

// Clamped knot vector with `inner` uniform interior knots, as full and as (knots, mults).
std::vector<double> full_knots(int p, int inner)
{
    std::vector<double> k(p + 1, 0.0);
    for (int i = 1; i <= inner; i++)
        k.push_back(double(i) / (inner + 1));
    for (int i = 0; i <= p; i++)
        k.push_back(1.0);
    return k;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> x)
{
    std::sort(x.begin(), x.end());
    return x[x.size() / 2];
}

void run(const Case &c)
{
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> U(0.0, 1.0), W(0.5, 2.0);
    int nu = c.p + 1 + c.inner_u, nv = c.q + 1 + c.inner_v;
    std::vector<double> poles(size_t(nu) * nv * 4);
    TColgp_Array2OfPnt P(1, nu, 1, nv);
    TColStd_Array2OfReal Wt(1, nu, 1, nv);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double x = i + 0.3 * U(rng), y = j + 0.3 * U(rng), z = U(rng), w = c.rational ? W(rng) : 1.0;
            double *q = &poles[(size_t(i) * nv + j) * 4];
            q[0] = x, q[1] = y, q[2] = z, q[3] = w;
            P.SetValue(i + 1, j + 1, gp_Pnt(x, y, z));
            Wt.SetValue(i + 1, j + 1, w);
        }
    std::vector<double> ku = full_knots(c.p, c.inner_u), kv = full_knots(c.q, c.inner_v);
    c2b_nurbs_surface *s = nullptr;
    c2b_error err;
    if (c2b_nurbs_surface_create(c.p, c.q, nu, nv, ku.data(), kv.data(), poles.data(), nullptr, &s, &err)) {
        std::fprintf(stderr, "bench: %s\n", err.msg);
        return;
    }
    TColStd_Array1OfReal UK(1, c.inner_u + 2), VK(1, c.inner_v + 2);
    TColStd_Array1OfInteger UM(1, c.inner_u + 2), VM(1, c.inner_v + 2);
    for (int i = 0; i < c.inner_u + 2; i++) {
        UK.SetValue(i + 1, double(i) / (c.inner_u + 1));
        UM.SetValue(i + 1, (i == 0 || i == c.inner_u + 1) ? c.p + 1 : 1);
    }
    for (int i = 0; i < c.inner_v + 2; i++) {
        VK.SetValue(i + 1, double(i) / (c.inner_v + 1));
        VM.SetValue(i + 1, (i == 0 || i == c.inner_v + 1) ? c.q + 1 : 1);
    }
    Handle(Geom_BSplineSurface) occ =
        c.rational ? new Geom_BSplineSurface(P, Wt, UK, VK, UM, VM, c.p, c.q)
                   : new Geom_BSplineSurface(P, UK, VK, UM, VM, c.p, c.q);
    const int N = 20000;
    std::vector<double> us(N), vs(N);
    for (int i = 0; i < N; i++)
        us[i] = U(rng), vs[i] = U(rng);
    // Agreement (same work): S, Su, Sv, Suu, Suv, Svv.
    double worst = 0, scale = 0;
    for (int i = 0; i < 500; i++) {
        double o[18];
        c2b_nurbs_surface_eval(s, us[i], vs[i], 2, o, nullptr);
        gp_Pnt p;
        gp_Vec du, dv, duu, dvv, duv;
        occ->D2(us[i], vs[i], p, du, dv, duu, dvv, duv);
        const double ref[18] = {p.X(), p.Y(), p.Z(), du.X(), du.Y(), du.Z(), dv.X(), dv.Y(), dv.Z(),
                                duu.X(), duu.Y(), duu.Z(), duv.X(), duv.Y(), duv.Z(), dvv.X(), dvv.Y(), dvv.Z()};
        for (int k = 0; k < 18; k++) {
            worst = std::max(worst, std::fabs(o[k] - ref[k]));
            scale = std::max(scale, std::fabs(ref[k]));
        }
    }
    std::vector<double> ours, theirs;
    double sink = 0;
    for (int r = 0; r < 15; r++) {
        auto t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < N; i++) {
            double o[18];
            c2b_nurbs_surface_eval(s, us[i], vs[i], 2, o, nullptr);
            sink += o[9];
        }
        ours.push_back(seconds_since(t0) / N);
        t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < N; i++) {
            gp_Pnt p;
            gp_Vec du, dv, duu, dvv, duv;
            occ->D2(us[i], vs[i], p, du, dv, duu, dvv, duv);
            sink += duu.X();
        }
        theirs.push_back(seconds_since(t0) / N);
    }
    double a = median(ours), b = median(theirs);
    std::printf("| %s (%dx%d poles, degree %d x %d) | %.0f ns | %.0f ns | %.2f | %.1e |\n", c.name, nu, nv,
                c.p, c.q, 1e9 * a, 1e9 * b, b / a, worst / scale);
    if (sink == 42.0)
        std::printf(" ");
    c2b_nurbs_surface_destroy(s);
}

} // namespace

int main()
{
    std::printf("NURBS surface evaluation with second derivatives (S, Su, Sv, Suu, Suv, Svv),\n"
                "20000 random parameters, medians of 15 runs, one core.\n\n");
    std::printf("| surface | C2Blend | OCCT D2 | OCCT / C2Blend | max difference (relative) |\n");
    std::printf("|---|---|---|---|---|\n");
    const Case cases[] = {
        {"rational bicubic", 3, 3, 0, 0, 16, 16, true},
        {"non-rational bicubic", 3, 3, 0, 0, 16, 16, false},
        {"non-rational quintic (fit-like)", 5, 5, 0, 0, 13, 26, false},
        {"rational biquadratic", 2, 2, 0, 0, 8, 8, true},
    };
    for (const Case &c : cases)
        run(c);
    return 0;
}
