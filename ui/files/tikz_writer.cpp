#include "ui/files/tikz_writer.h"

#include "core/base/number_format.h"

#include <QMap>
#include <QRectF>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace granota::ui {

namespace {

// The room the layout keeps around the points, in cm (at most 11 pt text, as in beamer).
constexpr double kEdgeCm = 0.12;      // a dot's radius (2 pt) and the thickest line
constexpr double kLabelRightCm = 1.0; // a label above right of its dot: "P_{10}", "c(t)"
constexpr double kLabelTopCm = 0.75;
constexpr double kTickBelowCm = 0.6;      // tick (2 pt) and the x tick labels below the axis
constexpr double kTickDigitCm = 0.21;     // one character of a y tick label, left of the axis
constexpr double kTickPadCm = 0.35;       // the y tick, the label's padding and a minus sign
constexpr double kTickHalfHeightCm = 0.2; // half a y tick label, above the top tick
constexpr double kMinAreaCm = 0.5;        // the smallest drawing area whatever the margins
constexpr int kMaxTicks = 100;
constexpr double kInsetPadCm = 0.1;   // inside the inset's frame
constexpr double kInsetTitleCm = 0.3; // its title's line (scriptsize)
/// Below this half-span (in model units) the scale, cm per unit, would overflow a double.
constexpr double kMinHalfSpan = 1e-290;
// The key, in \scriptsize (8 pt in an 11 pt beamer frame): the room one character of text
// may take (generous: a key a little wide rather than text over its frame), a line, a swatch.
constexpr double kKeyCharCm = 0.16;
constexpr double kKeyLineCm = 0.36;
constexpr double kKeySwatchCm = 0.5;
constexpr double kKeyPadCm = 0.1;
/// What one covered thing costs a place for the inset or the key (canvas_legend.h's measure):
/// a sample of a line 1, a dot or its label kCoverKeepClear.
constexpr double kCoverKeepClear = 1000.0;
/// Samples of a line at most this far apart (cm), of a cubic segment this many.
constexpr double kCoverSampleCm = 0.15;
constexpr int kCoverBezierSamples = 24;

/// A length in cm as TikZ reads it: three decimals (0.01 mm), a point, no "-0".
QString cm(double v)
{
    QString s = QString::fromStdString(formatFixed(v, 3));
    if (s.contains(QLatin1Char('.'))) {
        while (s.endsWith(QLatin1Char('0')))
            s.chop(1);
        if (s.endsWith(QLatin1Char('.')))
            s.chop(1);
    }
    return s == QLatin1String("-0") ? QStringLiteral("0") : s;
}

/// 1, 2 or 5 times a power of ten, about an eighth of `span`: the step of ticks and grid.
double roundStep(double span)
{
    const double raw = span / 8;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    const double m = raw / power;
    return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * power;
}

/// The interval a picture shows on one axis; `half` is half its length, which stays finite
/// for points as far apart as doubles allow.
struct Interval {
    double lo = 0, hi = 0;
    double half() const { return hi / 2 - lo / 2; }
    bool contains(double v) const { return lo <= v && v <= hi; }
};

/// The tick values of `r` at `step` (a multiple of `step` each), at most kMaxTicks.
std::vector<double> ticks(const Interval& r, double step)
{
    std::vector<double> out;
    const double first = std::ceil(r.lo / step - 1e-9);
    for (int k = 0; k < kMaxTicks; ++k) {
        const double v = (first + k) * step;
        if (!std::isfinite(v) || v > r.hi + step * 1e-9)
            break;
        out.push_back(v == 0 ? 0.0 : v);
    }
    return out;
}

/// A tick label: as many decimals as the step has, in TeX math.
QString tickLabel(double v, double step)
{
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    const std::string text = (decimals <= 6 && std::fabs(v) < 1e7) ? formatFixed(v, decimals) : formatSignificant(v, 3);
    return QStringLiteral("$%1$").arg(QString::fromStdString(text));
}

/// The points of a cubic Bézier segment that bound it: its ends and where x′ or y′ is 0
/// (the roots in (0, 1) of the quadratic derivative of each coordinate).
void addExtremes(const std::array<Point, 4>& b, std::vector<Point>& out)
{
    const auto at = [&b](double t) {
        const double u = 1 - t;
        return u * u * u * b[0] + 3 * u * u * t * b[1] + 3 * u * t * t * b[2] + t * t * t * b[3];
    };
    out.push_back(b[0]);
    out.push_back(b[3]);
    for (int axis = 0; axis < 2; ++axis) {
        const auto c = [&b, axis](int i) {
            return axis == 0 ? b[static_cast<std::size_t>(i)].x : b[static_cast<std::size_t>(i)].y;
        };
        // c′(t)/3 = a t² + 2k t + d with d = c1 − c0, k = c2 − 2c1 + c0, a = c3 − 3c2 + 3c1 − c0.
        const double d = c(1) - c(0), k = c(2) - 2 * c(1) + c(0), a = c(3) - 3 * c(2) + 3 * c(1) - c(0);
        std::vector<double> roots;
        if (std::fabs(a) <= 1e-12 * (std::fabs(k) + std::fabs(d))) {
            if (k != 0)
                roots.push_back(-d / (2 * k));
        } else {
            const double disc = k * k - a * d;
            if (disc >= 0) {
                const double r = std::sqrt(disc);
                roots.push_back((-k + r) / a);
                roots.push_back((-k - r) / a);
            }
        }
        for (double t : roots)
            if (t > 0 && t < 1 && std::isfinite(t))
                out.push_back(at(t));
    }
}

/// TikZ's name for a line style.
QString dashOption(Qt::PenStyle pen)
{
    switch (pen) {
    case Qt::DashLine: return QStringLiteral(", dashed");
    case Qt::DotLine: return QStringLiteral(", dotted");
    case Qt::DashDotLine: return QStringLiteral(", dash dot");
    case Qt::DashDotDotLine: return QStringLiteral(", dash dot dot");
    default: return QString();
    }
}

/// The characters a TeX text shows, about: a command counts one, `$`, braces and `\` none.
int shownLength(const QString& tex)
{
    int n = 0;
    for (qsizetype i = 0; i < tex.size(); ++i) {
        const QChar c = tex[i];
        if (c == QLatin1Char('\\')) {
            ++n;
            while (i + 1 < tex.size() && tex[i + 1].isLetter())
                ++i;
        } else if (c != QLatin1Char('$') && c != QLatin1Char('{') && c != QLatin1Char('}')) {
            ++n;
        }
    }
    return n;
}

/// What a box laid over the drawing would cover, in cm from its lower left corner.
struct Cover {
    std::vector<QPointF> points;   ///< samples of the lines and curves: 1 each
    std::vector<QRectF> keepClear; ///< dots with their labels, the inset: kCoverKeepClear each
    double cost(const QRectF& box) const
    {
        double c = 0;
        for (const QRectF& r : keepClear)
            c += box.intersects(r) ? kCoverKeepClear : 0.0;
        for (const QPointF& q : points)
            c += box.contains(q) ? 1.0 : 0.0;
        return c;
    }
    /// Of boxes of `size` with their lower left corners at `at`, the first of least cost.
    QRectF best(const std::vector<QPointF>& at, const QSizeF& size) const
    {
        QRectF out;
        double least = std::numeric_limits<double>::infinity();
        for (const QPointF& corner : at) {
            const QRectF box(corner, size);
            if (const double c = cost(box); c < least) {
                least = c;
                out = box;
            }
        }
        return out;
    }
};

} // namespace

