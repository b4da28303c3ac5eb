#pragma once
/// \file drawable.h
/// Anything that draws itself with one `render(QPainter&, rect)`: the screen and every
/// export (PNG, SVG, PDF) go through the same call, so what is exported is what is seen.

#include <QRectF>
#include <QSizeF>

class QPainter;

namespace granota::ui {

class Drawable {
public:
    virtual ~Drawable() = default;
    /// The logical size (device-independent pixels) an export uses by default: the view's size on screen.
    virtual QSizeF exportSize() const = 0;
    /// Draws the whole view into `target` (logical coordinates of the painter).
    virtual void render(QPainter& painter, const QRectF& target) = 0;
};

} // namespace granota::ui
