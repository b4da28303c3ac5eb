#pragma once
/// \file vertical_scroll_area.h
/// A panel that scrolls up and down when the window is short (an 800×600 screen, presentation
/// mode at 1024×768) but is never narrower than what it holds: its rows stay whole, and the
/// window's minimum height no longer adds up every panel's rows.
#include <QScrollArea>

namespace granota::ui {

/// A QScrollArea that scrolls only vertically; its minimum width is its content's.
class VerticalScrollArea : public QScrollArea {
public:
    /// Holds `content` (resized to the viewport's width); `parent` owns it.
    explicit VerticalScrollArea(QWidget* content, QWidget* parent = nullptr);
    QSize minimumSizeHint() const override;
};

} // namespace granota::ui