QString TikzWriter::texText(const QString& text)
{
    static const QMap<QChar, QString> symbols = {
        {QChar(0x03C4), QStringLiteral("\\tau")},   {QChar(0x03BA), QStringLiteral("\\kappa")},
        {QChar(0x2032), QStringLiteral("'")},       {QChar(0x2212), QStringLiteral("-")},
        {QChar(0x2264), QStringLiteral("\\le")},    {QChar(0x2265), QStringLiteral("\\ge")},
        {QChar(0x00D7), QStringLiteral("\\times")}, {QChar(0x2248), QStringLiteral("\\approx")},
        {QChar(0x2260), QStringLiteral("\\ne")},    {QChar(0x25C6), QStringLiteral("\\diamond")},
        {QChar(0x221E), QStringLiteral("\\infty")}, {QChar(0x25CB), QStringLiteral("\\circ")},
        {QChar(0x007C), QStringLiteral("|")},       {QChar(0x03B1), QStringLiteral("\\alpha")},
        {QChar(0x0394), QStringLiteral("\\Delta")}};
    // The letters and signs the labels write as sub- and superscripts ("Pᵢ₊₁", "Bᵢⁿ", "10¹⁶").
    static const QMap<QChar, QString> subscripts = {{QChar(0x1D62), QStringLiteral("i")}, {QChar(0x2C7C), QStringLiteral("j")},
                                                    {QChar(0x2096), QStringLiteral("k")}, {QChar(0x2099), QStringLiteral("n")},
                                                    {QChar(0x1D63), QStringLiteral("r")}, {QChar(0x2093), QStringLiteral("x")},
                                                    {QChar(0x208A), QStringLiteral("+")}, {QChar(0x208B), QStringLiteral("-")}};
    static const QMap<QChar, QString> superscripts = {
        {QChar(0x207F), QStringLiteral("n")},      {QChar(0x2071), QStringLiteral("i")}, {QChar(0x02B3), QStringLiteral("r")},
        {QChar(0x1D40), QStringLiteral("T")},      {QChar(0x207A), QStringLiteral("+")}, {QChar(0x207B), QStringLiteral("-")},
        {QChar(0x1D45), QStringLiteral("\\alpha")}};
    QString out;
    bool inMath = false; // the last thing written is a formula: the next symbol joins it ("Pᵢ²": P$_i^2$)
    QChar script;        // '_' or '^' when that formula ends in a sub- or superscript group
    const auto math = [&out, &inMath, &script](const QString& m) {
        if (inMath)
            out.chop(1);
        out += (inMath ? QString() : QStringLiteral("$")) + m + QLatin1Char('$');
        inMath = true;
        script = QChar();
    };
    // A sub- or superscript: the characters of one run in one group ("P₁₀": P$_{10}$, "Pᵢ₊₁": P$_{i+1}$).
    const auto scripted = [&](QChar kind, const QString& s) {
        if (inMath && script == kind) {
            out.chop(2); // "}$"
            out += s + QStringLiteral("}$");
        } else {
            math(QString(kind) + QLatin1Char('{') + s + QLatin1Char('}'));
            script = kind;
        }
    };
    const auto digit = [&](QChar kind, int d) { scripted(kind, QString::number(d)); };
    const auto textOut = [&out, &inMath](const QString& t) {
        out += t;
        inMath = false;
    };
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (c == QLatin1Char('\\'))
            textOut(QStringLiteral("\\textbackslash{}"));
        else if (c == QLatin1Char('~'))
            textOut(QStringLiteral("\\textasciitilde{}"));
        else if (c == QLatin1Char('^'))
            textOut(QStringLiteral("\\textasciicircum{}"));
        else if (QStringLiteral("#$%&_{}").contains(c))
            textOut(QLatin1Char('\\') + c);
        else if (u >= 0x2080 && u <= 0x2089) // subscript digits
            digit(QLatin1Char('_'), u - 0x2080);
        else if ((u >= 0x2074 && u <= 0x2079) || u == 0x2070) // superscript digits
            digit(QLatin1Char('^'), u - 0x2070);
        else if (u == 0x00B9 || u == 0x00B2 || u == 0x00B3)
            digit(QLatin1Char('^'), u == 0x00B9 ? 1 : u - 0x00B0);
        else if (const auto sub = subscripts.find(c); sub != subscripts.end())
            scripted(QLatin1Char('_'), *sub);
        else if (const auto sup = superscripts.find(c); sup != superscripts.end())
            scripted(QLatin1Char('^'), *sup);
        else if (const auto it = symbols.find(c); it != symbols.end())
            math(*it);
        else
            textOut(QString(c));
    }
    return out;
}

