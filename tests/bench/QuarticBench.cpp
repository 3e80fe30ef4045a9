// Speed and accuracy of smallestRootInInterval on quartics built from known roots.
//
// Each quartic is the product of its roots computed in binary128 and rounded to double. The rounded
// polynomial no longer has exactly those roots, so the reference is recomputed for the coefficients
// the solver actually sees: binary128 Newton iteration from each constructed root. The sets keep
// complex pairs away from the real axis and real roots apart (by at least 1e-6 relative), so that
// rounding the coefficients can neither create nor merge real roots and each Newton run converges to
// the root it started next to.

#include "QuarticBench.h"

#include "Quartic.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace cuelab::bench {

namespace {

__extension__ typedef __float128 Quad;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The timing loop's results end up here, so the compiler cannot drop the calls.
volatile double observed = 0.0;

struct Case {
    Quartic c{};
    double smallestPositive = kInfinity;  // reference smallest root > 0 of c (as rounded), s
};

// Coefficients highest degree first, in binary128.
using QuadPoly = std::array<Quad, 5>;

QuadPoly quadPoly(const Quartic& c)
{
    QuadPoly q{};
    for (int i = 0; i < 5; ++i) q[i] = c[i];
    return q;
}

// Multiply p (degree < 4) by (t - r).
void multiplyByRoot(QuadPoly& p, Quad r)
{
    for (int i = 0; i < 4; ++i) p[i] = p[i + 1];
    p[4] = 0;
    for (int i = 4; i > 0; --i) p[i] -= r * p[i - 1];
}

// Newton in binary128 on the double coefficients, from a starting point next to a simple root.
Quad polish(const QuadPoly& p, Quad x)
{
    for (int iteration = 0; iteration < 100; ++iteration) {
        Quad f = p[0];
        Quad df = 0;
        for (int i = 1; i < 5; ++i) {
            df = df * x + f;
            f = f * x + p[i];
        }
        if (df == 0) break;
        const Quad step = f / df;
        x -= step;
        if (step == 0 || (step < 0 ? -step : step) <= Quad(1e-32) * (x < 0 ? -x : x)) break;
    }
    return x;
}

// realRoots: the real roots; pairs: (alpha, beta) of complex pairs alpha +- i beta; scale: leading
// coefficient. Exactly four roots in all.
Case buildCase(const std::vector<Quad>& realRoots, const std::vector<std::array<double, 2>>& pairs,
               double scale)
{
    QuadPoly p{};
    p[4] = scale;
    for (const Quad r : realRoots) multiplyByRoot(p, r);
    for (const auto& pair : pairs) {
        // (t - alpha)^2 + beta^2 = t^2 + b t + c, the real quadratic of the conjugate pair.
        const Quad alpha = pair[0];
        const Quad beta = pair[1];
        const Quad b = -2 * alpha;
        const Quad c = alpha * alpha + beta * beta;
        // p has degree <= 2 here (real roots come first, at most two pairs) and sits in p[2..4].
        QuadPoly next{};
        const Quad p2 = p[2];
        const Quad p3 = p[3];
        const Quad p4 = p[4];
        next[0] = p2;
        next[1] = p3 + b * p2;
        next[2] = p4 + b * p3 + c * p2;
        next[3] = b * p4 + c * p3;
        next[4] = c * p4;
        p = next;
    }
    Case k;
    for (int i = 0; i < 5; ++i) k.c[i] = static_cast<double>(p[i]);
    const QuadPoly rounded = quadPoly(k.c);
    for (const Quad r : realRoots) {
        const double root = static_cast<double>(polish(rounded, r));
        if (root > 0.0) k.smallestPositive = std::min(k.smallestPositive, root);
    }
    return k;
}

// Random roots in [-1, 3]: two, one or no complex pairs, real roots at least 0.05 apart, imaginary
// parts at least 0.1, and a leading coefficient of either sign between 0.1 and 10.
std::vector<Case> randomSet(int count)
{
    std::mt19937_64 random(20260101);
    std::uniform_real_distribution<double> position(-1.0, 3.0);
    std::uniform_real_distribution<double> imaginary(0.1, 1.0);
    std::uniform_real_distribution<double> logScale(-1.0, 1.0);
    std::vector<Case> cases;
    while (static_cast<int>(cases.size()) < count) {
        const int pairCount = static_cast<int>(random() % 3);
        std::vector<Quad> roots;
        while (static_cast<int>(roots.size()) < 4 - 2 * pairCount) {
            const double r = position(random);
            bool apart = true;
            for (const Quad s : roots) apart = apart && std::abs(r - static_cast<double>(s)) >= 0.05;
            if (apart) roots.push_back(r);
        }
        std::vector<std::array<double, 2>> pairs;
        for (int i = 0; i < pairCount; ++i) pairs.push_back({position(random), imaginary(random)});
        const double sign = (random() % 2 == 0) ? 1.0 : -1.0;
        cases.push_back(buildCase(roots, pairs, sign * std::pow(10.0, logScale(random))));
    }
    return cases;
}

// Hard cases, alternating: a positive near-double pair r, r (1 + delta) with delta from 1e-6 to 1e-3,
// the smallest positive roots; and a leading coefficient from 1e-6 to 1e-18 (a cubic with a fourth
// root at 1e6 to 1e18 of either sign, p = (1 - t / R) cubic).
std::vector<Case> hardSet(int count)
{
    std::mt19937_64 random(20260202);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Case> cases;
    for (int i = 0; i < count; ++i) {
        if (i % 2 == 0) {
            const double r = 0.1 + 2.9 * unit(random);
            const double delta = std::pow(10.0, -6.0 + 3.0 * unit(random));
            const Quad second = Quad(r) * (1 + Quad(delta));
            std::vector<Quad> roots{r, second};
            std::vector<std::array<double, 2>> pairs;
            if (random() % 2 == 0)
                pairs.push_back({-1.0 + 5.0 * unit(random), 0.1 + unit(random)});
            else
                roots.insert(roots.end(), {-0.5 - unit(random), r + 0.1 + 2.0 * unit(random)});
            cases.push_back(buildCase(roots, pairs, (random() % 2 == 0) ? 1.0 : -2.5));
        } else {
            const double far = ((random() % 2 == 0) ? 1.0 : -1.0) * std::pow(10.0, 6.0 + 12.0 * unit(random));
            std::vector<Quad> roots{Quad(far)};
            std::vector<std::array<double, 2>> pairs;
            roots.push_back(-1.0 + 4.0 * unit(random));
            if (random() % 2 == 0) {
                pairs.push_back({-1.0 + 4.0 * unit(random), 0.1 + unit(random)});
            } else {
                const double a = -1.0 + 4.0 * unit(random);
                const double b = -1.0 + 4.0 * unit(random);
                if (std::abs(a - b) < 0.05 || std::abs(a - static_cast<double>(roots[1])) < 0.05 ||
                    std::abs(b - static_cast<double>(roots[1])) < 0.05) {
                    --i;  // too close for the reference's Newton runs to be told apart; draw again
                    continue;
                }
                roots.insert(roots.end(), {a, b});
            }
            cases.push_back(buildCase(roots, pairs, -1.0 / far));
        }
    }
    return cases;
}

double relativeError(double x, double reference)
{
    if (x == reference) return 0.0;  // also both +infinity: no positive root, none reported
    if (std::isinf(x) || std::isinf(reference)) return kInfinity;  // a missed or invented root
    return std::abs(x - reference) / std::abs(reference);
}

double worstError(const std::vector<Case>& cases)
{
    double worst = 0.0;
    for (const Case& k : cases)
        worst = std::max(worst, relativeError(smallestRootInInterval(k.c, 0.0, kInfinity),
                                              k.smallestPositive));
    return worst;
}

}  // namespace

