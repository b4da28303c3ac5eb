#include "ui/catmull_rom/catmull_rom_settings.h"

#include "core/base/number_format.h"

#include <QJsonArray>

#include <cmath>

namespace granota::ui {

bool CatmullRomSettings::operator==(const CatmullRomSettings& o) const
{
    const auto sameTcb = [](const std::vector<TcbKnot<Rational>>& a, const std::vector<TcbKnot<Rational>>& b) {
        if (a.size() != b.size())
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i].tension != b[i].tension || a[i].continuity != b[i].continuity || a[i].bias != b[i].bias)
                return false;
        return true;
    };
    return family == o.family && cardinalTension == o.cardinalTension && sameTcb(tcb, o.tcb) &&
           hermiteTangents == o.hermiteTangents && taus == o.taus && selectedTau == o.selectedTau && ends == o.ends &&
           spacing == o.spacing && bezier == o.bezier && spline == o.spline && compareEnds == o.compareEnds &&
           allTausInPlot == o.allTausInPlot && curvaturePlot == o.curvaturePlot && catmullRom == o.catmullRom &&
           controlPoints == o.controlPoints && splineEnds == o.splineEnds && startSlope == o.startSlope &&
           endSlope == o.endSlope && planeSpline == o.planeSpline && functionData == o.functionData;
}

TcbKnot<Rational> tcbAt(const CatmullRomSettings& settings, std::size_t i)
{
    return i < settings.tcb.size() ? settings.tcb[i] : TcbKnot<Rational>{};
}

QString endsKey(CatmullRomEnds ends)
{
    switch (ends) {
    case CatmullRomEnds::Open: return QStringLiteral("open");
    case CatmullRomEnds::Cyclic: return QStringLiteral("cyclic");
    case CatmullRomEnds::Closed: return QStringLiteral("closed");
    case CatmullRomEnds::Segment: return QStringLiteral("segment");
    }
    return {};
}

std::optional<CatmullRomEnds> endsFromKey(const QString& key)
{
    for (auto e : {CatmullRomEnds::Open, CatmullRomEnds::Cyclic, CatmullRomEnds::Closed, CatmullRomEnds::Segment})
        if (endsKey(e) == key)
            return e;
    return std::nullopt;
}

QString spacingKey(CatmullRomSpacing spacing)
{
    switch (spacing) {
    case CatmullRomSpacing::Uniform: return QStringLiteral("uniform");
    case CatmullRomSpacing::Centripetal: return QStringLiteral("centripetal");
    case CatmullRomSpacing::Chordal: return QStringLiteral("chordal");
    }
    return {};
}

std::optional<CatmullRomSpacing> spacingFromKey(const QString& key)
{
    for (auto s : {CatmullRomSpacing::Uniform, CatmullRomSpacing::Centripetal, CatmullRomSpacing::Chordal})
        if (spacingKey(s) == key)
            return s;
    return std::nullopt;
}

double spacingAlpha(CatmullRomSpacing spacing)
{
    switch (spacing) {
    case CatmullRomSpacing::Uniform: return 0.0;
    case CatmullRomSpacing::Centripetal: return 0.5;
    case CatmullRomSpacing::Chordal: return 1.0;
    }
    return 0.0;
}

std::optional<Rational> parseTension(const QString& text, TensionProblem* problem)
{
    QString t = text.trimmed();
    t.replace(QChar(0x2212), QLatin1Char('-')); // "−1/2" as the thesis prints it
    t.remove(QLatin1Char(' '));
    const auto value = parseRational(t.toStdString());
    if (!value) {
        if (problem)
            *problem = TensionProblem::NotANumber;
        return std::nullopt;
    }
    if (abs(*value) > CatmullRomSettings::kMaxTensionAbs) {
        if (problem)
            *problem = TensionProblem::OutOfRange;
        return std::nullopt;
    }
    if (problem)
        *problem = TensionProblem::None;
    return value;
}

QString tensionText(const Rational& tau) { return QString::fromStdString(toString(tau)); }

