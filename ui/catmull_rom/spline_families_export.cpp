#include "ui/catmull_rom/spline_families_export.h"

#include "ui/catmull_rom/spline_families_drawing.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/files/tikz_writer.h"

namespace granota::ui {

void writeSplineFamilyTikzKey(TikzWriter& w, const CanvasLegend& key)
{
    std::vector<TikzLegendEntry> entries;
    for (const CanvasLegendEntry& e : key.entries)
        entries.push_back({e.color, e.pen, TikzWriter::texText(e.text)});
    w.legend(entries, TikzWriter::texText(key.note), key.alertColor);
}

void writePlaneSplineTikz(TikzWriter& w, const PlaneSplineSettings& settings, const PlaneSplineScene& scene)
{
    w.comment(QStringLiteral("C2 spline in the plane (Def 2.1), %1 ends")
                  .arg(QString::fromUtf8(parametricEndsName(settings.ends).data(),
                                         static_cast<int>(parametricEndsName(settings.ends).size()))));
    if (!scene.catmullRom.bezier.empty())
        w.bezierSegments(scene.catmullRom.bezier, tensionColour(0.5), 1.0, true);
    if (!scene.spline.bezier.empty())
        w.bezierSegments(scene.spline.bezier, QColor(0x33, 0x33, 0x33), 1.25);
}

void writeFunctionDataTikz(TikzWriter& w, const FunctionDataSettings& settings, const FunctionDataScene& scene)
{
    w.comment(QStringLiteral("Function data: natural spline, Catmull-Rom, Fritsch-Carlson, Steffen"));
    if (settings.shadeOvershoot)
        for (const auto& shape : scene.curves) {
            // TikzWriter fills opaquely: the canvas's translucent fill over white, as a tint.
            const QColor c = functionDataCurveColour(shape.curve);
            const double a = kOvershootFillAlpha / 255.0;
            const auto tint = [a](int v) { return static_cast<int>(v * a + 255 * (1 - a) + 0.5); };
            const QColor fill(tint(c.red()), tint(c.green()), tint(c.blue()));
            for (const auto& region : shape.overshootRegions)
                w.polygon(region, QColor(), fill, 0.0);
        }
    for (const auto& shape : scene.curves)
        w.bezierSegments(shape.bezier, functionDataCurveColour(shape.curve), 1.0);
}

} // namespace granota::ui