QuarticFigures runQuarticBench()
{
    const std::vector<Case> random = randomSet(4096);
    const std::vector<Case> hard = hardSet(4096);
    QuarticFigures figures;
    figures.maxRelErrorRandom = worstError(random);
    figures.maxRelErrorHard = worstError(hard);

    // Timing: one batch solves the whole random set; the sum keeps the calls from being optimised
    // away. The median of many batches ignores the ones a busy machine interrupted.
    constexpr int kBatches = 101;
    std::vector<double> nsPerSolve;
    double sink = 0.0;
    for (int batch = 0; batch < kBatches; ++batch) {
        const auto start = std::chrono::steady_clock::now();
        for (const Case& k : random) {
            const double t = smallestRootInInterval(k.c, 0.0, kInfinity);
            sink += std::isinf(t) ? 1.0 : t;
        }
        const auto stop = std::chrono::steady_clock::now();
        const double ns = std::chrono::duration<double, std::nano>(stop - start).count();
        nsPerSolve.push_back(ns / static_cast<double>(random.size()));
    }
    std::nth_element(nsPerSolve.begin(), nsPerSolve.begin() + kBatches / 2, nsPerSolve.end());
    figures.nsMedian = nsPerSolve[kBatches / 2];
    observed = sink;
    return figures;
}

}  // namespace cuelab::bench