void writeSettings(const CatmullRomSettings& s, QJsonObject& json)
{
    QJsonArray taus;
    for (const Rational& t : s.taus)
        taus.append(tensionText(t));
    json.insert(QStringLiteral("family"), curveFamilyKey(s.family));
    json.insert(QStringLiteral("cardinal_tension"), tensionText(s.cardinalTension));
    QJsonArray tcb;
    for (const TcbKnot<Rational>& k : s.tcb)
        tcb.append(QJsonArray{tensionText(k.tension), tensionText(k.continuity), tensionText(k.bias)});
    json.insert(QStringLiteral("tcb"), tcb);
    QJsonArray tangents;
    for (const Point& t : s.hermiteTangents)
        tangents.append(QJsonArray{t.x, t.y});
    json.insert(QStringLiteral("hermite_tangents"), tangents);
    json.insert(QStringLiteral("taus"), taus);
    json.insert(QStringLiteral("selected_tau"), s.selectedTau);
    json.insert(QStringLiteral("mode"), endsKey(s.ends));
    json.insert(QStringLiteral("parametrization"), spacingKey(s.spacing));
    json.insert(QStringLiteral("bezier"), s.bezier);
    json.insert(QStringLiteral("spline"), s.spline);
    json.insert(QStringLiteral("catmull_rom"), s.catmullRom);
    json.insert(QStringLiteral("control_points"), s.controlPoints);
    json.insert(QStringLiteral("spline_ends"),
                QString::fromUtf8(splineEndsName(s.splineEnds).data(), static_cast<int>(splineEndsName(s.splineEnds).size())));
    json.insert(QStringLiteral("spline_start_slope"), tensionText(s.startSlope));
    json.insert(QStringLiteral("spline_end_slope"), tensionText(s.endSlope));
    json.insert(QStringLiteral("compare_ends"), s.compareEnds);
    json.insert(QStringLiteral("all_taus_in_plot"), s.allTausInPlot);
    json.insert(QStringLiteral("curvature_plot"), s.curvaturePlot);
    QJsonObject plane, data;
    writePlaneSplineSettings(s.planeSpline, plane);
    writeFunctionDataSettings(s.functionData, data);
    json.insert(QStringLiteral("plane_spline"), plane);
    json.insert(QStringLiteral("function_data"), data);
}

