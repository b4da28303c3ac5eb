#pragma once
/// \file tikz_writer.h
/// A TikZ picture for LaTeX slides (docs/tabs.md): polylines, cubic Bézier paths, points and labels that a tab
/// adds in model coordinates; str() lays them out at the size TikzOptions asks for (the
/// width, labels included, and at most the height), with optional axes and grid, and writes
/// them in centimetres, always with a decimal point (docs/numbers-and-locales.md).
/// Items added between beginInset() and endInset() form an inset instead: a small framed
/// picture of their own, with their own scale, in the corner of the drawing where it covers
/// least of the picture (as the De Casteljau tab draws its hodograph). A key (legend()) goes
/// where it covers least too, clear of the inset, as canvasLegendRect() places the canvas's.

#include "core/base/vec2.h"
#include "ui/files/tikz_options.h"

#include <QColor>
#include <QString>
#include <Qt>

#include <array>
#include <vector>

namespace granota::ui {

/// One line of a picture's key: a swatch in `color` and `pen` (Qt::NoPen: none, the text
/// in the key's alert colour), and `text`, TeX text (TikzWriter::texText of what the canvas says).
struct TikzLegendEntry {
    QColor color;
    Qt::PenStyle pen = Qt::SolidLine;
    QString text;
};

class TikzWriter {
public:
    explicit TikzWriter(const TikzOptions& options = TikzOptions()) : m_options(options) {}

    void polyline(const std::vector<Point>& points, const QColor& color, double widthPt = 1.0, bool dashed = false,
                  bool closed = false);
    /// The same in one of Qt's line styles (dashed, dotted, dash-dotted), as the canvas draws it.
    void polyline(const std::vector<Point>& points, const QColor& color, double widthPt, Qt::PenStyle pen, bool closed = false);
    /// A closed polygon filled with `fill` and outlined in `stroke` (no outline when invalid).
    void polygon(const std::vector<Point>& points, const QColor& stroke, const QColor& fill, double widthPt = 1.0);
    /// An arrow from `from` to `to`, its filled head at `to` (as the canvas draws vectors).
    void arrow(Point from, Point to, const QColor& color, double widthPt = 1.0);
    /// Cubic Bézier segments b_0..b_3 as one path `(b_0) .. controls (b_1) and (b_2) .. (b_3)`,
    /// each segment continuing from the previous one's end (a new start where it does not
    /// meet it). The picture's extent is the curve's (its extreme points), not the control
    /// polygon's. Segments with a point that is not finite are left out.
    void bezierSegments(const std::vector<std::array<Point, 4>>& segments, const QColor& color, double widthPt = 1.0,
                        bool dashed = false);
    /// A dot, labelled above right by `label`, which is TeX math ("P_{0}", without $).
    void point(Point p, const QColor& color, const QString& label = QString());
    void comment(const QString& text);
    /// What is drawn afterwards in the main picture is clipped to the rectangle [lo, hi] (the
    /// frog's frame, as its canvas clips to the scene), which also bounds the picture.
    void clipTo(Point lo, Point hi);

    /// The key: a white framed box, one line per entry and `note` (TeX text) under them,
    /// in \scriptsize, in the place of the drawing where it covers least (the corners first,
    /// the top left winning a tie, then along the edges), clear of the inset; left out, with
    /// a comment, when it is larger than the drawing (a picture a few cm wide).
    void legend(const std::vector<TikzLegendEntry>& entries, const QString& note = QString(),
                const QColor& alertColor = QColor(0xb0, 0x30, 0x20));
    /// `text` as TeX reads it literally (its special characters escaped), with the symbols the
    /// canvas writes (τ, κ, ′, ², −, …) in math mode.
    static QString texText(const QString& text);

    /// What follows, up to endInset(), is drawn in the inset: a white framed box in the
    /// corner of the drawing that covers least of it (the lower right winning a tie, then the
    /// lower left, upper right, upper left), kInsetShare of its width wide, titled `title` (TeX text),
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
        Qt::PenStyle pen = Qt::SolidLine;
        bool closed = false;
        QString text;
        bool inset = false;
        std::vector<Point> extent; ///< Bezier: the points the picture must hold
        QColor fill;               ///< Line, closed: its fill (invalid: none)
        bool arrow = false;        ///< Line: an arrowhead at its end
        bool clipped = false;      ///< drawn inside the clip rectangle
    };
    TikzOptions m_options;
    std::vector<Item> m_items;
    bool m_inInset = false;
    QString m_insetTitle;
    bool m_clip = false;
    Point m_clipLo, m_clipHi;
    std::vector<TikzLegendEntry> m_legend;
    QString m_legendNote;
    QColor m_legendAlert;
};

} // namespace granota::ui
