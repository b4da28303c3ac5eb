#include "ui/document.h"

#include "ui/tab_page.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

namespace granota::ui {

namespace {
constexpr int kVersion = 1;
} // namespace

QByteArray serializeDocument(const QVector<TabPage*>& tabs, const QString& currentTab)
{
    QJsonObject parts;
    for (const TabPage* tab : tabs)
        parts.insert(tab->key(), tab->saveState());
    QJsonObject root;
    root.insert(QStringLiteral("format"), QStringLiteral("granota"));
    root.insert(QStringLiteral("version"), kVersion);
    root.insert(QStringLiteral("current"), currentTab);
    root.insert(QStringLiteral("tabs"), parts);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool loadDocument(const QByteArray& bytes, const QVector<TabPage*>& tabs, QString* error, QString* currentTab)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (doc.isNull() || !doc.isObject()) {
        *error = QCoreApplication::translate("granota::ui::Document", "This is not a Granota document: %1 (at byte %2).")
                     .arg(parseError.errorString())
                     .arg(parseError.offset);
        return false;
    }
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != QLatin1String("granota")) {
        *error = QCoreApplication::translate("granota::ui::Document", "This is not a Granota document (no \"format\": \"granota\").");
        return false;
    }
    const int version = root.value(QStringLiteral("version")).toInt(-1);
    if (version < 1 || version > kVersion) {
        *error = QCoreApplication::translate("granota::ui::Document", "This document has version %1; this Granota reads version %2.").arg(version).arg(kVersion);
        return false;
    }
    const QJsonObject parts = root.value(QStringLiteral("tabs")).toObject();
    QVector<QJsonObject> before;
    for (const TabPage* tab : tabs)
        before.push_back(tab->saveState());
    for (int i = 0; i < tabs.size(); ++i) {
        if (!parts.contains(tabs[i]->key()))
            continue; // a document may hold only some tabs
        QString tabError;
        if (!tabs[i]->loadState(parts.value(tabs[i]->key()).toObject(), &tabError)) {
            for (int j = 0; j < i; ++j) {
                QString ignored;
                tabs[j]->loadState(before[j], &ignored);
            }
            *error = QCoreApplication::translate("granota::ui::Document", "Tab “%1”: %2").arg(tabs[i]->title(), tabError);
            return false;
        }
    }
    if (currentTab)
        *currentTab = root.value(QStringLiteral("current")).toString();
    return true;
}

} // namespace granota::ui