std::optional<CatmullRomSettings> readSettings(const QJsonObject& json, QString* problem)
{
    auto fail = [problem](const QString& why) -> std::optional<CatmullRomSettings> {
        if (problem)
            *problem = why;
        return std::nullopt;
    };
    CatmullRomSettings s;
    const QJsonValue taus = json.value(QStringLiteral("taus"));
    if (!taus.isArray() || taus.toArray().isEmpty() || taus.toArray().size() > CatmullRomSettings::kMaxTensions)
        return fail(QStringLiteral("taus"));
    s.taus.clear();
    for (const QJsonValue& v : taus.toArray()) {
        std::optional<Rational> tau;
        if (v.isString())
            tau = parseTension(v.toString());
        else if (v.isDouble())
            tau = parseTension(QString::fromStdString(formatDouble(v.toDouble()))); // 0.1 is 1/10, not 0.10000000000000001
        if (!tau)
            return fail(QStringLiteral("tau"));
        for (const Rational& t : s.taus)
            if (t == *tau)
                return fail(QStringLiteral("duplicate tau"));
        s.taus.push_back(*tau);
    }
    const QJsonValue selected = json.value(QStringLiteral("selected_tau"));
    if (!selected.isUndefined()) {
        if (!selected.isDouble() || selected.toDouble() != std::floor(selected.toDouble()))
            return fail(QStringLiteral("selected_tau"));
        s.selectedTau = selected.toInt(-1);
    } else {
        s.selectedTau = 0;
    }
    if (s.selectedTau < 0 || s.selectedTau >= static_cast<int>(s.taus.size()))
        return fail(QStringLiteral("selected_tau"));
    // Absent in documents older than the family selector: Catmull-Rom, as they were drawn.
    const QJsonValue family = json.value(QStringLiteral("family"));
    if (!family.isUndefined()) {
        const auto f = curveFamilyFromKey(family.toString());
        if (!f)
            return fail(QStringLiteral("family"));
        s.family = *f;
    }
    // A T, C, B or cardinal c: exact text in [−1, 1].
    const auto unitValue = [](const QJsonValue& v) -> std::optional<Rational> {
        const std::optional<Rational> r = v.isString() ? parseTension(v.toString()) : std::nullopt;
        if (!r || abs(*r) > 1)
            return std::nullopt;
        return r;
    };
    const QJsonValue cardinal = json.value(QStringLiteral("cardinal_tension"));
    if (!cardinal.isUndefined()) {
        const auto c = unitValue(cardinal);
        if (!c)
            return fail(QStringLiteral("cardinal_tension"));
        s.cardinalTension = *c;
    }
    const QJsonValue tcb = json.value(QStringLiteral("tcb"));
    if (!tcb.isUndefined()) {
        if (!tcb.isArray() || tcb.toArray().size() > CatmullRomSettings::kMaxPoints)
            return fail(QStringLiteral("tcb"));
        for (const QJsonValue& k : tcb.toArray()) {
            const QJsonArray a = k.toArray();
            const auto t = unitValue(a.at(0)), c = unitValue(a.at(1)), b = unitValue(a.at(2));
            if (!k.isArray() || a.size() != 3 || !t || !c || !b)
                return fail(QStringLiteral("tcb"));
            s.tcb.push_back({*t, *c, *b});
        }
    }
    const QJsonValue tangents = json.value(QStringLiteral("hermite_tangents"));
    if (!tangents.isUndefined()) {
        if (!tangents.isArray() || tangents.toArray().size() > CatmullRomSettings::kMaxPoints)
            return fail(QStringLiteral("hermite_tangents"));
        for (const QJsonValue& t : tangents.toArray()) {
            const QJsonArray a = t.toArray();
            if (!t.isArray() || a.size() != 2 || !a.at(0).isDouble() || !a.at(1).isDouble())
                return fail(QStringLiteral("hermite_tangents"));
            const Point p{a.at(0).toDouble(), a.at(1).toDouble()};
            if (!isFinite(p))
                return fail(QStringLiteral("hermite_tangents"));
            s.hermiteTangents.push_back(p);
        }
    }
    const QJsonValue mode = json.value(QStringLiteral("mode"));
    if (!mode.isUndefined()) {
        const auto e = endsFromKey(mode.toString());
        if (!e)
            return fail(QStringLiteral("mode"));
        s.ends = *e;
    }
    const QJsonValue spacing = json.value(QStringLiteral("parametrization"));
    if (!spacing.isUndefined()) {
        const auto p = spacingFromKey(spacing.toString());
        if (!p)
            return fail(QStringLiteral("parametrization"));
        s.spacing = *p;
    }
    const QJsonValue splineEnds = json.value(QStringLiteral("spline_ends"));
    if (!splineEnds.isUndefined()) {
        const auto e = parseSplineEnds(splineEnds.toString().toStdString());
        if (!e)
            return fail(QStringLiteral("spline_ends"));
        s.splineEnds = *e;
    }
    for (const auto& [key, target] :
         {std::pair{"spline_start_slope", &s.startSlope}, std::pair{"spline_end_slope", &s.endSlope}}) {
        const QJsonValue v = json.value(QLatin1String(key));
        if (v.isUndefined())
            continue;
        // An end slope is a number as a tension is: exact text, in the tensions' range.
        const std::optional<Rational> slope = v.isString() ? parseTension(v.toString()) : std::nullopt;
        if (!slope)
            return fail(QLatin1String(key));
        *target = *slope;
    }
    const std::pair<const char*, bool*> flags[] = {{"bezier", &s.bezier},
                                                   {"spline", &s.spline},
                                                   {"catmull_rom", &s.catmullRom},
                                                   {"control_points", &s.controlPoints},
                                                   {"compare_ends", &s.compareEnds},
                                                   {"all_taus_in_plot", &s.allTausInPlot},
                                                   {"curvature_plot", &s.curvaturePlot}};
    for (const auto& [key, target] : flags) {
        const QJsonValue v = json.value(QLatin1String(key));
        if (v.isUndefined())
            continue;
        if (!v.isBool())
            return fail(QLatin1String(key));
        *target = v.toBool();
    }
    // The families' own settings, each an object (absent: the defaults).
    const QJsonValue plane = json.value(QStringLiteral("plane_spline"));
    if (!plane.isUndefined()) {
        QString why;
        const auto read = plane.isObject() ? readPlaneSplineSettings(plane.toObject(), &why) : std::nullopt;
        if (!read)
            return fail(QStringLiteral("plane_spline.") + why);
        s.planeSpline = *read;
    }
    const QJsonValue data = json.value(QStringLiteral("function_data"));
    if (!data.isUndefined()) {
        QString why;
        const auto read = data.isObject() ? readFunctionDataSettings(data.toObject(), &why) : std::nullopt;
        if (!read)
            return fail(QStringLiteral("function_data.") + why);
        s.functionData = *read;
    }
    return s;
}

} // namespace granota::ui
