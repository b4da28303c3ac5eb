// The build keeps a*b + c as two roundings (-ffp-contract=off, CMakeLists.txt) on a
// processor that has fused multiply-add. Were it fused, the seed solver's trace and the
// golden hash would no longer be the same to the bit on every machine; test_seed_solver
// and test_golden_hash check those in this same build.
#include "tests/test_main.h"

#include <cmath>

namespace {

// Compiled for a processor with FMA, so that the compiler could fuse the expression if
// contraction were allowed; not inlined and fed through volatiles, so it is not folded.
__attribute__((target("fma"), noinline)) double productPlusSum(double a, double b, double c) { return a * b + c; }

bool processorHasFma()
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma");
}

} // namespace

class TestFpContract : public QObject {
    Q_OBJECT
private slots:
    void productAndSumAreRoundedApart()
    {
        if (!processorHasFma())
            QSKIP("this processor has no fused multiply-add: nothing could be contracted");
        // a·b = 1 − 2⁻⁶⁰ exactly; rounded to a double it is 1 (2⁻⁶⁰ is below half an ulp
        // of 1, 2⁻⁵³), so a·b − 1 is 0 with two roundings and −2⁻⁶⁰ with one.
        volatile double a = 1.0 + std::ldexp(1.0, -30);
        volatile double b = 1.0 - std::ldexp(1.0, -30);
        volatile double c = -1.0;
        QCOMPARE(std::fma(a, b, c), -std::ldexp(1.0, -60)); // the values tell the two apart
        QCOMPARE(productPlusSum(a, b, c), 0.0);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestFpContract)
#include "test_fp_contract.moc"
