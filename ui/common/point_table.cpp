#include "ui/common/point_table.h"

#include "core/exact/number_column.h"
#include "core/exact/rational.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"

#include <QEvent>
#include <QHeaderView>
#include <QSignalBlocker>
#include <QStringList>

#include <cmath>
#include <utility>

namespace granota::ui {

PointTable::PointTable(PointEditor* editor, QWidget* parent) : QTableWidget(parent), m_editor(editor)
{
    setColumnCount(2);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setTabKeyNavigation(false); // Tab leaves the table (the arrows move between cells)
    setAccessibleName(tr("Points"));
    connect(m_editor, &PointEditor::pointsChanged, this, &PointTable::refresh);
    connect(m_editor, &PointEditor::selectionChanged, this, [this](int index) {
        if (index >= 0 && index < rowCount())
            selectRow(index);
        else
            clearSelection();
    });
    connect(this, &QTableWidget::cellChanged, this, &PointTable::cellEdited);
    connect(this, &QTableWidget::currentCellChanged, this, [this](int row, int, int, int) {
        if (!m_refreshing && row >= 0)
            m_editor->setSelected(row);
    });
    retranslate();
    refresh();
}

void PointTable::retranslate()
{
    setHeaders();
    setToolTip(tr("The points as numbers: type a decimal or a fraction such as 1/3."));
    refresh();
}

void PointTable::setHeaders()
{
    QStringList labels{tr("x"), tr("y")};
    if (hasExtraColumn())
        labels << m_extraHeader;
    setColumnCount(static_cast<int>(labels.size()));
    setHorizontalHeaderLabels(labels);
    if (QTableWidgetItem* header = hasExtraColumn() ? horizontalHeaderItem(kExtraColumn) : nullptr)
        header->setToolTip(m_extraToolTip);
}

void PointTable::setExtraColumn(const QString& header, ExtraText text, ExtraEdit edit)
{
    m_extraHeader = header;
    m_extraText = std::move(text);
    m_extraEdit = std::move(edit);
    setHeaders();
    refresh();
}

void PointTable::setExtraColumnToolTip(const QString& toolTip)
{
    m_extraToolTip = toolTip;
    setHeaders();
}

void PointTable::refreshExtraColumn()
{
    if (!hasExtraColumn())
        return;
    const bool refreshing = std::exchange(m_refreshing, true);
    for (int i = 0; i < rowCount(); ++i)
        if (QTableWidgetItem* cell = item(i, kExtraColumn))
            cell->setText(m_extraText(i));
    m_refreshing = refreshing;
}

ColumnNotation PointTable::notation(int column) const
{
    const std::size_t count = m_editor->points().size();
    if (m_editor->exactPoints().size() != count)
        return ColumnNotation::Decimals; // none has an exact form
    std::vector<ExactCoordinate> values;
    values.reserve(count);
    for (const ExactPoint& p : m_editor->exactPoints())
        values.push_back(column == 0 ? p.x : p.y);
    return columnNotation(values);
}

QString PointTable::cellText(int row, int column) const
{
    if (column == kExtraColumn)
        return m_extraText(row);
    const auto i = static_cast<std::size_t>(row);
    const Point& p = m_editor->points()[i];
    const ExactPoint& q = m_editor->exactAt(i);
    return displayText(column == 0 ? columnEntry(q.x, p.x, m_notation[0]) : columnEntry(q.y, p.y, m_notation[1]));
}

void PointTable::refresh()
{
    m_refreshing = true;
    const auto& points = m_editor->points();
    // One notation per column (number_column.h): fractions for all, or decimals for all.
    const ColumnNotation notations[2] = {notation(0), notation(1)};
    const bool sameNotation = notations[0] == m_notation[0] && notations[1] == m_notation[1];
    m_notation[0] = notations[0];
    m_notation[1] = notations[1];
    // During a drag only the dragged point changes: refresh its row alone (unless its column
    // changes notation).
    const int dragged = m_editor->dragging() ? m_editor->selected() : -1;
    if (dragged >= 0 && sameNotation && rowCount() == static_cast<int>(points.size()) && item(dragged, 0) && item(dragged, 1)) {
        item(dragged, 0)->setText(cellText(dragged, 0));
        item(dragged, 1)->setText(cellText(dragged, 1));
        m_refreshing = false;
        return;
    }
    const int rows = static_cast<int>(points.size());
    const int columns = columnCount();
    setRowCount(rows);
    {
        // The views hear of the new labels and texts once, below: told of each row's label
        // alone, the row header measured up to 200 labels again every time, and 2 000 points
        // took tens of seconds to list.
        const QSignalBlocker quiet(model());
        for (int i = 0; i < rows; ++i) {
            setVerticalHeaderItem(i, new QTableWidgetItem(QStringLiteral("%1%2").arg(m_editor->labelPrefix()).arg(i)));
            for (int c = 0; c < columns; ++c) {
                QTableWidgetItem* cell = item(i, c);
                if (!cell) {
                    cell = new QTableWidgetItem;
                    cell->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                    setItem(i, c, cell);
                }
                cell->setText(cellText(i, c));
            }
        }
    }
    if (rows > 0) {
        emit model()->headerDataChanged(Qt::Vertical, 0, rows - 1);
        emit model()->dataChanged(model()->index(0, 0), model()->index(rows - 1, columns - 1));
    }
    m_refreshing = false;
}

void PointTable::cellEdited(int row, int column)
{
    if (m_refreshing)
        return;
    if (column == kExtraColumn) {
        m_extraEdit(row, item(row, column)->text());
        refreshExtraColumn(); // the value in force, refused or not (a typed "2.0" reads "2")
        return;
    }
    const QString text = item(row, column)->text().trimmed();
    const auto q = parseTypedRational(text);
    const double v = q ? toDouble(*q) : std::nan("");
    if (!q || !std::isfinite(v)) {
        emit message(tr("“%1” is not a number: type a decimal (2.5) or a fraction (5/2).").arg(text));
        refresh();
        return;
    }
    Point p = m_editor->points()[static_cast<std::size_t>(row)];
    ExactPoint exact = m_editor->exactAt(static_cast<std::size_t>(row));
    (column == 0 ? p.x : p.y) = v;
    (column == 0 ? exact.x : exact.y) = *q;
    m_editor->movePoint(row, p, exact);
}

void PointTable::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        setAccessibleName(tr("Points"));
    QTableWidget::changeEvent(event);
}

} // namespace granota::ui
