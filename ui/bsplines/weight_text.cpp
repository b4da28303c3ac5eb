#include "ui/bsplines/weight_text.h"

#include "ui/common/number_text.h"

#include <QStringList>

namespace granota::ui {

std::optional<Rational> parseTypedWeight(const QString& text) { return parseTypedRational(text.trimmed()); }

std::optional<std::vector<Rational>> parseTypedWeights(const QString& text)
{
    std::vector<Rational> weights;
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return weights;
    for (const QString& part : trimmed.split(QLatin1Char(','))) {
        const auto w = parseTypedWeight(part);
        if (!w)
            return std::nullopt;
        weights.push_back(*w);
    }
    return weights;
}

QString weightText(const Rational& w) { return displayText(toString(w)); }

} // namespace granota::ui
