#pragma once
/// \file weight_text.h
/// The weights of a rational B-spline (NURBS) as a person types and reads them, in the one way
/// the weights field and the point table's w column share: a weight is an integer, a decimal
/// (with the interface's decimal sign or a point) or a fraction — "3/2", "0.7" —, nothing else
/// ("√2/2" is not read: the exact arithmetic holds fractions only). Whether a weight is > 0 is
/// the tab's to say (BSplineTab::setWeights), with its message.

#include "core/exact/rational.h"

#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

/// One typed weight (surrounding spaces ignored); nullopt if it is not a number.
std::optional<Rational> parseTypedWeight(const QString& text);
/// The weights field: weights separated by commas, empty for none (polynomial); nullopt if
/// any part is not a number.
std::optional<std::vector<Rational>> parseTypedWeights(const QString& text);
/// A weight as the field and the table show it: "3/2", "2".
QString weightText(const Rational& w);

} // namespace granota::ui
