#pragma once
/// \file frog_art_view.h
/// The frog's art alone, as the thesis shows its two images (Fig 4.11, the head; Fig 4.12,
/// the background): a Drawable for the figure exports (ui/shell/thesis_figure_export.h).

#include "ui/common/drawable.h"
#include "ui/frog/frog_art.h"

namespace granota::ui {

class FrogArtView : public Drawable {
public:
    enum class Piece { Head, Background };
    explicit FrogArtView(Piece piece) : m_piece(piece) {}

    /// The head four times the thesis's 1109/8 × 747/8 px image; the background at the
    /// scenes' 1280 × 720 frame.
    QSizeF exportSize() const override;
    /// The piece centred in `target`, as large as fits, on white.
    void render(QPainter& painter, const QRectF& target) override;

private:
    Piece m_piece;
    FrogArt m_art;
};

} // namespace granota::ui
