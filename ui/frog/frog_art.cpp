#include "ui/frog/frog_art.h"
#include "core/base/math_constants.h"

#include <QLinearGradient>
#include <QPaintEngine>
#include <QPainter>
#include <QRadialGradient>
#include <QTransform>

#include <algorithm>
#include <array>
#include <cmath>

namespace granota::ui {

namespace {

// The seed's body colour, fill(48, 161, 48) (Annex II, Poligon.dibuixar and Pota.dibuixar).
const QColor kSeedGreen(48, 161, 48);
const QColor kOutline(22, 66, 30);
// Each body's skin: the seed's green and three neighbouring shades.
const std::array<QColor, 4> kSkins = {kSeedGreen, QColor(70, 150, 40), QColor(36, 140, 70), QColor(90, 165, 55)};
const QColor kStoneLight(0xa8, 0xa0, 0x92), kStoneDark(0x74, 0x6c, 0x60);

/// `path` (drawn along +x from the origin) at the wrist, turned by `angle`, scaled.
QTransform footTransform(QPointF wrist, double angle, double scale)
{
    QTransform t;
    t.translate(wrist.x(), wrist.y());
    t.rotate(angle * 180 / kPi);
    t.scale(scale, scale);
    return t;
}

QBrush shadedSkin(const QColor& base)
{
    // In object bounding mode the gradient follows each shape's bounding box: no per-frame work.
    QLinearGradient g(0, 0, 0, 1);
    g.setCoordinateMode(QGradient::ObjectBoundingMode);
    g.setColorAt(0, base.lighter(122));
    g.setColorAt(0.55, base);
    g.setColorAt(1, base.darker(118));
    return QBrush(g);
}

} // namespace

FrogArt::FrogArt()
{
    for (std::size_t i = 0; i < kSkins.size(); ++i)
        m_skins[i] = shadedSkin(kSkins[i]);

    QLinearGradient stone(0, 0, 0, 1);
    stone.setCoordinateMode(QGradient::ObjectBoundingMode);
    stone.setColorAt(0, kStoneLight);
    stone.setColorAt(1, kStoneDark);
    m_stone = QBrush(stone);
    m_jointBrush = QBrush(QColor(0xf2, 0xb1, 0x34));
    m_pinBrush = QBrush(QColor(0x37, 0x47, 0x4f));
    m_whiteBrush = QBrush(Qt::white);
    setLineScale(1);

    m_headPen = QPen(kOutline, 3, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    m_eyePen = QPen(QColor(0x22, 0x33, 0x22), 1.6);
    m_mouthPen = QPen(kOutline, 3, Qt::SolidLine, Qt::RoundCap);
    m_footEdgePen = QPen(kOutline, 6.5, Qt::SolidLine, Qt::RoundCap);
    m_footWebPen = QPen(kSeedGreen.darker(108), 3.8, Qt::SolidLine, Qt::RoundCap);
    m_toePen = QPen(kOutline, 1.5);
    m_cheekBrush = QBrush(QColor(0xf0, 0x8f, 0x9a, 80));
    m_eyeWhiteBrush = QBrush(QColor(0xfd, 0xfd, 0xf4));
    m_pupilBrush = QBrush(QColor(0x16, 0x1c, 0x16));
    m_glintBrush = QBrush(QColor(255, 255, 255, 230));
    m_outlineBrush = QBrush(kOutline);
    m_toeBrush = QBrush(kSeedGreen.lighter(110));

    // The head, in the thesis's image box 1109/8 × 747/8 px centred on vertex 0: a wide
    // rounded head with two eye bumps on top.
    QPainterPath face;
    face.addEllipse(QPointF(0, 6), 62, 34);
    QPainterPath bumps;
    bumps.addEllipse(QPointF(-34, -20), 24, 23);
    bumps.addEllipse(QPointF(34, -20), 24, 23);
    m_head = face.united(bumps);

    m_eyeWhites.addEllipse(QPointF(-34, -21), 16, 15);
    m_eyeWhites.addEllipse(QPointF(34, -21), 16, 15);

    m_mouth.moveTo(-42, 16);
    m_mouth.cubicTo(-20, 33, 20, 33, 42, 16);

    m_nostrils.addEllipse(QPointF(-8, 1), 2.4, 1.8);
    m_nostrils.addEllipse(QPointF(8, 1), 2.4, 1.8);
    m_cheeks.addEllipse(QPointF(-44, 17), 9, 5.5);
    m_cheeks.addEllipse(QPointF(44, 17), 9, 5.5);

    // A foot pointing along +x from the wrist: three toes with round tips, webbed.
    for (double a : {-0.62, 0.0, 0.62}) {
        const QPointF tip(17 * std::cos(a), 17 * std::sin(a));
        m_foot.addEllipse(tip, 3.6, 3.6);
        m_footWeb.moveTo(0, 0);
        m_footWeb.lineTo(tip);
    }
    m_footWeb.moveTo(17 * std::cos(-0.62), 17 * std::sin(-0.62));
    m_footWeb.quadTo(8, 0, 17 * std::cos(0.62), 17 * std::sin(0.62));
}

const QBrush& FrogArt::skin(int index) const { return m_skins[((index % 4) + 4) % 4]; }

QColor FrogArt::skinColour(int index) { return kSkins[static_cast<std::size_t>(((index % 4) + 4) % 4)]; }

QColor FrogArt::stoneColour()
{
    return QColor((kStoneLight.red() + kStoneDark.red()) / 2, (kStoneLight.green() + kStoneDark.green()) / 2,
                  (kStoneLight.blue() + kStoneDark.blue()) / 2);
}

QPainterPath FrogArt::footWeb(QPointF wrist, double angle, double scale) const
{
    return footTransform(wrist, angle, scale).map(m_footWeb);
}

QPainterPath FrogArt::footToes(QPointF wrist, double angle, double scale) const
{
    return footTransform(wrist, angle, scale).map(m_foot);
}

void FrogArt::setLineScale(double k)
{
    const auto pen = [](const QColor& c, double w, Qt::PenCapStyle cap = Qt::RoundCap) {
        return QPen(c, w, Qt::SolidLine, cap, Qt::RoundJoin);
    };
    m_bodyPen = pen(kOutline, 3.2 * k);
    m_legPen = pen(kOutline, 2.5 * k);
    m_inkPen = pen(QColor(0x1c, 0x2a, 0x33), 3 * k);
    m_rodPen = pen(QColor(0x37, 0x47, 0x4f), 7 * k);
    m_jointPen = pen(QColor(0x37, 0x47, 0x4f), 2.5 * k);
    m_stonePen = pen(QColor(0x4a, 0x45, 0x3e), 3 * k);
    m_logPen = pen(QColor(0x6e, 0x4b, 0x2c), 14 * k);
    m_logHighlightPen = pen(QColor(0x9b, 0x72, 0x49), 4 * k);
}

void FrogArt::paintBackground(QPainter& p, double W, double H) const
{
    p.save();
    p.setPen(Qt::NoPen);
    const auto X = [W](double f) { return f * W; };
    const auto Y = [H](double f) { return f * H; };

    // Sky.
    QLinearGradient sky(0, 0, 0, Y(0.62));
    sky.setColorAt(0, QColor(0xb9, 0xdc, 0xee));
    sky.setColorAt(1, QColor(0xee, 0xf5, 0xec));
    p.fillRect(QRectF(0, 0, W, Y(0.62)), sky);

    // Two soft clouds.
    p.setBrush(QColor(255, 255, 255, 170));
    for (const auto& c : {QPointF(0.17, 0.13), QPointF(0.70, 0.08)}) {
        const double r = Y(0.045);
        p.drawEllipse(QPointF(X(c.x()), Y(c.y())), 2.6 * r, r);
        p.drawEllipse(QPointF(X(c.x()) - 1.2 * r, Y(c.y()) + 0.2 * r), 1.5 * r, 0.8 * r);
        p.drawEllipse(QPointF(X(c.x()) + 0.9 * r, Y(c.y()) - 0.5 * r), 1.3 * r, 0.9 * r);
    }

    // Far hills, two layers: a ridge of two cubic arcs from the left edge at `start` to the
    // right edge, filled down to `base` (fractions of the size, as X and Y take them).
    const auto hill = [&](double start, const std::array<QPointF, 6>& ridge, double base, const QColor& colour) {
        QPainterPath path;
        path.moveTo(0, Y(start));
        path.cubicTo(X(ridge[0].x()), Y(ridge[0].y()), X(ridge[1].x()), Y(ridge[1].y()), X(ridge[2].x()), Y(ridge[2].y()));
        path.cubicTo(X(ridge[3].x()), Y(ridge[3].y()), X(ridge[4].x()), Y(ridge[4].y()), X(ridge[5].x()), Y(ridge[5].y()));
        path.lineTo(W, Y(base));
        path.lineTo(0, Y(base));
        path.closeSubpath();
        p.setBrush(colour);
        p.drawPath(path);
    };
    hill(0.56, {{{0.15, 0.44}, {0.30, 0.47}, {0.45, 0.53}, {0.60, 0.58}, {0.75, 0.42}, {1.0, 0.50}}}, 0.64,
         QColor(0xb7, 0xd3, 0xa8));
    hill(0.60, {{{0.20, 0.53}, {0.38, 0.60}, {0.55, 0.58}, {0.72, 0.56}, {0.86, 0.55}, {1.0, 0.59}}}, 0.66,
         QColor(0x96, 0xbf, 0x8a));

    // The pond.
    QLinearGradient water(0, Y(0.62), 0, Y(0.97));
    water.setColorAt(0, QColor(0x8c, 0xc2, 0xcf));
    water.setColorAt(1, QColor(0x5f, 0x9c, 0xae));
    p.fillRect(QRectF(0, Y(0.62), W, Y(0.36)), water);
    p.setBrush(Qt::NoBrush);
    QPen ripple(QColor(255, 255, 255, 90), std::max(1.0, Y(0.003)), Qt::SolidLine, Qt::RoundCap);
    p.setPen(ripple);
    for (const auto& r :
         {QPointF(0.12, 0.70), QPointF(0.42, 0.76), QPointF(0.80, 0.68), QPointF(0.63, 0.86), QPointF(0.25, 0.90)}) {
        const QRectF box(X(r.x()) - X(0.05), Y(r.y()) - Y(0.008), X(0.10), Y(0.016));
        p.drawArc(box, 20 * 16, 140 * 16);
    }

    // Lily pads: a disc with a notch, veins, and one flower.
    const QColor pad(0x3d, 0x80, 0x63), padEdge(0x2c, 0x5f, 0x4a);
    for (const auto& l : {QPointF(0.16, 0.78), QPointF(0.88, 0.75), QPointF(0.55, 0.70)}) {
        const QPointF c(X(l.x()), Y(l.y()));
        const double rx = X(0.045), ry = Y(0.028);
        p.setPen(QPen(padEdge, std::max(1.0, Y(0.003))));
        p.setBrush(pad);
        p.drawPie(QRectF(c.x() - rx, c.y() - ry, 2 * rx, 2 * ry), 110 * 16, 330 * 16);
        p.setPen(QPen(QColor(0x6f, 0xa8, 0x8b), std::max(1.0, Y(0.002))));
        p.drawLine(c, c + QPointF(-0.7 * rx, 0.5 * ry));
        p.drawLine(c, c + QPointF(0.75 * rx, 0.35 * ry));
        p.drawLine(c, c + QPointF(0.1 * rx, 0.85 * ry));
    }
    {
        const QPointF c(X(0.885), Y(0.742));
        const double r = Y(0.012);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0xf4, 0xb6, 0xc6));
        for (int k = 0; k < 6; ++k) {
            const double a = k * kPi / 3;
            p.drawEllipse(c + QPointF(1.2 * r * std::cos(a), 0.8 * r * std::sin(a)), r, 0.7 * r);
        }
        p.setBrush(QColor(0xf7, 0xd9, 0x6b));
        p.drawEllipse(c, 0.6 * r, 0.5 * r);
    }

