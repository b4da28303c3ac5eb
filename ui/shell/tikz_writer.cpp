#include "ui/shell/tikz_writer.h"

#include <QMap>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

void TikzWriter::polyline(const std::vector<Point>& points, const QColor& color, double widthPt, bool dashed,
                          bool closed)
{
    if (points.size() < 2)
        return;
    m_items.push_back({Item::Line, points, color, widthPt, dashed, closed, {}});
}

void TikzWriter::point(Point p, const QColor& color, const QString& label)
{
    m_items.push_back({Item::Dot, {p}, color, 1.0, false, false, label});
}

void TikzWriter::comment(const QString& text) { m_items.push_back({Item::Comment, {}, {}, 0, false, false, text}); }

QString TikzWriter::str() const
{
    double minX = std::numeric_limits<double>::infinity(), maxX = -minX;
    for (const Item& item : m_items)
        for (const Point& p : item.points)
            if (isFinite(p)) {
                minX = std::min(minX, p.x);
                maxX = std::max(maxX, p.x);
            }
    const double span = (maxX > minX) ? maxX - minX : 1.0;
    const double scale = m_widthCm / span;
    QMap<QString, QString> colours; // name → hex
    auto colourName = [&colours](const QColor& c) {
        const QString hex = c.name().mid(1).toUpper();
        const QString name = QStringLiteral("g") + hex;
        colours.insert(name, hex);
        return name;
    };
    QString body;
    auto coord = [](Point p) { return QStringLiteral("(%1,%2)").arg(p.x, 0, 'g', 8).arg(p.y, 0, 'g', 8); };
    for (const Item& item : m_items) {
        switch (item.kind) {
        case Item::Comment:
            body += QStringLiteral("  % %1\n").arg(item.text);
            break;
        case Item::Line: {
            body += QStringLiteral("  \\draw[%1, line width=%2pt%3] ")
                        .arg(colourName(item.color))
                        .arg(item.width, 0, 'g', 3)
                        .arg(item.dashed ? QStringLiteral(", dashed") : QString());
            QStringList parts;
            for (const Point& p : item.points)
                if (isFinite(p))
                    parts << coord(p);
            body += parts.join(QStringLiteral(" -- "));
            body += item.closed ? QStringLiteral(" -- cycle;\n") : QStringLiteral(";\n");
            break;
        }
        case Item::Dot:
            body += QStringLiteral("  \\fill[%1] %2 circle[radius=2pt]").arg(colourName(item.color), coord(item.points[0]));
            if (!item.text.isEmpty())
                body += QStringLiteral(" node[above right] {$%1$}").arg(item.text);
            body += QStringLiteral(";\n");
            break;
        }
    }
    QString out = QStringLiteral("%% Made with Granota. Needs \\usepackage{tikz}.\n");
    for (auto it = colours.cbegin(); it != colours.cend(); ++it)
        out += QStringLiteral("\\definecolor{%1}{HTML}{%2}\n").arg(it.key(), it.value());
    out += QStringLiteral("\\begin{tikzpicture}[x=%1cm, y=%1cm]\n").arg(scale, 0, 'g', 6);
    out += body;
    out += QStringLiteral("\\end{tikzpicture}\n");
    return out;
}

} // namespace granota::ui
