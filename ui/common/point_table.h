#pragma once
/// \file point_table.h
/// The numeric table beside a canvas: one row per point of a PointEditor, x and y editable.
/// It edits the same points through the same undo stack; fractions ("1/3") and decimals are
/// accepted, anything else is refused with a message and the cell shows the old value.

#include <QTableWidget>

namespace granota::ui {

class PointEditor;

class PointTable : public QTableWidget {
    Q_OBJECT
public:
    explicit PointTable(PointEditor* editor, QWidget* parent = nullptr);
    void retranslate();

signals:
    void message(const QString& text);

private:
    void refresh();
    void cellEdited(int row, int column);

    PointEditor* m_editor;
    bool m_refreshing = false;
};

} // namespace granota::ui
