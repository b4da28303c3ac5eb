#pragma once
/// \file tikz_options_dialog.h
/// The small dialog File ▸ Export ▸ TikZ shows before the file dialog (docs/tabs.md): the
/// picture's width and greatest height in cm, axes with tick labels, a grid. It starts from
/// the last choice (TikzOptions::load) and keeps the new one when the teacher accepts.

#include "ui/files/tikz_options.h"

#include <QDialog>

class QCheckBox;

namespace granota::ui {

class DecimalSpinBox;

class TikzOptionsDialog : public QDialog {
    Q_OBJECT
public:
    explicit TikzOptionsDialog(const TikzOptions& options, QWidget* parent = nullptr);

    /// What the dialog shows now.
    TikzOptions options() const;

    /// Shows the dialog with the last choice; on OK keeps the choice and returns it in
    /// `options`; false if the teacher cancels.
    static bool ask(QWidget* parent, TikzOptions* options);

private:
    DecimalSpinBox* m_width = nullptr;
    DecimalSpinBox* m_height = nullptr;
    QCheckBox* m_axes = nullptr;
    QCheckBox* m_grid = nullptr;
};

} // namespace granota::ui