    // Reeds and cattails at both sides.
    const auto reed = [&](double x, double top, double lean) {
        QPainterPath stem;
        stem.moveTo(X(x), Y(0.975));
        stem.quadTo(X(x), Y((top + 0.975) / 2), X(x + lean), Y(top));
        p.setPen(QPen(QColor(0x5b, 0x73, 0x3a), std::max(1.0, Y(0.005)), Qt::SolidLine, Qt::RoundCap));
        p.setBrush(Qt::NoBrush);
        p.drawPath(stem);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0x7a, 0x4e, 0x2d));
        p.drawRoundedRect(QRectF(X(x + lean) - Y(0.008), Y(top) + Y(0.01), Y(0.016), Y(0.07)), Y(0.008), Y(0.008));
    };
    reed(0.035, 0.52, -0.004);
    reed(0.055, 0.58, 0.006);
    reed(0.075, 0.62, 0.012);
    reed(0.935, 0.55, 0.004);
    reed(0.958, 0.50, -0.006);

    // The muddy bank along the floor, with a few tufts of grass.
    QPainterPath bank;
    bank.moveTo(0, Y(0.962));
    bank.cubicTo(X(0.25), Y(0.950), X(0.55), Y(0.972), X(0.78), Y(0.958));
    bank.cubicTo(X(0.88), Y(0.952), X(0.95), Y(0.962), W, Y(0.955));
    bank.lineTo(W, H);
    bank.lineTo(0, H);
    bank.closeSubpath();
    QLinearGradient mud(0, Y(0.95), 0, H);
    mud.setColorAt(0, QColor(0xb0, 0x93, 0x64));
    mud.setColorAt(1, QColor(0x86, 0x6a, 0x44));
    p.setPen(Qt::NoPen);
    p.setBrush(mud);
    p.drawPath(bank);
    p.setPen(QPen(QColor(0x8a, 0x9a, 0x3c), std::max(1.0, Y(0.004)), Qt::SolidLine, Qt::RoundCap));
    for (double x : {0.10, 0.31, 0.47, 0.69, 0.83, 0.97}) {
        const QPointF base(X(x), Y(0.968));
        p.drawLine(base, base + QPointF(-Y(0.012), -Y(0.03)));
        p.drawLine(base, base + QPointF(0, -Y(0.038)));
        p.drawLine(base, base + QPointF(Y(0.012), -Y(0.028)));
    }
    p.restore();
}

