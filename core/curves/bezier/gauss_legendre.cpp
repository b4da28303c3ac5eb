#include "core/curves/bezier/gauss_legendre.h"

#include <cmath>

namespace granota {

GaussLegendreRule gaussLegendreRule(int k)
{
    GaussLegendreRule rule;
    const long double pi = 3.141592653589793238462643383279502884L;
    for (int i = 0; i < k; ++i) {
        long double z = std::cos(pi * (i + 0.75L) / (k + 0.5L)), dp = 1;
        for (int it = 0; it < 100; ++it) {
            long double p0 = 1, p1 = z;
            for (int j = 2; j <= k; ++j) {
                const long double p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j;
                p0 = p1, p1 = p2;
            }
            dp = k * (z * p1 - p0) / (z * z - 1);
            const long double dz = p1 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-19L)
                break;
        }
        rule.nodes.push_back(z);
        rule.weights.push_back(2 / ((1 - z * z) * dp * dp));
    }
    return rule;
}

} // namespace granota
