#pragma once
/// \file curve_canvas.h
/// A QPainter canvas in model coordinates: paper, grid and axes, then the layers a tab adds
/// (curves, constructions, handles). Pan with a drag on empty paper or the middle button,
/// zoom with the wheel. While it has the focus it draws a focus frame (focus_frame.h) on
/// screen. The same render() draws the screen and every export.

#include "ui/common/canvas_style.h"
#include "ui/common/drawable.h"
#include "ui/common/view_transform.h"

#include <QWidget>

class QFontMetricsF;

#include <functional>
#include <vector>

namespace granota::ui {

class CurveCanvas : public QWidget, public Drawable {
    Q_OBJECT
public:
    /// A layer draws in widget pixels through the view transform.
    using Layer = std::function<void(QPainter&, const ViewTransform&, const CanvasStyle&)>;

    explicit CurveCanvas(QWidget* parent = nullptr);

    /// Layers are drawn in the order added, after the grid.
    void addLayer(Layer layer);
    /// Overlays are drawn after every layer, in the order added: a key or an inset stays clear
    /// of the handles and labels that the point editor's layer draws last.
    void addOverlay(Layer overlay);

    ViewTransform& view() { return m_view; }
    const ViewTransform& view() const { return m_view; }
    const CanvasStyle& style() const { return m_style; }
    /// Presentation mode: thicker lines, larger handles and labels.
    void setStyleScale(double scale);

    /// The model rectangle the content occupies; the view fits it until the user pans or zooms.
    void setContentBounds(const QRectF& modelBounds);
    /// Fits the view to the content again (View ▸ Fit, or after loading).
    void fitToContent();
    void zoom(double factor);
    /// The extent of what is drawn now (the points as they are edited), without refitting the
    /// view: it only decides whether the content can be drawn (contentDrawable()).
    void setDataExtent(const QRectF& modelBounds);
    /// Whether the content can be drawn at all: its extent is finite and within what the view
    /// can show (kMaxDrawableSpan). Control points near ±1e308 cannot: the canvas then shows
    /// notice() instead of a blank or a wrong picture.
    bool contentDrawable() const;
    /// The text shown instead of the drawing when the content cannot be drawn; empty otherwise.
    QString notice() const;
    /// The widest span of content the canvas draws: the smallest scale over a large screen.
    static constexpr double kMaxDrawableSpan = 1e12;
    bool gridVisible() const { return m_gridVisible; }
    void setGridVisible(bool on);

    QSizeF exportSize() const override { return size(); }
    void render(QPainter& painter, const QRectF& target) override;

    /// A label of the grid's axes, as drawn: its text, where its baseline starts and its box
    /// (widget pixels). Only labels wholly inside the viewport are drawn.
    struct GridLabel {
        QString text;
        QPointF baseline;
        QRectF box;
    };
    /// The grid's labels in the canvas's view, with the font they are drawn in.
    std::vector<GridLabel> gridLabels() const;

    QSize sizeHint() const override { return {640, 480}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

signals:
    /// The mouse moved over the canvas: its model position (for the status bar).
    void cursorMoved(double x, double y);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    void drawGrid(QPainter& painter, const ViewTransform& view) const;
    std::vector<GridLabel> gridLabels(const ViewTransform& view, const QFontMetricsF& metrics) const;

    ViewTransform m_view;
    CanvasStyle m_style;
    std::vector<Layer> m_layers;
    std::vector<Layer> m_overlays;
    QRectF m_content{-1, -1, 2, 2};
    QRectF m_dataExtent{-1, -1, 2, 2};
    bool m_userMoved = false; ///< once the user pans or zooms, new content no longer refits
    bool m_gridVisible = true;
    bool m_panning = false;
    QPointF m_lastMouse;
};

} // namespace granota::ui
