#pragma once
/// \file shortcuts_dialog.h
/// Help ▸ Keyboard shortcuts as a window beside the main one: the keys in two columns
/// (ShortcutsHelp::twoColumnHtml) in a pane that scrolls, never taller or wider than the
/// screen's available area less a window manager's frame, so that its last rows and its Close
/// button stay on a 1024×768 or 800×600 projector (docs/classroom.md, "Keyboard").
#include <QDialog>
#include <QMargins>

class QPushButton;
class QTextBrowser;

namespace granota::ui {

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ShortcutsDialog(QWidget* parent);
    /// Shows `html` (again, in the language of now), sized to it but within the screen less
    /// `frame`, and raises the dialog.
    void present(const QString& html, const QMargins& frame);
    QTextBrowser* browser() const { return m_browser; }

private:
    QTextBrowser* m_browser;
    QPushButton* m_close;
};

} // namespace granota::ui