void TikzWriter::bezierSegments(const std::vector<std::array<Point, 4>>& segments, const QColor& color, double widthPt,
                                bool dashed)
{
    Item item{Item::Bezier,        {}, color, widthPt, dashed ? Qt::DashLine : Qt::SolidLine, false, {}, m_inInset, {}, {}, false,
              m_clip && !m_inInset};
    for (const auto& b : segments) {
        if (!std::all_of(b.begin(), b.end(), [](const Point& p) { return isFinite(p); }))
            continue;
        item.points.insert(item.points.end(), b.begin(), b.end());
        addExtremes(b, item.extent);
    }
    if (!item.points.empty())
        m_items.push_back(std::move(item));
}

void TikzWriter::polyline(const std::vector<Point>& points, const QColor& color, double widthPt, bool dashed, bool closed)
{
    polyline(points, color, widthPt, dashed ? Qt::DashLine : Qt::SolidLine, closed);
}

void TikzWriter::polyline(const std::vector<Point>& points, const QColor& color, double widthPt, Qt::PenStyle pen, bool closed)
{
    if (points.size() < 2)
        return;
    m_items.push_back({Item::Line, points, color, widthPt, pen, closed, {}, m_inInset, {}, {}, false, m_clip && !m_inInset});
}

void TikzWriter::polygon(const std::vector<Point>& points, const QColor& stroke, const QColor& fill, double widthPt)
{
    if (points.size() < 3)
        return;
    m_items.push_back({Item::Line,
                       points,
                       stroke,
                       widthPt,
                       stroke.isValid() ? Qt::SolidLine : Qt::NoPen,
                       true,
                       {},
                       m_inInset,
                       {},
                       fill,
                       false,
                       m_clip && !m_inInset});
}

