#pragma once
/// \file main_window.h
/// Granota's main window: one tab per part of the thesis (SPEC §1).

#include <QMainWindow>

class QTabWidget;

namespace granota::ui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    /// Tab keys of SPEC §5: decasteljau, bernstein, fit, catmull-rom, frog.
    bool showTab(const QString& key);

private:
    void retranslate();
    QTabWidget* m_tabs = nullptr;
};

} // namespace granota::ui
