#pragma once
/// \file frog_overlay_painter.h
/// What the Frog canvas draws over the scene, on screen and in every export: the body the plots
/// show alone, the ghost of the other solver, the trail, the broad phase's pairs (§5.2.2), the
/// vertices, springs and velocities (§4.1–4.4), the protractor (§4.15), the ruler, and the
/// text panel of readouts with the area bar (§4.5). Its buffers are reused: a frame allocates
/// nothing here once warm.

#include "core/base/vec2.h"
#include "core/softbody/link_angles.h"
#include "ui/frog/frog_overlays.h"

#include <QBrush>
#include <QFont>
#include <QLineF>
#include <QPainterPath>
#include <QPen>
#include <QRectF>
#include <QSizeF>
#include <QStaticText>
#include <QStringList>

#include <optional>
#include <utility>
#include <vector>

class QPainter;

namespace granota {
class Simulation;
}

namespace granota::ui {

class FrogArt;
class FrogRun;

class FrogOverlayPainter {
public:
    /// What is drawn over the scene (the tab's Overlays check boxes; frog_overlays.h).
    using Overlays = FrogOverlays;
    /// One frame's overlays: the run they show and what the view adds to it.
    struct Frame {
        const FrogRun& run;
        const Overlays& overlays;
        const FrogArt& art;
        int markedBody = -1; ///< the body the plots show alone, −1 none
        const std::optional<std::pair<Point, Point>>& ruler;
        QString rulerText; ///< what the ruler says (FrogCanvas::rulerText)
        QSizeF bounds;     ///< the widget: the ruler's label stays inside it
        bool textPanel = true;
    };
    /// The text panel: from the frame's corner, and inside it, px (× presentation scale).
    static constexpr double kPanelMargin = 8;
    static constexpr double kPanelPad = 6;

    FrogOverlayPainter();

    /// The pens, brushes and fonts at a presentation scale: `labelFont` for the text panel,
    /// `widgetFont` the family of the numbers.
    void setStyle(double scale, const QFont& labelFont, const QFont& widgetFont);
    const QFont& numberFont() const { return m_numberFont; }

    /// Draws `f` over the scene of `frame` (the scene's rectangle on the device), then the
    /// text panel in its corner, clipped to `target` (it may run below a small scene).
    void draw(QPainter& p, const Frame& f, const QRectF& frame, const QRectF& target);

    /// The text panel's lines, laid out in the label font: each wrapped at `room` px when
    /// wider, the first always when `wrapFirst` (a line that must be read whole).
    void setLines(const QStringList& lines, double room, bool wrapFirst);
    QStringList lines() const;
    double linesWidth() const;
    /// The trail's segments the last draw drew: those in the frame, cut to it, the newest
    /// first up to kTrailInkBudget times the frame's width plus height of line.
    int trailSegmentsDrawn() const { return m_trailSegmentsDrawn; }

private:
    void drawMarkedBody(QPainter& p, const Simulation& sim, int body, double pixel);
    void drawGhost(QPainter& p, const Simulation& ghost);
    void drawTrail(QPainter& p, const Simulation& sim, const FrogRun& run);
    void drawPairs(QPainter& p, const Simulation& sim);
    void drawPoints(QPainter& p, const Frame& f, const Simulation& sim, double pixel);
    void drawProtractor(QPainter& p, const Simulation& sim, double pixel);
    void drawRuler(QPainter& p, const Frame& f, double pixel);
    void drawTextPanel(QPainter& p, const Frame& f, const Simulation& sim, const QRectF& frame);

    double m_scale = 1;
    std::vector<Point> m_vertices, m_joints, m_work;
    QPainterPath m_path;
    std::vector<std::pair<int, int>> m_pairs;
    std::vector<LinkAngleReading> m_angles;
    struct ProtractorLabel {
        QPointF at;
        QString text;
        bool atLimit = false;
    };
    std::vector<ProtractorLabel> m_protractorLabels; // kept for their capacity
    std::vector<QRectF> m_protractorBoxes;
    std::vector<QLineF> m_trailLines;
    int m_trailSegmentsDrawn = 0;
    std::vector<QStaticText> m_lines;
    std::vector<QString> m_numbers; ///< "0", "1", … for the vertex overlay, made once
    QPen m_edgePen, m_velocityPen, m_ringPen, m_numberPen, m_markPen;
    QBrush m_panelBrush, m_trackBrush, m_goodBrush, m_offBrush, m_jointDotBrush;
    QFont m_font, m_numberFont;
};

} // namespace granota::ui
