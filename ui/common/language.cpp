#include "ui/common/language.h"

#include "ui/common/number_text.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>
#include <QWidget>
#include <qcustomplot.h>

namespace granota::ui {

namespace {
QString g_current = QStringLiteral("en");
QTranslator* g_own = nullptr;
QTranslator* g_qt = nullptr;

/// QCustomPlot sets its own locale (English) when it is made, so plots do not inherit the
/// interface's: every plot gets it when it is first polished, and again on a switch.
class PlotLocaleKeeper : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::Polish)
            if (auto* plot = qobject_cast<QCustomPlot*>(watched); plot && plot->locale() != displayLocale())
                plot->setLocale(displayLocale());
        return false;
    }
};
PlotLocaleKeeper* g_plotLocale = nullptr;

/// Every widget that exists shows its numbers in the new language's locale: spin boxes
/// and plot axes redraw with the new decimal sign (widgets made later take the default).
void applyDisplayLocale()
{
    auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
    if (!app)
        return;
    if (!g_plotLocale) {
        g_plotLocale = new PlotLocaleKeeper(app);
        app->installEventFilter(g_plotLocale);
    }
    const QLocale locale = displayLocale();
    for (QWidget* w : QApplication::topLevelWidgets())
        w->setLocale(locale);
    for (QWidget* w : QApplication::allWidgets())
        if (auto* plot = qobject_cast<QCustomPlot*>(w)) {
            plot->setLocale(locale);
            plot->replot(QCustomPlot::rpQueuedReplot);
        }
}
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
    // The numbers' locale first: installing a translator sends the LanguageChange on which
    // widgets rewrite their texts, numbers included.
    g_current = language;
    QLocale::setDefault(displayLocale(language));
    applyDisplayLocale();
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
    if (remember)
        QSettings().setValue(QStringLiteral("language"), language);
    return true;
}

QString currentLanguage() { return g_current; }

} // namespace granota::ui
