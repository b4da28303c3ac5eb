#pragma once
/// \file frog_scene_painter.h
/// The frog's scene as the canvas paints it, on screen and in every export: the pond behind
/// it, the obstacles, then in Annex II's order (Granota.dibuixar) the back legs, the bodies,
/// the front legs and the head, or the pendulum's rods and joints (§4.14), in the scene's own
/// Processing pixels. A body's outline is the polygon, the seed's curveVertex outline, the
/// closed Catmull-Rom curve or the Bézier curve of §4.9 as the scene's components say. Its
/// buffers are reused: a frame allocates nothing here once warm.

#include "core/base/vec2.h"
#include "core/softbody/head_pose.h"
#include "ui/frog/frog_art.h"

#include <QElapsedTimer>
#include <QPainterPath>
#include <QPixmap>

#include <memory>
#include <optional>
#include <vector>

class QPainter;

namespace granota {
class OutlineFitter;
class Simulation;
} // namespace granota

namespace granota::ui {

/// `path` becomes the polyline through the finite points of `points` (closed if `close`),
/// filled by the winding rule.
void setPolylinePath(QPainterPath& path, const std::vector<Point>& points, bool close);

class FrogScenePainter {
public:
    /// §4.9/4.10: how a Bézier scene draws its body.
    enum class BezierOutline {
        Precomputed, ///< the thesis's choice: the body's vertices are the precomputed Bézier points
        Fit,         ///< the option it abandoned: a least-squares Bézier curve fitted every frame
    };
    /// The half width of a leg's outline (Annex II, Pota.dibuixar: the factor 7).
    static constexpr double kLegHalfWidth = 7;

    FrogScenePainter();
    ~FrogScenePainter();

    /// The presentation scale (the art's lines and the joints grow with it).
    void setScale(double scale);
    const FrogArt& art() const { return m_art; }
    void setBezierOutline(BezierOutline mode);
    BezierOutline bezierOutline() const { return m_bezier; }
    /// A new run: the fit starts again, its cost too, and the pond is painted again.
    void restart();

    /// Paints the pond into `frame` (the scene's rectangle on the device), then the scene of
    /// `sim` scaled into it; `onScreenDpr` > 0 keeps the pond as a pixmap at that device
    /// pixel ratio (the screen), 0 paints it as vectors (every export). The eyes look at
    /// `look` (scene px), straight down without one.
    void draw(QPainter& p, const Simulation& sim, const QRectF& frame, double onScreenDpr, std::optional<Point> look);

    /// The outline drawn for body `body`, in scene pixels. Valid until the next call.
    const std::vector<Point>& bodyOutline(const Simulation& sim, int body);
    /// The head of `body` as draw() paints it, in scene coordinates (the TikZ picture
    /// records it as paths).
    void paintHead(QPainter& p, const Simulation& sim, int body, std::optional<Point> look);
    /// Where the head of `body` is drawn (head_pose.h): on the seed solver as Annex II draws
    /// it, upright; on the stable solver Granota's head, turned with the body.
    HeadPose headPose(const Simulation& sim, int body);

    /// The least-squares fit's cost, µs a frame: averageFitCost() averages what was measured
    /// since its last call (fitMicroseconds() keeps the last average, 0 before any).
    void averageFitCost();
    double fitMicroseconds() const { return m_fitShownUs; }
    /// The fit of the last frame (null before any, or with the Bézier points precomputed).
    const OutlineFitter* fitter() const { return m_fitter.get(); }

private:
    void drawBackground(QPainter& p, const QRectF& frame, double W, double H, double onScreenDpr);
    void drawBody(QPainter& p, const Simulation& sim, int body, double pixel, std::optional<Point> look);
    /// The head of `body` over m_vertices (its vertices).
    void drawHead(QPainter& p, const Simulation& sim, int body, std::optional<Point> look);
    void drawLeg(QPainter& p, const Simulation& sim, int chain);
    void drawPendulum(QPainter& p, const Simulation& sim);
    void drawObstacles(QPainter& p, const Simulation& sim);

    FrogArt m_art;
    double m_scale = 1;
    BezierOutline m_bezier = BezierOutline::Precomputed;
    std::vector<Point> m_vertices, m_outline, m_joints, m_fitControl, m_fitCurve, m_work;
    QPainterPath m_path;
    std::unique_ptr<OutlineFitter> m_fitter;
    QElapsedTimer m_clock;
    double m_fitNsSum = 0, m_fitShownUs = 0;
    int m_fits = 0;
    // The pond, cached for the screen at the size last drawn.
    QPixmap m_background;
    QSize m_backgroundSize;
};

} // namespace granota::ui
