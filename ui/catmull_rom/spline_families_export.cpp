#include "ui/catmull_rom/spline_families_export.h"

#include "ui/catmull_rom/spline_families_drawing.h"
#include "ui/catmull_rom/tension_colour.h"
#include "core/base/number_format.h"
#include "ui/files/tikz_writer.h"

namespace granota::ui {

namespace {

/// The rows "curve,segment,t,x,y" of `samples` taken `perSegment` to a segment, t from 0 to 1.
QString splineFamilySampleRows(const QString& curve, const std::vector<Point>& samples, int perSegment)
{
    QString out;
    const auto number = [](double v) { return QString::fromStdString(formatReadable(v)); };
    for (std::size_t k = 0; k < samples.size() && perSegment > 1; ++k) {
        const int segment = static_cast<int>(k) / perSegment + 1;
        const double t = static_cast<double>(static_cast<int>(k) % perSegment) / (perSegment - 1);
        out +=
            QStringLiteral("%1,%2,%3,%4,%5\n").arg(curve).arg(segment).arg(number(t), number(samples[k].x), number(samples[k].y));
    }
    return out;
}

} // namespace

QString planeSplineCsv(const PlaneSplineScene& scene)
{
    QString out = QStringLiteral("curve,segment,t,x,y\n");
    out += splineFamilySampleRows(QStringLiteral("c2-spline"), scene.spline.samples, PlaneSplineScene::kSamplesPerSegment);
    out += splineFamilySampleRows(QStringLiteral("catmull-rom"), scene.catmullRom.samples, PlaneSplineScene::kSamplesPerSegment);
    out += QStringLiteral("\nknot,u\n");
    for (std::size_t i = 0; i < scene.spline.knots.size(); ++i)
        out += QStringLiteral("%1,%2\n").arg(i).arg(QString::fromStdString(formatReadable(scene.spline.knots[i])));
    return out;
}

QString functionDataCsv(const FunctionDataScene& scene)
{
    QString out = QStringLiteral("curve,segment,t,x,y\n");
    for (const auto& shape : scene.curves)
        out += splineFamilySampleRows(functionDataCurveKey(shape.curve), shape.samples, FunctionDataScene::kSamplesPerSegment);
    out += QStringLiteral("\ncurve,interval,overshoot\n");
    for (const auto& shape : scene.curves)
        for (std::size_t i = 0; i < shape.overshoot.size(); ++i)
            out += QStringLiteral("%1,%2,%3\n")
                       .arg(functionDataCurveKey(shape.curve))
                       .arg(i + 1)
                       .arg(QString::fromStdString(formatReadable(shape.overshoot[i].amount)));
    return out;
}

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
