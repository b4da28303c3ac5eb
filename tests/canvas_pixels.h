#pragma once
// The pixels of a canvas as every export draws them (Drawable::render into an image of the
// canvas's size on white), and a colour comparison that forgives antialiasing: what the GUI
// tests that look for a point, a handle or a line at a model position compare.
#include "ui/common/drawable.h"

#include <QColor>
#include <QImage>
#include <QPainter>
#include <QWidget>

#include <cstdlib>

/// `canvas` rendered at its size on screen.
template <class Canvas> QImage renderedPixels(Canvas* canvas)
{
    QImage image(canvas->size(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    canvas->render(painter, QRectF(image.rect()));
    return image;
}

/// Whether `a` and `b` differ by less than `tolerance` in the sum of their RGB channels.
inline bool nearColour(const QColor& a, const QColor& b, int tolerance)
{
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) < tolerance;
}
