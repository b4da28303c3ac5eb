#pragma once
/// \file tikz_writer.h
/// A TikZ picture for LaTeX slides (docs/tabs.md): polylines, cubic Bézier paths, points and labels that a tab
/// adds in model coordinates; str() lays them out at the size TikzOptions asks for (the
/// width, labels included, and at most the height), with optional axes and grid, and writes
/// them in centimetres, always with a decimal point (docs/numbers-and-locales.md).
/// Items added between beginInset() and endInset() form an inset instead: a small framed
/// picture of their own, with their own scale, in the lower right corner (as the De Casteljau
/// tab draws its hodograph).

#include "core/base/vec2.h"
#include "ui/shell/tikz_options.h"

#include <QColor>
#include <QString>

#include <array>
#include <vector>

namespace granota::ui {

class TikzWriter {
public:
    explicit TikzWriter(const TikzOptions& options = TikzOptions()) : m_options(options) {}

    void polyline(const std::vector<Point>& points, const QColor& color, double widthPt = 1.0, bool dashed = false,
                  bool closed = false);
    /// Cubic Bézier segments b_0..b_3 as one path `(b_0) .. controls (b_1) and (b_2) .. (b_3)`,
    /// each segment continuing from the previous one's end (a new start where it does not
    /// meet it). The picture's extent is the curve's (its extreme points), not the control
    /// polygon's. Segments with a point that is not finite are left out.
    void bezierSegments(const std::vector<std::array<Point, 4>>& segments, const QColor& color, double widthPt = 1.0,
                        bool dashed = false);
    /// A dot, labelled above right by `label`, which is TeX math ("P_{0}", without $).
    void point(Point p, const QColor& color, const QString& label = QString());
    void comment(const QString& text);

    /// What follows, up to endInset(), is drawn in the inset: a white framed box in the
    /// picture's lower right corner, kInsetShare of its width wide, titled `title` (TeX text),
    /// with its own scale that fits its items and the origin, and the axes through the origin.
    /// The inset's items take no room in the main picture's layout. One inset per picture.
    void beginInset(const QString& title);
    void endInset();
    static constexpr double kInsetShare = 0.3;

    /// The whole `tikzpicture` environment, with the colours defined.
    QString str() const;

private:
    struct Item {
        enum Kind { Line, Dot, Comment, Bezier } kind;
        std::vector<Point> points; ///< Bezier: four per segment, b_0..b_3
        QColor color;
        double width = 1.0;
        bool dashed = false, closed = false;
        QString text;
        bool inset = false;
        std::vector<Point> extent; ///< Bezier: the points the picture must hold
    };
    TikzOptions m_options;
    std::vector<Item> m_items;
    bool m_inInset = false;
    QString m_insetTitle;
};

} // namespace granota::ui