void FrogArt::paintHeadStill(QPainter& p) const
{
    p.setPen(m_headPen);
    p.setBrush(m_skins[0]);
    p.drawPath(m_head);
    p.setPen(Qt::NoPen);
    p.setBrush(m_cheekBrush);
    p.drawPath(m_cheeks);
    p.setPen(m_eyePen);
    p.setBrush(m_eyeWhiteBrush);
    p.drawPath(m_eyeWhites);
    p.setPen(Qt::NoPen);
    p.setBrush(m_outlineBrush);
    p.drawPath(m_nostrils);
    p.setBrush(Qt::NoBrush);
    p.setPen(m_mouthPen);
    p.drawPath(m_mouth);
}

void FrogArt::paintPupils(QPainter& p, QPointF mouse, bool glints) const
{
    // The pupils (horizontal, as a frog's) look at the mouse, 4 px off centre at most.
    p.setPen(Qt::NoPen);
    for (double ex : {-34.0, 34.0}) {
        const QPointF eye(ex, -21);
        QPointF look = mouse - eye;
        const double n = std::hypot(look.x(), look.y());
        look = n > 1e-9 && std::isfinite(n) ? look * (4.5 / std::max(n, 4.5)) : QPointF();
        p.setBrush(m_pupilBrush);
        p.drawEllipse(eye + look, 8.5, 6.5);
        if (glints) {
            p.setBrush(m_glintBrush);
            p.drawEllipse(eye + look + QPointF(-2.6, -2.4), 2.2, 2.2);
        }
    }
}

