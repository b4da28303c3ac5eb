#pragma once
/// \file widest_text_width.h
/// A button whose text changes as it is used (Play ↔ Pause, Run ↔ Pause) keeps one width:
/// the widest of its texts in the language shown, so that neither it nor what is beside it
/// moves under the pointer when it is pressed (issue 34, item 11). The width follows the
/// button's font (presentation mode enlarges it) and is set again with the texts whenever the
/// language changes (the tab's retranslate calls this again).
#include <QStringList>

class QAbstractButton;

namespace granota::ui {

/// Keeps `button` at least as wide as it would be showing any of `texts`.
void keepWidestTextWidth(QAbstractButton* button, const QStringList& texts);

} // namespace granota::ui
