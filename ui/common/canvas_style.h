#pragma once
/// \file canvas_style.h
/// Pens, colours and sizes shared by every canvas, scaled up in presentation mode so that
/// lines and labels read from the back of a classroom (docs/classroom.md).

#include <QColor>
#include <QFont>

namespace granota::ui {

struct CanvasStyle {
    double scale = 1.0;                  ///< 1 on a desk, larger in presentation mode
    QColor background{0xfb, 0xfa, 0xf6}; ///< paper
    QColor gridMinor{0xe6, 0xe4, 0xdc};
    QColor gridMajor{0xcf, 0xcc, 0xc0};
    QColor axis{0x8a, 0x86, 0x7a};
    QColor text{0x2b, 0x2b, 0x2b};
    QColor curve{0x1f, 0x5f, 0xa8};   ///< the curve c(t)
    QColor polygon{0x9a, 0x9a, 0x9a}; ///< control polygon
    QColor handle{0xd9, 0x48, 0x2b};  ///< editable points
    QColor handleSelected{0x2b, 0x9d, 0x48};

    double lineWidth() const { return 2.0 * scale; }
    double thinLine() const { return 1.0 * scale; }
    double handleRadius() const { return 6.0 * scale; }
    double pickRadius() const { return 10.0 * scale; } ///< how near the mouse must be to pick a point
    QFont labelFont() const
    {
        QFont f;
        f.setPointSizeF(f.pointSizeF() * scale);
        return f;
    }

    /// One colour per level of De Casteljau, per tension, per series: distinct and printable.
    static QColor series(int i)
    {
        static const QColor palette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
                                         QColor(0xd6, 0x27, 0x28), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                         QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22),
                                         QColor(0x17, 0xbe, 0xcf)};
        return palette[((i % 10) + 10) % 10];
    }
};

} // namespace granota::ui