namespace {
// The head's box in its own frame, with room for the outline's pen.
const QRectF kHeadBox(-66, -47, 132, 92);
} // namespace

const QImage& FrogArt::headImage(int key) const
{
    auto found = m_headImages.find(key);
    if (found != m_headImages.end())
        return found->second;
    const double s = key / 32.0; // device pixels per head unit
    QImage image(QSize(int(std::ceil(kHeadBox.width() * s)) + 2, int(std::ceil(kHeadBox.height() * s)) + 2),
                 QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing, true);
    p.translate(1, 1);
    p.scale(s, s);
    p.translate(-kHeadBox.topLeft());
    paintHeadStill(p);
    p.end();
    if (m_headImages.size() > 64) // sizes seen while zooming: keep the cache small
        m_headImages.clear();
    return m_headImages.emplace(key, std::move(image)).first->second;
}

void FrogArt::paintHead(QPainter& p, QPointF at, double angle, double scale, QPointF lookAt) const
{
    // Where the mouse is in the head's own frame (turned by −angle, unscaled).
    const QPointF d = lookAt - at;
    const double c = std::cos(angle), s = std::sin(angle), k = scale > 0 ? 1 / scale : 0;
    const QPointF mouse((d.x() * c + d.y() * s) * k, (-d.x() * s + d.y() * c) * k);
    // Device pixels per head unit (the canvas scales uniformly).
    const double pixels = scale * std::sqrt(std::abs(p.worldTransform().determinant()));
    const bool raster = p.paintEngine() && p.paintEngine()->type() == QPaintEngine::Raster;
    const bool fromImage = raster && std::isfinite(pixels) && pixels > 0 && pixels * kHeadBox.width() < kHeadImageBelowPx;

    p.save();
    p.translate(at);
    p.rotate(angle * 180 / kPi);
    p.scale(scale, scale);
    if (fromImage) {
        // A crowd of small heads: one image each (made once per size), then the pupils.
        const int key = std::max(1, int(std::lround(pixels * 32)));
        const QImage& image = headImage(key);
        const double unitsPerPixel = 32.0 / key;
        p.drawImage(QRectF(kHeadBox.left() - unitsPerPixel, kHeadBox.top() - unitsPerPixel, image.width() * unitsPerPixel,
                           image.height() * unitsPerPixel),
                    image);
        paintPupils(p, mouse, false); // the glints would be under a pixel
    } else {
        paintHeadStill(p);
        paintPupils(p, mouse, true);
    }
    p.restore();
}

void FrogArt::paintFoot(QPainter& p, QPointF wrist, double angle, double scale) const
{
    p.save();
    p.setTransform(footTransform(wrist, angle, scale), true);
    p.setPen(m_footEdgePen);
    p.setBrush(Qt::NoBrush);
    p.drawPath(m_footWeb);
    p.setPen(m_footWebPen);
    p.drawPath(m_footWeb);
    p.setPen(m_toePen);
    p.setBrush(m_toeBrush);
    p.drawPath(m_foot);
    p.restore();
}

} // namespace granota::ui
