// granota: the desktop application (SPEC §1, §5).
#include "ui/main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QTextStream>
#include <QTranslator>

namespace {

/// Installs Granota's own translation and Qt's (for the standard dialogs) for `language`
/// ("ca" or "en"). English is the source language, so its file only confirms the texts.
void installTranslators(QApplication& app, const QString& language)
{
    auto* own = new QTranslator(&app);
    if (own->load(QStringLiteral(":/i18n/granota_%1.qm").arg(language)))
        app.installTranslator(own);
    auto* qt = new QTranslator(&app);
    if (qt->load(QStringLiteral("qtbase_%1").arg(language), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(qt);
}

} // namespace

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Granota"));
    QApplication::setOrganizationName(QStringLiteral("Granota"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Splines and soft bodies, for the classroom."));
    parser.addHelpOption();
    QCommandLineOption tabOption(QStringLiteral("tab"), QStringLiteral("Open on tab KEY."), QStringLiteral("KEY"));
    QCommandLineOption langOption(QStringLiteral("lang"), QStringLiteral("Interface language: ca or en."),
                                  QStringLiteral("LANG"));
    QCommandLineOption screenshotOption(QStringLiteral("screenshot"),
                                        QStringLiteral("Render the window (1280x800) to FILE.png and exit."),
                                        QStringLiteral("FILE"));
    parser.addOption(tabOption);
    parser.addOption(langOption);
    parser.addOption(screenshotOption);
    parser.process(app);

    // Catalan by default on a Catalan system (SPEC §5), English otherwise.
    QString language = QLocale::system().language() == QLocale::Catalan ? QStringLiteral("ca") : QStringLiteral("en");
    if (parser.isSet(langOption)) {
        language = parser.value(langOption);
        if (language != QLatin1String("ca") && language != QLatin1String("en")) {
            QTextStream(stderr) << "error: unknown language '" << language << "' (ca, en)\n";
            return 2;
        }
    }
    installTranslators(app, language);

    granota::ui::MainWindow window;
    if (parser.isSet(tabOption) && !window.showTab(parser.value(tabOption))) {
        QTextStream(stderr) << "error: unknown tab '" << parser.value(tabOption)
                            << "' (decasteljau, bernstein, fit, catmull-rom, frog)\n";
        return 2;
    }
    if (parser.isSet(screenshotOption)) {
        window.resize(1280, 800);
        window.show();
        QApplication::processEvents();
        const QString file = parser.value(screenshotOption);
        if (!window.grab().save(file, "PNG")) {
            QTextStream(stderr) << "error: cannot write '" << file << "'\n";
            return 2;
        }
        return 0;
    }
    window.show();
    return app.exec();
}
