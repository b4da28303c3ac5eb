#include "core/exact/number_column.h"

#include "core/base/number_format.h"
#include "core/exact/rational_approximation.h"

namespace granota {

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

ColumnNotation columnNotation(const std::vector<ExactCoordinate>& exact)
{
    bool repeating = false;
    for (const ExactCoordinate& q : exact) {
        if (!q || q->get_den() > kColumnFractionDenominator)
            return ColumnNotation::Decimals;
        repeating = repeating || !terminates(*q);
    }
    return repeating ? ColumnNotation::Fractions : ColumnNotation::Decimals;
}

std::string columnEntry(const ExactCoordinate& exact, double v, ColumnNotation notation)
{
    if (!exact)
        return columnEntry(v, ColumnNotation::Decimals);
    if (notation == ColumnNotation::Fractions)
        return toString(*exact);
    if (auto text = terminatingDecimal(*exact, kExactDecimalDigits))
        return *text;
    constexpr int kRepeatingDigits = 16; // a double holds 15 to 17; the 17th tells only its rounding
    return roundedDecimal(*exact, kRepeatingDigits);
}

} // namespace granota
