#include "ui/shell/document.h"

#include "ui/common/tab_page.h"

#include "core/io/json.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace granota::ui {

namespace {

constexpr int kVersion = 1;
const QString kAutosaveKey = QStringLiteral("autosave");

/// The parts of a document every reader checks before any tab sees it.
struct Root {
    QJsonObject object;
    QJsonObject parts; ///< "tabs"
};

/// The document's root, or nothing with a translated `error`: not JSON, not an object, not
/// a Granota document, a version this Granota does not read, no "tabs" object, or a known
/// tab whose part is not an object.
std::optional<Root> readRoot(const QByteArray& bytes, const QVector<TabPage*>& tabs, QString* error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (doc.isNull()) {
        // Said in plain words, not the parser's ("invalid termination by number"): a file
        // cut short (a full disk, a copy stopped half-way) is named as such, by the core's
        // reader, which tells the end of the text from a wrong byte inside it.
        const auto core = Json::parse(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
        if (bytes.trimmed().isEmpty())
            *error = QCoreApplication::translate("granota::ui::Document", "This is not a Granota document: the file is empty.");
        else if (!core && core.error().code == ErrorCode::CutOff)
            *error = QCoreApplication::translate("granota::ui::Document",
                                                 "This is not a whole Granota document: the file is cut off at byte %1.")
                         .arg(bytes.size());
        else
            *error = QCoreApplication::translate("granota::ui::Document",
                                                 "This is not a Granota document: the text is not JSON at byte %1 (line %2).")
                         .arg(parseError.offset)
                         .arg(bytes.left(parseError.offset).count('\n') + 1);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = QCoreApplication::translate("granota::ui::Document",
                                             "This is not a Granota document: it is a JSON list, not an object.");
        return std::nullopt;
    }
    Root root{doc.object(), {}};
    if (root.object.value(QStringLiteral("format")).toString() != QLatin1String("granota")) {
        *error = QCoreApplication::translate("granota::ui::Document",
                                             "This is not a Granota document (no \"format\": \"granota\").");
        return std::nullopt;
    }
    const QJsonValue version = root.object.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toDouble() != std::floor(version.toDouble())) {
        *error = QCoreApplication::translate("granota::ui::Document",
                                             "This document's \"version\" is not a whole number; this Granota reads version %1.")
                     .arg(kVersion);
        return std::nullopt;
    }
    if (version.toDouble() < 1 || version.toDouble() > kVersion) {
        *error = QCoreApplication::translate("granota::ui::Document",
                                             "This document has version %1; this Granota reads version %2.")
                     .arg(version.toDouble())
                     .arg(kVersion);
        return std::nullopt;
    }
    const QJsonValue parts = root.object.value(QStringLiteral("tabs"));
    if (!parts.isObject()) {
        *error = QCoreApplication::translate("granota::ui::Document",
                                             "This document has no \"tabs\" object holding the tabs' points and settings.");
        return std::nullopt;
    }
    root.parts = parts.toObject();
    for (const TabPage* tab : tabs)
        if (root.parts.contains(tab->key()) && !root.parts.value(tab->key()).isObject()) {
            *error = QCoreApplication::translate("granota::ui::Document", "Tab “%1”: its part of the document is not an object.")
                         .arg(tab->title());
            return std::nullopt;
        }
    return root;
}

QJsonObject documentObject(const QVector<TabPage*>& tabs, const QString& currentTab)
{
    QJsonObject parts;
    for (const TabPage* tab : tabs)
        parts.insert(tab->key(), tab->saveState());
    QJsonObject root;
    root.insert(QStringLiteral("format"), QStringLiteral("granota"));
    root.insert(QStringLiteral("version"), kVersion);
    root.insert(QStringLiteral("current"), currentTab);
    root.insert(QStringLiteral("tabs"), parts);
    return root;
}

} // namespace

QByteArray serializeDocument(const QVector<TabPage*>& tabs, const QString& currentTab)
{
    return QJsonDocument(documentObject(tabs, currentTab)).toJson(QJsonDocument::Indented);
}

QByteArray serializeAutosave(const QVector<TabPage*>& tabs, const QString& currentTab, const QString& documentFile)
{
    QJsonObject root = documentObject(tabs, currentTab);
    root.insert(kAutosaveKey, QJsonObject{{QStringLiteral("file"), documentFile}});
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool loadDocument(const QByteArray& bytes, const QVector<TabPage*>& tabs, QString* error, QString* currentTab)
{
    const std::optional<Root> root = readRoot(bytes, tabs, error);
    if (!root)
        return false;
    QVector<QJsonObject> before;
    for (const TabPage* tab : tabs)
        before.push_back(tab->saveState());
    for (int i = 0; i < tabs.size(); ++i) {
        if (!root->parts.contains(tabs[i]->key()))
            continue; // a document may hold only some tabs
        QString tabError;
        if (!tabs[i]->loadState(root->parts.value(tabs[i]->key()).toObject(), &tabError)) {
            for (int j = 0; j < i; ++j) {
                QString ignored;
                tabs[j]->loadState(before[j], &ignored);
            }
            *error = QCoreApplication::translate("granota::ui::Document", "Tab “%1”: %2").arg(tabs[i]->title(), tabError);
            return false;
        }
    }
    if (currentTab)
        *currentTab = root->object.value(QStringLiteral("current")).toString();
    return true;
}

Recovery recoverDocument(const QByteArray& bytes, const QVector<TabPage*>& tabs)
{
    Recovery r;
    const std::optional<Root> root = readRoot(bytes, tabs, &r.error);
    if (!root)
        return r;
    r.readable = true;
    for (TabPage* tab : tabs) {
        if (!root->parts.contains(tab->key()))
            continue;
        QString tabError;
        if (tab->loadState(root->parts.value(tab->key()).toObject(), &tabError))
            r.recovered << tab->title();
        else
            r.refused << QStringLiteral("%1: %2").arg(tab->title(), tabError);
    }
    r.currentTab = root->object.value(QStringLiteral("current")).toString();
    r.documentFile = root->object.value(kAutosaveKey).toObject().value(QStringLiteral("file")).toString();
    return r;
}

std::optional<QString> autosaveDocumentFile(const QByteArray& bytes)
{
    const QJsonDocument doc = QJsonDocument::fromJson(bytes);
    const QJsonValue autosave = doc.object().value(kAutosaveKey);
    if (!autosave.isObject())
        return std::nullopt;
    return autosave.toObject().value(QStringLiteral("file")).toString();
}

} // namespace granota::ui
