#pragma once
/// \file tikz_writer.h
/// A TikZ picture for LaTeX slides (docs/tabs.md): polylines, points and labels in model
/// coordinates, scaled to a given width. Tabs add what they draw; str() is the file.

#include "core/base/vec2.h"

#include <QColor>
#include <QString>

#include <vector>

namespace granota::ui {

class TikzWriter {
public:
    /// `widthCm`: the picture's width on the slide; the scale follows from the content.
    explicit TikzWriter(double widthCm = 10.0) : m_widthCm(widthCm) {}

    void polyline(const std::vector<Point>& points, const QColor& color, double widthPt = 1.0, bool dashed = false,
                  bool closed = false);
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
    double m_widthCm;
    std::vector<Item> m_items;
};

} // namespace granota::ui
