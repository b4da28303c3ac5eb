#include "ui/catmull_rom/knot_continuity_table.h"

#include "ui/common/number_text.h"

#include <QHeaderView>

#include <cmath>

namespace granota::ui {

namespace {

const QColor kKnotFailColor(0xc6, 0x28, 0x28);
const QColor kKnotPassColor(0x2e, 0x7d, 0x32);

QTableWidgetItem* knotMarkItem(bool holds)
{
    auto* item = new QTableWidgetItem(holds ? QStringLiteral("✓") : QStringLiteral("✗"));
    item->setForeground(holds ? kKnotPassColor : kKnotFailColor);
    item->setTextAlignment(Qt::AlignCenter);
    return item;
}

} // namespace

KnotContinuityTable::KnotContinuityTable(QWidget* parent) : QTableWidget(parent)
{
    setColumnCount(ColumnCount);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    horizontalHeader()->setStretchLastSection(true);
}

void KnotContinuityTable::showCurve(const std::vector<Vec2<Polynomial<double>>>& segments, const std::vector<double>& intervals,
                                    bool closedLoop, int firstPoint, int pointCount)
{
    m_knots.clear();
    m_knotPoints.clear();
    if (!segments.empty() && (intervals.empty() || intervals.size() == segments.size()) && pointCount > 0) {
        bool positive = true;
        for (double h : intervals)
            positive = positive && h > 0;
        if (positive)
            m_knots = knotContinuity(segments, intervals, closedLoop, kTolerance);
    }
    for (const auto& k : m_knots)
        m_knotPoints.push_back((firstPoint + k.fromSegment + 1) % pointCount);
    fill();
}

void KnotContinuityTable::fill()
{
    setRowCount(static_cast<int>(m_knots.size()));
    for (int r = 0; r < static_cast<int>(m_knots.size()); ++r) {
        const KnotContinuity<double>& k = m_knots[static_cast<std::size_t>(r)];
        auto* knot = new QTableWidgetItem(QStringLiteral("q%1").arg(m_knotPoints[static_cast<std::size_t>(r)]));
        setItem(r, KnotColumn, knot);
        const int order = k.parametricOrder();
        setItem(r, C0Column, knotMarkItem(order >= 0));
        setItem(r, C1Column, knotMarkItem(order >= 1));
        setItem(r, C2Column, knotMarkItem(order >= 2));
        setItem(r, G1Column, knotMarkItem(k.g1));
        setItem(r, G2Column, knotMarkItem(k.g2));
        const Point jump = k.jump(1);
        auto* size = new QTableWidgetItem(displayNumber(std::hypot(jump.x, jump.y)));
        size->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(r, JumpColumn, size);
    }
}

void KnotContinuityTable::retranslate()
{
    setHorizontalHeaderLabels({tr("Knot"), QStringLiteral("C⁰"), QStringLiteral("C¹"), QStringLiteral("C²"), QStringLiteral("G¹"),
                               QStringLiteral("G²"), tr("|p′₊ − p′₋|")});
    setToolTip(tr("Each knot of the curve drawn: ✓ where the derivatives of order 0, 1, 2 agree (C⁰, C¹, C²) and "
                  "where the direction (G¹) and the curvature (G²) agree; the last column is the jump of the tangent. "
                  "Catmull-Rom curves are C¹ at every knot (Prop 2.3); a continuity C ≠ 0 breaks it."));
    setAccessibleName(tr("Continuity at the knots"));
}

} // namespace granota::ui
