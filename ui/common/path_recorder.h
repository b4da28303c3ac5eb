#pragma once
/// \file path_recorder.h
/// A paint device that keeps what is painted on it as filled and stroked paths, in the
/// device's coordinates, with the colour of each: the TikZ and CSV of a drawing that exists
/// only as QPainter calls (the frog's art, Figs 4.11 and 4.12). Text and images are not kept.

#include <QColor>
#include <QPaintDevice>
#include <QPainterPath>

#include <memory>
#include <vector>

namespace granota::ui {

class PathRecorder : public QPaintDevice {
public:
    struct Shape {
        QPainterPath path; ///< device coordinates
        QColor fill;       ///< invalid: not filled (a gradient gives its first colour)
        QColor stroke;     ///< invalid: not stroked
        double strokeWidth = 0;
    };

    explicit PathRecorder(QSize size);
    ~PathRecorder() override;

    const std::vector<Shape>& shapes() const { return m_shapes; }
    QPaintEngine* paintEngine() const override;

protected:
    int metric(PaintDeviceMetric metric) const override;

private:
    class Engine;
    friend class Engine;
    QSize m_size;
    std::vector<Shape> m_shapes;
    std::unique_ptr<Engine> m_engine;
};

} // namespace granota::ui
