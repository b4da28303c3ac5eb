#pragma once
/// \file tikz_writer.h
/// A TikZ picture for LaTeX slides (docs/tabs.md): polylines, points and labels that a tab
/// adds in model coordinates; str() lays them out at the size TikzOptions asks for (the
/// width, labels included, and at most the height), with optional axes and grid, and writes
/// them in centimetres, always with a decimal point (docs/numbers-and-locales.md).

#include "core/base/vec2.h"
#include "ui/shell/tikz_options.h"

#include <QColor>
#include <QString>

#include <vector>

namespace granota::ui {

class TikzWriter {
public:
    explicit TikzWriter(const TikzOptions& options = TikzOptions()) : m_options(options) {}

    void polyline(const std::vector<Point>& points, const QColor& color, double widthPt = 1.0, bool dashed = false,
                  bool closed = false);
    /// A dot, labelled above right by `label`, which is TeX math ("P_{0}", without $).
    void point(Point p, const QColor& color, const QString& label = QString());
    void comment(const QString& text);

    /// The whole `tikzpicture` environment, with the colours defined.
    QString str() const;

private:
    struct Item {
        enum Kind { Line, Dot, Comment } kind;
        std::vector<Point> points;
        QColor color;
        double width = 1.0;
        bool dashed = false, closed = false;
        QString text;
    };
    TikzOptions m_options;
    std::vector<Item> m_items;
};

} // namespace granota::ui
