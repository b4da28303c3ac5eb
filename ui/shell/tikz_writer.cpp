#include "ui/shell/tikz_writer.h"

#include "core/base/number_format.h"

#include <QMap>
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

} // namespace

void TikzWriter::bezierSegments(const std::vector<std::array<Point, 4>>& segments, const QColor& color, double widthPt,
                                bool dashed)
{
    Item item{Item::Bezier, {}, color, widthPt, dashed, false, {}, m_inInset, {}};
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
    if (points.size() < 2)
        return;
    m_items.push_back({Item::Line, points, color, widthPt, dashed, closed, {}, m_inInset, {}});
}

void TikzWriter::point(Point p, const QColor& color, const QString& label)
{
    m_items.push_back({Item::Dot, {p}, color, 1.0, false, false, label, m_inInset, {}});
}

void TikzWriter::comment(const QString& text)
{
    QString line = text;
    line.replace(QLatin1Char('\n'), QLatin1Char(' ')).replace(QLatin1Char('\r'), QLatin1Char(' '));
    m_items.push_back({Item::Comment, {}, {}, 0, false, false, line, m_inInset, {}});
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
        for (const Point& p : item.kind == Item::Bezier ? item.extent : item.points)
            if (isFinite(p)) {
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
        for (const Item& item : m_items) {
            if (item.inset != inset)
                continue;
            switch (item.kind) {
            case Item::Comment: body += QStringLiteral("  % %1\n").arg(item.text); break;
            case Item::Line: {
                body += QStringLiteral("  \\draw[%1, line width=%2pt%3] ")
                            .arg(colourName(item.color), QString::fromStdString(formatSignificant(item.width, 3)),
                                 item.dashed ? QStringLiteral(", dashed") : QString());
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
                                 item.dashed ? QStringLiteral(", dashed") : QString());
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
    };
    write(false, [&](const Point& p) { return coord(p.x, p.y); });
    if (insetShown) {
        // The inset, like the canvas's: in the lower right corner of the drawing, kInsetShare
        // of its width wide and at most three quarters of that tall, on white, framed.
        const double W = cx(x.hi), H = cy(y.hi);
        const double w = kInsetShare * W, h = std::min(0.75 * w, std::max(0.32 * H, 0.5 * w));
        const double left = W - w, right = W, bottom = 0, top = h;
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
