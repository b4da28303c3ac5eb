#include "core/exact/number_column.h"

#include "core/base/number_format.h"
#include "core/exact/rational_approximation.h"

namespace granota {

namespace {

/// Whether q is an integer over 2^a 5^b: it has a finite decimal expansion.
bool terminates(const Rational& q)
{
    mpz_class d = q.get_den();
    for (unsigned long p : {2UL, 5UL})
        while (mpz_divisible_ui_p(d.get_mpz_t(), p))
            d /= p;
    return d == 1;
}

} // namespace

ColumnNotation columnNotation(const std::vector<double>& values)
{
    bool repeating = false;
    for (double v : values) {
        const auto q = smallRational(v, kColumnFractionDenominator);
        if (!q)
            return ColumnNotation::Decimals; // a value that is no small fraction: decimals for all
        repeating = repeating || !terminates(*q);
    }
    return repeating ? ColumnNotation::Fractions : ColumnNotation::Decimals;
}

std::string columnEntry(double v, ColumnNotation notation)
{
    if (v == 0)
        v = 0; // no "-0"
    if (notation == ColumnNotation::Fractions)
        if (const auto q = smallRational(v, kColumnFractionDenominator))
            return toString(*q);
    return formatDouble(v);
}

} // namespace granota