void TikzWriter::arrow(Point from, Point to, const QColor& color, double widthPt)
{
    m_items.push_back(
        {Item::Line, {from, to}, color, widthPt, Qt::SolidLine, false, {}, m_inInset, {}, {}, true, m_clip && !m_inInset});
}

void TikzWriter::point(Point p, const QColor& color, const QString& label)
{
    m_items.push_back({Item::Dot, {p}, color, 1.0, Qt::SolidLine, false, label, m_inInset, {}, {}, false, m_clip && !m_inInset});
}

void TikzWriter::comment(const QString& text)
{
    QString line = text;
    line.replace(QLatin1Char('\n'), QLatin1Char(' ')).replace(QLatin1Char('\r'), QLatin1Char(' '));
    m_items.push_back({Item::Comment, {}, {}, 0, Qt::SolidLine, false, line, m_inInset, {}, {}, false, false});
}

void TikzWriter::clipTo(Point lo, Point hi)
{
    m_clip = true;
    m_clipLo = Point(std::min(lo.x, hi.x), std::min(lo.y, hi.y));
    m_clipHi = Point(std::max(lo.x, hi.x), std::max(lo.y, hi.y));
}

void TikzWriter::legend(const std::vector<TikzLegendEntry>& entries, const QString& note, const QColor& alertColor)
{
    m_legend = entries;
    m_legendNote = note;
    m_legendAlert = alertColor;
}

void TikzWriter::beginInset(const QString& title)
{
    m_inInset = true;
    m_insetTitle = title;
}

void TikzWriter::endInset() { m_inInset = false; }

