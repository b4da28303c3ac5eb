#pragma once
/// \file document.h
/// The .granota document (docs/file-formats.md): one JSON object with every tab's points and settings.
///
///     { "format": "granota", "version": 1, "current": "fit",
///       "tabs": { "decasteljau": {…}, "bernstein": {…}, "fit": {…}, "catmull-rom": {…}, "frog": {…}, "bspline": {…} } }
///
/// An autosave is a document with one more member, naming the document it belongs to
/// ("" for an Untitled window):   "autosave": { "file": "/home/anna/lesson.granota" }
///
/// Opening is all or nothing: if one tab refuses its part, every tab is put back as it was
/// and no tab's undo history changes. Recovering an autosave takes what it can: every tab
/// whose part is valid, with the others named.

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace granota::ui {

class TabPage;

QByteArray serializeDocument(const QVector<TabPage*>& tabs, const QString& currentTab);
/// The document with the "autosave" member naming `documentFile` (empty: Untitled).
QByteArray serializeAutosave(const QVector<TabPage*>& tabs, const QString& currentTab, const QString& documentFile);

/// Loads `bytes` into the tabs. On failure returns false, sets a translated `error` and
/// leaves every tab unchanged. `currentTab` receives the tab the document was saved on.
bool loadDocument(const QByteArray& bytes, const QVector<TabPage*>& tabs, QString* error, QString* currentTab);

/// What recovering an autosave did.
struct Recovery {
    bool readable = false; ///< false: nothing was loaded, `error` says why
    QString error;
    QStringList recovered; ///< titles of the tabs that took their part
    QStringList refused;   ///< "Title: reason" for each tab that refused its part
    QString currentTab;
    QString documentFile; ///< the document the autosave belongs to, empty for Untitled
};
/// Loads every tab whose part of `bytes` is valid, leaving the others as they are.
Recovery recoverDocument(const QByteArray& bytes, const QVector<TabPage*>& tabs);

/// The document an autosave belongs to ("" for Untitled), or nothing if `bytes` is not one.
std::optional<QString> autosaveDocumentFile(const QByteArray& bytes);

} // namespace granota::ui
