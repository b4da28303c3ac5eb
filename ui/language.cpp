#include "ui/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

namespace granota::ui {

namespace {
QString g_current = QStringLiteral("en");
QTranslator* g_own = nullptr;
QTranslator* g_qt = nullptr;
} // namespace

QStringList availableLanguages() { return {QStringLiteral("ca"), QStringLiteral("en")}; }

QString preferredLanguage()
{
    const QString saved = QSettings().value(QStringLiteral("language")).toString();
    if (availableLanguages().contains(saved))
        return saved;
    return QLocale::system().language() == QLocale::Catalan ? QStringLiteral("ca") : QStringLiteral("en");
}

bool setLanguage(const QString& language, bool remember)
{
    if (!availableLanguages().contains(language))
        return false;
    auto* app = QCoreApplication::instance();
    if (g_own) {
        QCoreApplication::removeTranslator(g_own);
        delete g_own;
        g_own = nullptr;
    }
    if (g_qt) {
        QCoreApplication::removeTranslator(g_qt);
        delete g_qt;
        g_qt = nullptr;
    }
    // English is the source language: its .qm only confirms the texts, but installing it
    // still sends the LanguageChange that makes every widget retranslate.
    g_own = new QTranslator(app);
    if (g_own->load(QStringLiteral(":/i18n/granota_%1.qm").arg(language)))
        QCoreApplication::installTranslator(g_own);
    g_qt = new QTranslator(app);
    if (g_qt->load(QStringLiteral("qtbase_%1").arg(language), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(g_qt);
    g_current = language;
    QLocale::setDefault(QLocale(language == QLatin1String("ca") ? QLocale::Catalan : QLocale::English));
    if (remember)
        QSettings().setValue(QStringLiteral("language"), language);
    return true;
}

QString currentLanguage() { return g_current; }

} // namespace granota::ui
