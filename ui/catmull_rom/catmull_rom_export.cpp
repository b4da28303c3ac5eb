#include "ui/catmull_rom/catmull_rom_export.h"
#include "ui/catmull_rom/spline_families_export.h"

#include "core/base/number_format.h"
#include "ui/catmull_rom/catmull_rom_drawing.h"
#include "ui/catmull_rom/family_drawing.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/canvas_style.h"
#include "ui/files/tikz_writer.h"

namespace granota::ui {

QString catmullRomCsv(const std::vector<Point>& points, const std::vector<ExactPoint>& exact, const CatmullRomSettings& settings,
                      const CatmullRomScene& scene)
{
    QString out = QStringLiteral("point,x,y\n");
    const bool haveExact = exact.size() == points.size();
    for (std::size_t i = 0; i < points.size(); ++i)
        out += QStringLiteral("q%1,%2,%3\n")
                   .arg(i)
                   .arg(QString::fromStdString(haveExact ? readableExact(exact[i].x, points[i].x) : formatReadable(points[i].x)),
                        QString::fromStdString(haveExact ? readableExact(exact[i].y, points[i].y) : formatReadable(points[i].y)));
    out += QStringLiteral("\ntau,segment,t,x,y\n");
    const int samples = CatmullRomScene::kSamplesPerSegment;
    for (const CatmullRomCurve& c : scene.curves) {
        const QString tau = tensionText(c.tau);
        for (std::size_t k = 0; k < c.samples.size(); ++k) {
            const int segment = static_cast<int>(k) / samples + 1 + firstSegmentStart(c.ends);
            const double t = static_cast<double>(static_cast<int>(k) % samples) / (samples - 1);
            out += QStringLiteral("%1,%2,%3,%4,%5\n")
                       .arg(tau)
                       .arg(segment)
                       .arg(QString::fromStdString(formatReadable(t)), QString::fromStdString(formatReadable(c.samples[k].x)),
                            QString::fromStdString(formatReadable(c.samples[k].y)));
        }
    }
    if (settings.family != CurveFamily::CatmullRom && !scene.family.samples.empty()) {
        // The family's curve (family_curves.h), sampled as the τ curves are.
        out += QStringLiteral("\nfamily,segment,t,x,y\n");
        const FamilyCurve& f = scene.family;
        for (std::size_t k = 0; k < f.samples.size(); ++k) {
            const int segment = static_cast<int>(k) / samples + 1 + firstSegmentStart(settings.ends);
            const double t = static_cast<double>(static_cast<int>(k) % samples) / (samples - 1);
            out += QStringLiteral("%1,%2,%3,%4,%5\n")
                       .arg(curveFamilyKey(settings.family))
                       .arg(segment)
                       .arg(QString::fromStdString(formatReadable(t)), QString::fromStdString(formatReadable(f.samples[k].x)),
                            QString::fromStdString(formatReadable(f.samples[k].y)));
        }
    }
    // The C² families' own curves (spline_families_export.h).
    if (settings.family == CurveFamily::PlaneSpline)
        out += QStringLiteral("\n") + planeSplineCsv(scene.planeSpline);
    else if (settings.family == CurveFamily::FunctionData)
        out += QStringLiteral("\n") + functionDataCsv(scene.functionData);
    if (settings.curvaturePlot) {
        // κ(s) as plotted: a knot appears twice, the end of one segment and the start of the next.
        out += QStringLiteral("\ncurve,tau,ends,segment,s,kappa\n");
        const auto number = [](double v) { return QString::fromStdString(formatReadable(v)); };
        auto write = [&](const QString& curve, const QString& tau, const QString& ends, int firstSegment,
                         const CurvatureProfile& profile) {
            for (std::size_t i = 0; i < profile.samples.size(); ++i)
                for (const CurvatureSample& sample : profile.samples[i])
                    out += QStringLiteral("%1,%2,%3,%4,%5,%6\n")
                               .arg(curve, tau, ends)
                               .arg(static_cast<int>(i) + firstSegment)
                               .arg(number(sample.s), sample.kappa ? number(*sample.kappa) : QString());
        };
        for (const CatmullRomCurve& c : scene.curves)
            write(QStringLiteral("catmull-rom"), tensionText(c.tau), endsKey(c.ends), 1 + firstSegmentStart(c.ends), c.curvature);
        for (const CatmullRomCurve& c : scene.otherEnds)
            write(QStringLiteral("catmull-rom"), tensionText(c.tau), endsKey(c.ends), 1 + firstSegmentStart(c.ends), c.curvature);
        write(QStringLiteral("bezier"), QString(), QString(), 1, scene.bezierCurvature);
        write(QStringLiteral("spline"), QString(), QString(), 1, scene.splineCurvature);
    }
    return out;
}

void writeCatmullRomTikz(TikzWriter& w, const std::vector<Point>& points, bool polygonVisible, const CatmullRomSettings& settings,
                         const CatmullRomScene& scene)
{
    if (settings.family == CurveFamily::PlaneSpline || settings.family == CurveFamily::FunctionData) {
        // The C² families (spline_families_export.h): their curves, the points, the canvas's key.
        if (settings.controlPoints && polygonVisible)
            w.polyline(points, CanvasStyle().polygon, 0.6, true);
        if (settings.family == CurveFamily::PlaneSpline)
            writePlaneSplineTikz(w, settings.planeSpline, scene.planeSpline);
        else
            writeFunctionDataTikz(w, settings.functionData, scene.functionData);
        for (std::size_t i = 0; settings.controlPoints && i < points.size(); ++i)
            w.point(points[i], CanvasStyle().handle, QStringLiteral("q_{%1}").arg(i));
        writeSplineFamilyTikzKey(w, catmullRomLegend(settings, scene));
        return;
    }
    w.comment(QStringLiteral("Catmull-Rom curves (thesis §2.2), mode %1").arg(endsKey(settings.ends)));
    // The polygon of the points q_i, dashed and thin, as the point editor draws it.
    if (settings.controlPoints && polygonVisible)
        w.polyline(points, CanvasStyle().polygon, 0.6, true);
    if (!scene.bezier.empty())
        w.polyline(scene.bezier, kCatmullRomBezierColor, 1.0, Qt::DashDotLine);
    // The Catmull-Rom segments and the spline's pieces are cubics: written as Bézier segments.
    if (!scene.splineBezier.empty())
        w.bezierSegments(scene.splineBezier, kCatmullRomSplineColor, 1.0);
    // A family other than Catmull-Rom (family_curves.h): its Hermite segments as Bézier segments
    // (hermiteToBezier), and the tangents at the points as arrows, as on the canvas.
    const bool catmullRom = settings.catmullRom && settings.family == CurveFamily::CatmullRom;
    if (settings.family != CurveFamily::CatmullRom) {
        w.comment(QStringLiteral("family %1").arg(curveFamilyKey(settings.family)));
        w.bezierSegments(scene.family.bezier, kFamilyCurveColor, 1.2);
        const FamilyCurve& f = scene.family;
        for (std::size_t i = 0; hasPointTangents(settings.family) && i < f.tangents.size() && i < f.points.size(); ++i) {
            if (!(f.tangents[i].in == f.tangents[i].out))
                w.arrow(f.points[i] - f.tangents[i].in, f.points[i], kTangentInColor, 0.8);
            w.arrow(f.points[i], f.points[i] + f.tangents[i].out, kTangentOutColor, 0.8);
        }
    }
    for (std::size_t i = 0; catmullRom && i < scene.otherEnds.size(); ++i)
        w.bezierSegments(scene.otherEnds[i].bezier, tensionColour(scene.otherEnds[i].tau), 0.8, true);
    for (std::size_t i = 0; catmullRom && i < scene.curves.size(); ++i) {
        w.comment(QStringLiteral("tau = %1").arg(tensionText(scene.curves[i].tau)));
        w.bezierSegments(scene.curves[i].bezier, tensionColour(scene.curves[i].tau), 1.2);
    }
    for (std::size_t i = 0; settings.controlPoints && i < points.size(); ++i)
        w.point(points[i], CanvasStyle().handle, QStringLiteral("q_{%1}").arg(i));
    // The canvas's key: the same lines in TeX.
    const CanvasLegend key = catmullRomLegend(settings, scene);
    std::vector<TikzLegendEntry> entries;
    for (const CanvasLegendEntry& e : key.entries)
        entries.push_back({e.color, e.pen, TikzWriter::texText(e.text)});
    w.legend(entries, TikzWriter::texText(key.note), key.alertColor);
}

} // namespace granota::ui
