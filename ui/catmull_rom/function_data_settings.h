#pragma once
/// \file function_data_settings.h
/// The settings of the Catmull-Rom tab's "function data" family: which of the four curves
/// on the same data y(x) are drawn — the natural spline of Def 2.3, Catmull-Rom with τ = 1/2
/// (Def 2.10, open), Fritsch–Carlson and Steffen (core/curves/splines/monotone_spline.h) —
/// and whether their overshoot is shaded. A plain value (undo steps hold it, the document
/// saves it).

#include <QJsonObject>
#include <QString>

#include <array>
#include <optional>

namespace granota::ui {

/// The four curves, in the order of the panel, the key and the overshoot table.
enum class FunctionDataCurve { Natural, CatmullRom, FritschCarlson, Steffen };
inline constexpr std::array<FunctionDataCurve, 4> kFunctionDataCurves{FunctionDataCurve::Natural, FunctionDataCurve::CatmullRom,
                                                                      FunctionDataCurve::FritschCarlson,
                                                                      FunctionDataCurve::Steffen};

struct FunctionDataSettings {
    std::array<bool, 4> shown{true, true, true, true}; ///< one per kFunctionDataCurves entry
    bool shadeOvershoot = true;                        ///< fill each curve's overshoot in its colour

    bool isShown(FunctionDataCurve curve) const { return shown[static_cast<std::size_t>(curve)]; }
    bool operator==(const FunctionDataSettings& o) const { return shown == o.shown && shadeOvershoot == o.shadeOvershoot; }
    bool operator!=(const FunctionDataSettings& o) const { return !(*this == o); }
};

/// "natural", "catmull_rom", "fritsch_carlson", "steffen": the document's keys.
QString functionDataCurveKey(FunctionDataCurve curve);

/// The settings as JSON: {"natural": true, "catmull_rom": true, "fritsch_carlson": true,
/// "steffen": true, "shade_overshoot": true}, and back. readFunctionDataSettings checks every
/// key it knows (a missing key keeps its default) and returns nullopt with `problem` set to
/// the offending key on bad data.
void writeFunctionDataSettings(const FunctionDataSettings& s, QJsonObject& json);
std::optional<FunctionDataSettings> readFunctionDataSettings(const QJsonObject& json, QString* problem);

} // namespace granota::ui
