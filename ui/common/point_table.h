#pragma once
/// \file point_table.h
/// The numeric table beside a canvas: one row per point of a PointEditor, x and y editable.
/// It edits the same points through the same undo stack; fractions ("1/3") and decimals are
/// accepted, anything else is refused with a message and the cell shows the old value.
/// Each column has one notation (core/exact/number_column.h), read from the exact forms the
/// editor keeps (exact_point.h): fractions for all when some entry is a repeating small fraction
/// such as 1/3 and all are small fractions, else decimals for all — an exact value's decimal
/// expansion (a typed 0.05688 is 0.05688, 0.1 nudged by 0.01 is 0.11), a repeating one to 16
/// digits, and a value without an exact form the shortest that reads back as its double.
/// A tab may add one more column after x and y (setExtraColumn: the B-spline tab's weights),
/// whose texts and edits are the tab's; the table only shows them and hands typed text over.

#include "core/exact/number_column.h"

#include <QTableWidget>

#include <functional>

namespace granota::ui {

class PointEditor;

class PointTable : public QTableWidget {
    Q_OBJECT
public:
    explicit PointTable(PointEditor* editor, QWidget* parent = nullptr);
    void retranslate();
    /// The notation column 0 (x) or 1 (y) is shown in.
    ColumnNotation columnShown(int column) const { return m_notation[column]; }

    /// A third column headed `header` (column 2): row i shows text(i); a text typed into it is
    /// given to edit(i, text), which makes the change (and says why not: the table does not)
    /// and returns false when it refuses. After an edit the column shows text(i) again.
    using ExtraText = std::function<QString(int row)>;
    using ExtraEdit = std::function<bool(int row, const QString& text)>;
    void setExtraColumn(const QString& header, ExtraText text, ExtraEdit edit);
    /// The extra column's header tooltip (in the language in use: the tab sets it again).
    void setExtraColumnToolTip(const QString& toolTip);
    /// Shows text(i) in every row of the extra column again (its values changed, not the points).
    void refreshExtraColumn();
    bool hasExtraColumn() const { return static_cast<bool>(m_extraText); }

signals:
    void message(const QString& text);

protected:
    /// The accessible name, again in the new language.
    void changeEvent(QEvent* event) override;

private:
    void refresh();
    void cellEdited(int row, int column);
    ColumnNotation notation(int column) const;
    QString cellText(int row, int column) const;
    /// Sets the header labels (x, y and the extra column's) and the extra header's tooltip.
    void setHeaders();

    PointEditor* m_editor;
    bool m_refreshing = false;
    ColumnNotation m_notation[2] = {ColumnNotation::Decimals, ColumnNotation::Decimals};
    static constexpr int kExtraColumn = 2;
    QString m_extraHeader;
    QString m_extraToolTip;
    ExtraText m_extraText;
    ExtraEdit m_extraEdit;
};

} // namespace granota::ui
