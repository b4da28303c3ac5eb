#pragma once
/// \file thesis_figures_dialog.h
/// Help ▸ Thesis figures: the thesis's 23 figures with their captions, in the interface's
/// language; choosing one (and its variant) puts its tab in the state that draws it
/// (thesis_figure_export.h), as one undo step; Export… writes the figure's view alone.

#include <QDialog>

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;

namespace granota::ui {

class MainWindow;

class ThesisFiguresDialog : public QDialog {
    Q_OBJECT
public:
    explicit ThesisFiguresDialog(MainWindow* window);

    /// Shows the chosen figure (the list's current row, the variant box's choice) in the window.
    bool showChosen();
    QListWidget* list() const { return m_list; }
    QComboBox* variants() const { return m_variants; }
    QLabel* note() const { return m_note; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void figureChosen(int row);
    void variantChosen(int index);
    void exportChosen();

    MainWindow* m_window;
    QListWidget* m_list;
    QComboBox* m_variants;
    QLabel *m_variantLabel, *m_note;
    QPushButton *m_show, *m_export, *m_close;
};

} // namespace granota::ui
