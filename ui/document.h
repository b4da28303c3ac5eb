#pragma once
/// \file document.h
/// The .granota document (SPEC §4): one JSON object with every tab's points and settings.
///
///     { "format": "granota", "version": 1, "current": "fit",
///       "tabs": { "decasteljau": {…}, "bernstein": {…}, "fit": {…}, "catmull-rom": {…}, "frog": {…} } }
///
/// Loading is all or nothing: if one tab refuses its part, every tab is put back as it was.

#include <QByteArray>
#include <QString>
#include <QVector>

namespace granota::ui {

class TabPage;

QByteArray serializeDocument(const QVector<TabPage*>& tabs, const QString& currentTab);

/// Loads `bytes` into the tabs. On failure returns false, sets a translated `error` and
/// leaves every tab unchanged. `currentTab` receives the tab the document was saved on.
bool loadDocument(const QByteArray& bytes, const QVector<TabPage*>& tabs, QString* error, QString* currentTab);

} // namespace granota::ui
