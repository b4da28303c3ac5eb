#include "ui/common/path_recorder.h"

#include <QGradient>

#include <cmath>
#include <QPaintEngine>

namespace granota::ui {

class PathRecorder::Engine : public QPaintEngine {
public:
    explicit Engine(PathRecorder* device) : QPaintEngine(AllFeatures), m_device(device) {}
    bool begin(QPaintDevice*) override { return true; }
    bool end() override { return true; }
    Type type() const override { return User; }
    void updateState(const QPaintEngineState& state) override
    {
        if (state.state() & DirtyTransform)
            m_transform = state.transform();
        if (state.state() & DirtyPen)
            m_pen = state.pen();
        if (state.state() & DirtyBrush)
            m_brush = state.brush();
        if (state.state() & DirtyClipPath || state.state() & DirtyClipRegion || state.state() & DirtyClipEnabled) {
            // Clipping is not kept: the art paints inside its own frame.
        }
    }
    void drawPath(const QPainterPath& path) override { keep(path); }
    void drawPolygon(const QPointF* points, int count, PolygonDrawMode mode) override
    {
        QPainterPath path;
        path.addPolygon(QPolygonF(QVector<QPointF>(points, points + count)));
        if (mode != PolylineMode)
            path.closeSubpath();
        keep(path, mode == PolylineMode);
    }
    void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {} // images are not kept

private:
    static QColor colourOf(const QBrush& brush)
    {
        if (brush.style() == Qt::NoBrush)
            return {};
        if (const QGradient* g = brush.gradient(); g && !g->stops().isEmpty())
            return g->stops().front().second;
        return brush.color();
    }
    void keep(const QPainterPath& path, bool strokeOnly = false)
    {
        Shape shape;
        shape.path = m_transform.map(path);
        if (!strokeOnly)
            shape.fill = colourOf(m_brush);
        if (m_pen.style() != Qt::NoPen) {
            shape.stroke = colourOf(m_pen.brush());
            // A cosmetic pen is as wide on the device whatever the transform.
            shape.strokeWidth = m_pen.isCosmetic() ? m_pen.widthF()
                                                   : m_pen.widthF() * std::sqrt(std::abs(m_transform.determinant()));
        }
        if (shape.fill.isValid() || shape.stroke.isValid())
            m_device->m_shapes.push_back(std::move(shape));
    }

    PathRecorder* m_device;
    QTransform m_transform;
    QPen m_pen;
    QBrush m_brush;
};

PathRecorder::PathRecorder(QSize size) : m_size(size), m_engine(std::make_unique<Engine>(this)) {}

PathRecorder::~PathRecorder() = default;

QPaintEngine* PathRecorder::paintEngine() const { return m_engine.get(); }

int PathRecorder::metric(PaintDeviceMetric metric) const
{
    switch (metric) {
    case PdmWidth: return m_size.width();
    case PdmHeight: return m_size.height();
    case PdmDpiX:
    case PdmDpiY:
    case PdmPhysicalDpiX:
    case PdmPhysicalDpiY: return 96;
    case PdmDevicePixelRatio: return 1;
    case PdmDevicePixelRatioScaled: return static_cast<int>(devicePixelRatioFScale());
    case PdmDepth: return 32;
    case PdmNumColors: return 0x7fffffff;
    case PdmWidthMM: return static_cast<int>(m_size.width() * 25.4 / 96);
    case PdmHeightMM: return static_cast<int>(m_size.height() * 25.4 / 96);
    }
    return 0;
}

} // namespace granota::ui
