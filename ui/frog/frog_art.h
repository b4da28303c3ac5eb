#pragma once
/// \file frog_art.h
/// The frog lab's own art (the thesis's panta.png and cap_granota.png are not available,
/// docs/scenes.md): a pond background, the frog's head with eyes and mouth, webbed feet, and the
/// colours of bodies, obstacles and pendulums. Everything is painted with QPainter in scene
/// coordinates (Processing pixels, y down); the paths are built once, so painting a frame
/// allocates nothing here.

#include <QBrush>
#include <QColor>
#include <QImage>
#include <QPainterPath>
#include <QPen>

#include <map>

class QPainter;

namespace granota::ui {

class FrogArt {
public:
    FrogArt();

    /// The pond: sky, hills, water with lily pads, reeds and the muddy bank the frog lands on
    /// (the frame's floor is the bottom edge). Sized to the scene's width × height.
    void paintBackground(QPainter& painter, double width, double height) const;

    /// The head centred on `at` (the body's vertex 0, as Annex II places cap_granota.png),
    /// turned by `angle` (radians), `scale` 1 for the thesis's 1109/8 × 747/8 px image; the
    /// pupils look towards `lookAt` (scene coordinates). A head smaller than
    /// kHeadImageBelowPx on a raster device (a crowd of small bodies) is drawn from an image
    /// of it made once per size, with only the pupils painted per frame; vector devices (SVG,
    /// PDF) always get paths.
    void paintHead(QPainter& painter, QPointF at, double angle, double scale, QPointF lookAt) const;
    /// On-screen head width (px) below which paintHead draws from the cached image.
    static constexpr double kHeadImageBelowPx = 72;
    /// A webbed foot at the wrist, toes along `angle` (the direction of the lower bone).
    void paintFoot(QPainter& painter, QPointF wrist, double angle, double scale) const;

    /// The web (its lines) and the toes (their outlines) of the foot paintFoot draws, in
    /// scene coordinates: for a picture drawn without a QPainter (TikZ).
    QPainterPath footWeb(QPointF wrist, double angle, double scale) const;
    QPainterPath footToes(QPointF wrist, double angle, double scale) const;
    const QPen& footEdgePen() const { return m_footEdgePen; }
    const QPen& footWebPen() const { return m_footWebPen; }
    QColor toeColour() const { return m_toeBrush.color(); }

    /// Skin of body `index` (the seed's fill(48, 161, 48), a shade lighter or darker for
    /// neighbours), shaded top to bottom.
    const QBrush& skin(int index) const;
    /// Its colour without the shading (the middle of the gradient).
    static QColor skinColour(int index);
    /// The stones' colour without the shading.
    static QColor stoneColour();

    /// Pens and brushes, made once per line scale (presentation mode thickens them) so that
    /// a frame only uses them. Widths are in scene pixels.
    void setLineScale(double scale);
    const QPen& bodyPen() const { return m_bodyPen; } ///< Annex II's strokeWeight(4), dark green
    const QPen& legPen() const { return m_legPen; }
    const QPen& inkPen() const { return m_inkPen; } ///< §4.1–4.7: the bare polygon of line()
    const QPen& rodPen() const { return m_rodPen; }
    const QPen& jointPen() const { return m_jointPen; }
    const QBrush& jointBrush() const { return m_jointBrush; }
    const QBrush& pinBrush() const { return m_pinBrush; }
    const QBrush& whiteBrush() const { return m_whiteBrush; }
    const QBrush& stoneBrush() const { return m_stone; }
    const QPen& stonePen() const { return m_stonePen; }
    const QPen& logPen() const { return m_logPen; }
    const QPen& logHighlightPen() const { return m_logHighlightPen; }

private:
    QBrush m_skins[4];
    QBrush m_stone, m_jointBrush, m_pinBrush, m_whiteBrush;
    QPen m_bodyPen, m_legPen, m_inkPen, m_rodPen, m_jointPen, m_stonePen, m_logPen, m_logHighlightPen;
    // The head and the feet, in their own frame.
    QPen m_headPen, m_eyePen, m_mouthPen, m_footEdgePen, m_footWebPen, m_toePen;
    QBrush m_cheekBrush, m_eyeWhiteBrush, m_pupilBrush, m_glintBrush, m_outlineBrush, m_toeBrush;
    QPainterPath m_head, m_mouth, m_nostrils, m_cheeks, m_eyeWhites, m_foot, m_footWeb;
    // The head without its pupils, by size: key = device pixels per head unit × 32.
    mutable std::map<int, QImage> m_headImages;
    void paintHeadStill(QPainter& painter) const; // head, cheeks, eye whites, nostrils, mouth
    void paintPupils(QPainter& painter, QPointF mouse, bool glints) const;
    const QImage& headImage(int key) const;
};

} // namespace granota::ui