QString TikzWriter::str() const
{
    // What the points span, and whether any dot has a label.
    Interval x{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}, y = x;
    bool labels = false;
    bool insetShown = false;
    for (const Item& item : m_items) {
        if (item.inset) { // the inset has a scale of its own
            insetShown = insetShown || item.kind != Item::Comment;
            continue;
        }
        labels = labels || (item.kind == Item::Dot && !item.text.isEmpty());
        for (Point p : item.kind == Item::Bezier ? item.extent : item.points)
            if (isFinite(p)) {
                if (item.clipped) // what the clip hides takes no room
                    p = Point(std::clamp(p.x, m_clipLo.x, m_clipHi.x), std::clamp(p.y, m_clipLo.y, m_clipHi.y));
                x = {std::min(x.lo, p.x), std::max(x.hi, p.x)};
                y = {std::min(y.lo, p.y), std::max(y.hi, p.y)};
            }
    }
    for (Interval* r : {&x, &y}) {
        if (!(r->lo <= r->hi))
            *r = {0, 1};                         // nothing drawn
        else if (!(r->half() >= kMinHalfSpan)) { // a single point, or points on one line
            const double pad = std::max(0.5, std::fabs(r->lo) * 1e-9);
            *r = {r->lo - pad, r->lo + pad};
        }
    }
    const bool scaleShown = m_options.axes || m_options.grid;
    const double step = roundStep(2 * std::max(x.half(), y.half()));
    std::vector<double> xTicks, yTicks;
    const auto longest = [step](const std::vector<double>& values) {
        int chars = 0;
        for (double v : values)
            chars = std::max(chars, static_cast<int>(tickLabel(v, step).size()) - 2); // without the $s
        return chars;
    };
    if (scaleShown) {
        xTicks = ticks(x, step);
        yTicks = ticks(y, step);
    }

    // The margins (labels; tick labels left of the y axis, below the x axis, and half of one
    // beyond each end) and one scale for both axes: the width asked for, or narrower when the
    // picture would be taller than allowed.
    const double yLabels = m_options.axes ? kTickPadCm + kTickDigitCm * longest(yTicks) : 0.0;
    const double xLabelHalf = m_options.axes ? kTickDigitCm * longest(xTicks) / 2 : 0.0;
    const double left = kEdgeCm + std::max(yLabels, xLabelHalf);
    const double right = kEdgeCm + std::max(labels ? kLabelRightCm : 0.0, xLabelHalf);
    const double bottom = kEdgeCm + (m_options.axes ? kTickBelowCm : 0.0);
    const double top = kEdgeCm + std::max(labels ? kLabelTopCm : 0.0, m_options.axes ? kTickHalfHeightCm : 0.0);
    const double areaW = std::max(kMinAreaCm, m_options.widthCm - left - right);
    const double areaH = std::max(kMinAreaCm, m_options.maxHeightCm - bottom - top);
    const double perHalf = std::min(areaW / x.half(), areaH / y.half()); // cm per two model units
    const auto cx = [&](double v) { return (v / 2 - x.lo / 2) * perHalf; };
    const auto cy = [&](double v) { return (v / 2 - y.lo / 2) * perHalf; };
    const auto coord = [&](double px, double py) { return QStringLiteral("(%1,%2)").arg(cm(cx(px)), cm(cy(py))); };

    QMap<QString, QString> colours; // name → hex
    auto colourName = [&colours](const QColor& c) {
        const QString hex = c.name().mid(1).toUpper();
        const QString name = QStringLiteral("g") + hex;
        colours.insert(name, hex);
        return name;
    };
    QString body;
    if (m_options.grid) {
        QStringList lines;
        for (double v : xTicks)
            lines << coord(v, y.lo) + QStringLiteral(" -- ") + coord(v, y.hi);
        for (double v : yTicks)
            lines << coord(x.lo, v) + QStringLiteral(" -- ") + coord(x.hi, v);
        body += QStringLiteral("  \\draw[black!15, line width=0.3pt] %1;\n").arg(lines.join(QLatin1Char(' ')));
    }
    if (m_options.axes) {
        // Through the origin when it is in the picture, else along the picture's edge.
        const double ax = x.contains(0) ? 0.0 : x.lo, ay = y.contains(0) ? 0.0 : y.lo;
        body += QStringLiteral("  \\draw[black, line width=0.5pt] %1 -- %2 %3 -- %4;\n")
                    .arg(coord(x.lo, ay), coord(x.hi, ay), coord(ax, y.lo), coord(ax, y.hi));
        for (double v : xTicks)
            body += QStringLiteral("  \\draw[black, line width=0.5pt] %1 -- ++(0,-2pt) node[below, inner sep=1pt] {%2};\n")
                        .arg(coord(v, ay), tickLabel(v, step));
        for (double v : yTicks)
            body += QStringLiteral("  \\draw[black, line width=0.5pt] %1 -- ++(-2pt,0) node[left, inner sep=1pt] {%2};\n")
                        .arg(coord(ax, v), tickLabel(v, step));
    }
    // The items of the main picture (inset false) or of the inset, through `at`.
    const auto write = [&](bool inset, const std::function<QString(const Point&)>& at) {
        const QString dotRadius = inset ? QStringLiteral("1.2pt") : QStringLiteral("2pt");
        bool clipping = false; // inside the scope that clips to clipTo's rectangle
        for (const Item& item : m_items) {
            if (item.inset != inset)
                continue;
            if (item.kind != Item::Comment && item.clipped != clipping) {
                clipping = item.clipped;
                body += clipping ? QStringLiteral("  \\begin{scope}\n  \\clip %1 rectangle %2;\n").arg(at(m_clipLo), at(m_clipHi))
                                 : QStringLiteral("  \\end{scope}\n");
            }
            switch (item.kind) {
            case Item::Comment: body += QStringLiteral("  % %1\n").arg(item.text); break;
            case Item::Line: {
                QString options = item.pen == Qt::NoPen ? QStringLiteral("draw=none")
                                                        : colourName(item.color) + QStringLiteral(", line width=") +
                                                              QString::fromStdString(formatSignificant(item.width, 3)) +
                                                              QStringLiteral("pt") + dashOption(item.pen);
                if (item.fill.isValid())
                    options += QStringLiteral(", fill=") + colourName(item.fill);
                if (item.arrow)
                    options += QStringLiteral(", -stealth");
                body += QStringLiteral("  \\draw[%1] ").arg(options);
                QStringList parts;
                for (const Point& p : item.points)
                    if (isFinite(p))
                        parts << at(p);
                body += parts.join(QStringLiteral(" -- "));
                body += item.closed ? QStringLiteral(" -- cycle;\n") : QStringLiteral(";\n");
                break;
            }
            case Item::Bezier: {
                // TikZ bounds a curve by its control points, which may lie far outside it:
                // the curve is drawn as an overlay, and an invisible rectangle holds what it
                // covers.
                double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
                for (const Point& p : item.extent) {
                    x0 = std::min(x0, p.x);
                    y0 = std::min(y0, p.y);
                    x1 = std::max(x1, p.x);
                    y1 = std::max(y1, p.y);
                }
                if (x0 <= x1 && y0 <= y1)
                    body += QStringLiteral("  \\path %1 rectangle %2;\n").arg(at(Point(x0, y0)), at(Point(x1, y1)));
                body += QStringLiteral("  \\draw[%1, line width=%2pt%3, overlay] ")
                            .arg(colourName(item.color), QString::fromStdString(formatSignificant(item.width, 3)),
                                 dashOption(item.pen));
                QString end; // where the path is, as written: a segment starting there continues it
                for (std::size_t i = 0; i + 3 < item.points.size(); i += 4) {
                    const Point* b = &item.points[i];
                    const QString start = at(b[0]);
                    if (start != end)
                        body += (end.isEmpty() ? QString() : QStringLiteral(" ")) + start;
                    end = at(b[3]);
                    body += QStringLiteral(" .. controls %1 and %2 .. %3").arg(at(b[1]), at(b[2]), end);
                }
                body += QStringLiteral(";\n");
                break;
            }
            case Item::Dot:
                if (!isFinite(item.points[0]))
                    break;
                body += QStringLiteral("  \\fill[%1] %2 circle[radius=%3]")
                            .arg(colourName(item.color), at(item.points[0]), dotRadius);
                if (!item.text.isEmpty())
                    body += QStringLiteral(" node[above right%1] {$%2$}")
                                .arg(inset ? QStringLiteral(", font=\\scriptsize, inner sep=1pt") : QString(), item.text);
                body += QStringLiteral(";\n");
                break;
            }
        }
        if (clipping)
            body += QStringLiteral("  \\end{scope}\n");
    };
    write(false, [&](const Point& p) { return coord(p.x, p.y); });
    // What the inset and the key would cover of the main picture, in cm: samples of its lines
    // and curves, its dots with their labels.
    Cover cover;
    const double W = cx(x.hi), H = cy(y.hi);
    {
        const auto toCm = [&](const Point& p) { return QPointF(cx(p.x), cy(p.y)); };
        const auto sample = [&](const QPointF& a, const QPointF& b) {
            const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
            const int n = std::clamp(static_cast<int>(std::ceil(length / kCoverSampleCm)), 1, 1000);
            for (int k = 0; k < n; ++k)
                cover.points.push_back(a + (b - a) * (static_cast<double>(k) / n));
            cover.points.push_back(b);
        };
        for (const Item& item : m_items) {
            if (item.inset || item.kind == Item::Comment)
                continue;
            if (item.kind == Item::Dot) {
                if (!isFinite(item.points[0]))
                    continue;
                const QPointF c = toCm(item.points[0]);
                QRectF dot(c - QPointF(kEdgeCm, kEdgeCm), QSizeF(2 * kEdgeCm, 2 * kEdgeCm));
                if (!item.text.isEmpty())
                    dot = dot.united(QRectF(c, QSizeF(kLabelRightCm, kLabelTopCm)));
                cover.keepClear.push_back(dot);
            } else if (item.kind == Item::Line) {
                std::vector<QPointF> at;
                for (const Point& p : item.points)
                    if (isFinite(p))
                        at.push_back(toCm(p));
                if (item.closed && at.size() > 2)
                    at.push_back(at.front());
                for (std::size_t i = 0; i + 1 < at.size(); ++i)
                    sample(at[i], at[i + 1]);
            } else if (item.kind == Item::Bezier) {
                for (std::size_t i = 0; i + 3 < item.points.size(); i += 4) {
                    const Point* b = &item.points[i];
                    for (int k = 0; k <= kCoverBezierSamples; ++k) {
                        const double t = static_cast<double>(k) / kCoverBezierSamples, u = 1 - t;
                        cover.points.push_back(
                            toCm(u * u * u * b[0] + 3 * u * u * t * b[1] + 3 * u * t * t * b[2] + t * t * t * b[3]));
                    }
                }
            }
        }
    }
    if (insetShown) {
        // The inset, like the canvas's: in a corner of the drawing, the one that covers least
        // of it (the lower right first), kInsetShare of its width wide and at most three
        // quarters of that tall, on white, framed.
        const double w = kInsetShare * W, h = std::min(0.75 * w, std::max(0.32 * H, 0.5 * w));
        const QRectF place = cover.best({{W - w, 0}, {0, 0}, {W - w, H - h}, {0, H - h}}, QSizeF(w, h));
        cover.keepClear.push_back(place); // the key keeps clear of it
        const double left = place.left(), right = place.right(), bottom = place.top(), top = place.bottom();
        const auto c = [](double px, double py) { return QStringLiteral("(%1,%2)").arg(cm(px), cm(py)); };
        body += QStringLiteral("  % inset: %1\n").arg(m_insetTitle);
        body += QStringLiteral(
                    "  \\filldraw[fill=white, draw=black!30, line width=0.4pt, rounded corners=1.5pt] %1 rectangle %2;\n")
                    .arg(c(left, bottom), c(right, top));
        body += QStringLiteral("  \\node[anchor=north west, inner sep=1pt, font=\\scriptsize] at %1 {%2};\n")
                    .arg(c(left + kInsetPadCm, top - kInsetPadCm / 2), m_insetTitle);
        // Its own scale, one for both axes, fitting its items and the origin with a margin of 5 %.
        Interval ix{0, 0}, iy{0, 0};
        for (const Item& item : m_items)
            if (item.inset)
                for (const Point& p : item.points)
                    if (isFinite(p)) {
                        ix = {std::min(ix.lo, p.x), std::max(ix.hi, p.x)};
                        iy = {std::min(iy.lo, p.y), std::max(iy.hi, p.y)};
                    }
        const double span = std::max({ix.half(), iy.half(), kMinHalfSpan});
        const double areaL = left + kInsetPadCm, areaR = right - kInsetPadCm;
        const double areaB = bottom + kInsetPadCm, areaT = top - kInsetPadCm - kInsetTitleCm;
        const double perHalfInset = std::max(0.0, std::min((areaR - areaL) / (ix.half() + 0.1 * span),
                                                           (areaT - areaB) / (iy.half() + 0.1 * span)));
        // Centred in the area.
        const double midX = ix.lo / 2 + ix.hi / 2, midY = iy.lo / 2 + iy.hi / 2;
        const auto ux = [&](double v) { return (areaL + areaR) / 2 + (v / 2 - midX / 2) * perHalfInset; };
        const auto uy = [&](double v) { return (areaB + areaT) / 2 + (v / 2 - midY / 2) * perHalfInset; };
        body += QStringLiteral("  \\begin{scope}\n  \\clip %1 rectangle %2;\n").arg(c(areaL, areaB), c(areaR, areaT));
        // The axes through the origin: the inset's points are vectors from there.
        body += QStringLiteral("  \\draw[black!50, line width=0.3pt] %1 -- %2 %3 -- %4;\n")
                    .arg(c(areaL, uy(0)), c(areaR, uy(0)), c(ux(0), areaB), c(ux(0), areaT));
        write(true, [&](const Point& p) { return c(ux(p.x), uy(p.y)); });
        body += QStringLiteral("  \\end{scope}\n");
    }
    if (!m_legend.empty() || !m_legendNote.isEmpty()) {
        // The key, laid out here (its size must be known to place it): a swatch and a text a
        // line, the note wrapped under them, at most 0.6 of the drawing's width for the note.
        double textCm = 0;
        for (const TikzLegendEntry& e : m_legend)
            textCm = std::max(textCm, kKeyCharCm * shownLength(e.text));
        const double entriesW = kKeySwatchCm + kKeyPadCm + textCm;
        const double noteFull = kKeyCharCm * shownLength(m_legendNote);
        const double noteW = m_legendNote.isEmpty() ? 0.0 : std::min(noteFull, std::max(entriesW, 0.6 * W));
        const double noteLines = noteW > 0 ? std::ceil(noteFull / noteW) : 0.0;
        const QSizeF size(std::max(entriesW, noteW) + 2 * kKeyPadCm,
                          kKeyLineCm * (static_cast<double>(m_legend.size()) + noteLines) + 2 * kKeyPadCm);
        // The corners (top left first, as the canvas's key), then along the edges.
        const double l = 0, r = std::max(0.0, W - size.width()), b = 0, t = std::max(0.0, H - size.height());
        std::vector<QPointF> at = {{l, t}, {r, t}, {l, b}, {r, b}};
        constexpr int kSteps = 8;
        for (int k = 1; k < kSteps; ++k) {
            const double f = static_cast<double>(k) / kSteps;
            at.insert(at.end(), {{l + f * (r - l), t}, {l + f * (r - l), b}, {l, b + f * (t - b)}, {r, b + f * (t - b)}});
        }
        const QRectF box = cover.best(at, size);
        const auto c = [](double px, double py) { return QStringLiteral("(%1,%2)").arg(cm(px), cm(py)); };
        if (size.width() > W || size.height() > H) { // a small picture: the key would overflow it
            body += QStringLiteral("  % key left out: %1 cm x %2 cm, larger than the drawing\n")
                        .arg(cm(size.width()), cm(size.height()));
        } else {
            body += QStringLiteral("  % key\n");
            body += QStringLiteral("  \\filldraw[fill=white, fill opacity=0.85, draw=black!30, line width=0.4pt, rounded "
                                   "corners=1.5pt] %1 rectangle %2;\n")
                        .arg(c(box.left(), box.top()), c(box.right(), box.bottom()));
            double lineY = box.bottom() - kKeyPadCm - kKeyLineCm / 2; // the middle of the first line
            const double swatchL = box.left() + kKeyPadCm, textL = swatchL + kKeySwatchCm + kKeyPadCm;
            for (const TikzLegendEntry& e : m_legend) {
                if (e.pen != Qt::NoPen)
                    body += QStringLiteral("  \\draw[%1, line width=0.8pt%2] %3 -- %4;\n")
                                .arg(colourName(e.color), dashOption(e.pen), c(swatchL, lineY), c(swatchL + kKeySwatchCm, lineY));
                body += QStringLiteral("  \\node[anchor=west, inner sep=0pt, font=\\scriptsize%1] at %2 {%3};\n")
                            .arg(e.pen == Qt::NoPen ? QStringLiteral(", text=") + colourName(m_legendAlert) : QString(),
                                 c(e.pen == Qt::NoPen ? swatchL : textL, lineY), e.text);
                lineY -= kKeyLineCm;
            }
            if (!m_legendNote.isEmpty())
                body += QStringLiteral(
                            "  \\node[anchor=north west, inner sep=0pt, font=\\scriptsize, align=left, text width=%1cm, "
                            "text=%2] at %3 {%4};\n")
                            .arg(cm(noteW), colourName(m_legendAlert), c(swatchL, lineY + kKeyLineCm / 2), m_legendNote);
        }
    }
    // Every line outside the picture ends in a comment, so that \input adds no space.
    QString out = QStringLiteral("%% Made with Granota. Needs \\usepackage{tikz}.\n"
                                 "%% %1 cm wide at most, %2 cm tall at most; 1 model unit = %3 cm.\n")
                      .arg(cm(m_options.widthCm), cm(m_options.maxHeightCm),
                           QString::fromStdString(formatSignificant(perHalf / 2, 6)));
    for (auto it = colours.cbegin(); it != colours.cend(); ++it)
        out += QStringLiteral("\\definecolor{%1}{HTML}{%2}%\n").arg(it.key(), it.value());
    out += QStringLiteral("\\begin{tikzpicture}\n");
    out += body;
    out += QStringLiteral("\\end{tikzpicture}%\n");
    return out;
}

} // namespace granota::ui
