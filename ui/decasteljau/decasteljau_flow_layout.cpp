#include "ui/decasteljau/decasteljau_flow_layout.h"

#include <QWidget>

#include <algorithm>

namespace granota::ui {

DeCasteljauFlowLayout::DeCasteljauFlowLayout(QWidget* parent, int hSpacing, int vSpacing)
    : QLayout(parent), m_hSpacing(hSpacing), m_vSpacing(vSpacing)
{
    setContentsMargins(0, 0, 0, 0);
}

DeCasteljauFlowLayout::~DeCasteljauFlowLayout()
{
    while (QLayoutItem* item = takeAt(0))
        delete item;
}

void DeCasteljauFlowLayout::addItem(QLayoutItem* item) { m_items.append(item); }

QLayoutItem* DeCasteljauFlowLayout::takeAt(int index)
{
    if (index < 0 || index >= m_items.size())
        return nullptr;
    return m_items.takeAt(index);
}

QSize DeCasteljauFlowLayout::minimumSize() const
{
    QSize size;
    for (const QLayoutItem* item : m_items)
        size = size.expandedTo(item->minimumSize());
    const QMargins m = contentsMargins();
    return size + QSize(m.left() + m.right(), m.top() + m.bottom());
}

void DeCasteljauFlowLayout::setGeometry(const QRect& rect)
{
    QLayout::setGeometry(rect);
    doLayout(rect, false);
}

int DeCasteljauFlowLayout::doLayout(const QRect& rect, bool testOnly) const
{
    const QMargins m = contentsMargins();
    const QRect area = rect.adjusted(m.left(), m.top(), -m.right(), -m.bottom());
    int x = area.x(), y = area.y(), lineHeight = 0;
    // Items of one row share its height and are centred in it.
    QList<QPair<QLayoutItem*, QRect>> row;
    auto flush = [&row, &lineHeight, testOnly] {
        if (!testOnly)
            for (auto& [item, r] : row)
                item->setGeometry(QRect(QPoint(r.x(), r.y() + (lineHeight - r.height()) / 2), r.size()));
        row.clear();
    };
    for (QLayoutItem* item : m_items) {
        if (item->isEmpty())
            continue;
        QSize hint = item->sizeHint().expandedTo(item->minimumSize());
        hint.setWidth(std::min(hint.width(), area.width()));
        if (x > area.x() && x + hint.width() > area.right() + 1) {
            flush();
            x = area.x();
            y += lineHeight + m_vSpacing;
            lineHeight = 0;
        }
        row.append({item, QRect(QPoint(x, y), hint)});
        x += hint.width() + m_hSpacing;
        lineHeight = std::max(lineHeight, hint.height());
    }
    flush();
    return y + lineHeight - rect.y() + m.bottom();
}

} // namespace granota::ui
