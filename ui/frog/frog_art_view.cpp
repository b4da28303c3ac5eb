#include "ui/frog/frog_art_view.h"

#include <QPainter>

#include <algorithm>

namespace granota::ui {

namespace {
// The thesis's image box of the head (cap_granota.png, drawn at 1/8 of its 1109 × 747 px).
constexpr double kHeadWidth = 1109.0 / 8, kHeadHeight = 747.0 / 8;
constexpr double kHeadZoom = 4;
// The frame of the scenes of chapter 4 (core/softbody/scenes/frog_params.h).
constexpr double kFrameWidth = 1280, kFrameHeight = 720;
} // namespace

QSizeF FrogArtView::exportSize() const
{
    if (m_piece == Piece::Head)
        return {kHeadWidth * kHeadZoom, kHeadHeight * kHeadZoom};
    return {kFrameWidth, kFrameHeight};
}

void FrogArtView::render(QPainter& painter, const QRectF& target)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.fillRect(target, Qt::white);
    const QSizeF natural = m_piece == Piece::Head ? QSizeF(kHeadWidth, kHeadHeight) : QSizeF(kFrameWidth, kFrameHeight);
    const double scale = std::min(target.width() / natural.width(), target.height() / natural.height());
    painter.translate(target.center());
    painter.scale(scale, scale);
    if (m_piece == Piece::Head) {
        // Centred on its anchor (the body's vertex 0), not turned, the pupils looking ahead.
        m_art.paintHead(painter, QPointF(0, 0), 0, 1, QPointF(0, kHeadHeight));
    } else {
        painter.translate(-kFrameWidth / 2, -kFrameHeight / 2);
        m_art.paintBackground(painter, kFrameWidth, kFrameHeight);
    }
    painter.restore();
}

} // namespace granota::ui
