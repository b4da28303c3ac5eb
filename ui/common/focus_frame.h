#pragma once
/// \file focus_frame.h
/// The frame a canvas draws round itself on screen while it has the keyboard focus, so that
/// someone driving Granota with a keyboard or a projector remote sees where the keys go
/// (docs/classroom.md, "Keyboard"). Exports never draw it.

class QPainter;
class QPalette;
class QRectF;

namespace granota::ui {

/// A frame in the palette's highlight colour, 3 px wide (× scale), just inside `rect`.
void drawFocusFrame(QPainter& painter, const QRectF& rect, const QPalette& palette, double scale);

} // namespace granota::ui
