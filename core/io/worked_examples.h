#pragma once
/// \file worked_examples.h
/// The worked examples of chapter 2 (Ex 2.1–2.13) as data: resources/examples/chapter2.json,
/// compiled into the core so that the GUI's Examples menu, the CLI and the tests share it.

#include "core/io/json.h"
#include "core/exact/radical_sum.h"
#include "core/exact/rational.h"

#include <string>
#include <string_view>
#include <vector>

namespace granota {

/// One worked example. Fields a kind does not use stay empty (degree −1).
struct WorkedExample {
    std::string id;                 ///< "2.1" … "2.13"
    std::string tab;                ///< tab key: decasteljau, bernstein, fit, catmull-rom
    std::string kind;               ///< bezier, bernstein, fit, cubic-spline, catmull-rom-segment, blending, catmull-rom
    std::vector<RPoint> points;     ///< control points, data points or interpolated points, exact
    int degree = -1;                ///< Bernstein degree (Ex 2.4) or fitted degree (Ex 2.7–2.10)
    std::string parametrization;    ///< "uniform" or "chord" (Ex 2.7–2.10)
    std::vector<Rational> taus;     ///< tensions τ (Ex 2.11, 2.12; Ex 2.13 has one)
    std::vector<std::string> modes; ///< Catmull-Rom modes (Ex 2.13: cyclic, open)
    std::string note;               ///< the thesis's slip, where it has one
    /// The t_i as the thesis prints them, in radicals (Ex 2.9: from its d_4 = √85), when it
    /// prints them; "t_as_printed" holds each as [coefficient, square-free radicand] terms.
    std::vector<RadicalSum> printedParameters;
    Json data; ///< the whole entry, including what the thesis prints
};

/// The text of resources/examples/chapter2.json.
std::string_view workedExamplesFile();

/// Every example, in the order of the thesis.
const std::vector<WorkedExample>& workedExamples();

/// The example with this id ("2.7"), or nullptr.
const WorkedExample* findWorkedExample(std::string_view id);

} // namespace granota
