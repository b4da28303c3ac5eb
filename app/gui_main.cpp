// granota: the desktop application (docs/tabs.md, docs/classroom.md).
#include "core/io/thesis_figures.h"
#include "core/softbody/scenes/scene.h"
#include "ui/fit/fit_tab.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_plot_panel.h"
#include "ui/frog/frog_tab.h"
#include "ui/files/exporter.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "ui/shell/thesis_figure_export.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFile>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QSize>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace {

/// With no display at all (over SSH, in CI), the options that print or render and then exit
/// (--help, --version, --screenshot, --list-figures, --figure, --export) use Qt's offscreen platform instead of aborting on
/// "could not connect to display". A platform the user chose is kept.
bool rendersAndExits(int argc, char* argv[])
{
    for (int i = 1; i < argc; ++i) {
        const char* a = argv[i];
        for (const char* option :
             {"-h", "-?", "--help", "--help-all", "-v", "--version", "--screenshot", "--list-figures", "--figure", "--export"}) {
            const std::size_t n = std::strlen(option);
            if (std::strcmp(a, option) == 0 || (std::strncmp(a, option, n) == 0 && a[n] == '=' && n > 2))
                return true;
        }
    }
    return false;
}

void offscreenWhenNothingIsShown(int argc, char* argv[])
{
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") || !qEnvironmentVariableIsEmpty("DISPLAY") ||
        !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        return;
    if (rendersAndExits(argc, argv))
        qputenv("QT_QPA_PLATFORM", "offscreen");
}

/// A text of the command line, in the interface's language (translations/, context
/// "granota::CommandLine").
QString say(const char* text) { return QCoreApplication::translate("granota::CommandLine", text); }

/// Qt's messages as usual, without the two notices every render run would print on a
/// machine without a desktop (the offscreen platform's "does not support
/// propagateSizeHints()", QStandardPaths' "XDG_RUNTIME_DIR not set"): no news to a script.
QtMessageHandler g_defaultHandler = nullptr;
void quietOffscreen(QtMsgType type, const QMessageLogContext& context, const QString& message)
{
    if (message.contains(QLatin1String("propagateSizeHints")) || message.contains(QLatin1String("XDG_RUNTIME_DIR not set")))
        return;
    if (g_defaultHandler)
        g_defaultHandler(type, context, message);
    else
        std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

/// "WxH" with each side in 100 … 10000, else an empty size.
QSize sizeOf(const QString& text)
{
    const QStringList wh = text.split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = wh.size() == 2 ? wh[0].toInt(&okW) : 0, h = wh.size() == 2 ? wh[1].toInt(&okH) : 0;
    if (!okW || !okH || w < 100 || h < 100 || w > 10000 || h > 10000)
        return {};
    return {w, h};
}

int fail(const QString& message)
{
    QTextStream(stderr) << "error: " << message << '\n';
    return 2;
}

} // namespace

int main(int argc, char* argv[])
{
    offscreenWhenNothingIsShown(argc, argv);
    if (rendersAndExits(argc, argv))
        g_defaultHandler = qInstallMessageHandler(quietOffscreen);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Granota"));
    QApplication::setOrganizationName(QStringLiteral("Granota"));
    QApplication::setApplicationVersion(QStringLiteral("1.0"));
    QApplication::setDesktopFileName(QStringLiteral("org.granota.Granota"));

    // The language of the messages below, and of --help: the one asked for with --lang when
    // it is one, else the saved or the desktop's (docs/classroom.md). Read before the parser,
    // which needs its texts translated.
    const QStringList arguments = QApplication::arguments();
    QString asked;
    for (int i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == QLatin1String("--lang") && i + 1 < arguments.size())
            asked = arguments[i + 1];
        else if (arguments[i].startsWith(QLatin1String("--lang=")))
            asked = arguments[i].mid(7);
    }
    QString language = granota::ui::preferredLanguage();
    granota::ui::setLanguage(granota::ui::availableLanguages().contains(asked) ? asked : language, false);

    QCommandLineParser parser;
    parser.setApplicationDescription(say("Splines and soft bodies, for the classroom."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    QCommandLineOption tabOption(QStringLiteral("tab"),
                                 say("Open on tab KEY: decasteljau, bernstein, fit, catmull-rom, frog, bspline."),
                                 QStringLiteral("KEY"));
    QCommandLineOption langOption(QStringLiteral("lang"), say("Interface language: ca or en."), QStringLiteral("LANG"));
    QCommandLineOption exampleOption(QStringLiteral("example"), say("Load worked example ID (2.1 … 2.13)."),
                                     QStringLiteral("ID"));
    QCommandLineOption sceneOption(QStringLiteral("scene"), say("Open the frog tab on scene NAME."), QStringLiteral("NAME"));
    QCommandLineOption presentOption(QStringLiteral("presentation"), say("Start in presentation mode."));
    QCommandLineOption screenshotOption(QStringLiteral("screenshot"), say("Render the window (1280x800) to FILE.png and exit."),
                                        QStringLiteral("FILE"));
    QCommandLineOption sizeOption(QStringLiteral("size"),
                                  say("Window size WxH (a screenshot's, else the window's), e.g. 800x570."),
                                  QStringLiteral("WxH"));
    QCommandLineOption plotsOption(QStringLiteral("plots"),
                                   say("Show the frog's plots over time: energy, area, stretch, contacts or phase."),
                                   QStringLiteral("VIEW"));
    QCommandLineOption plotBodyOption(QStringLiteral("plot-body"),
                                      say("Plot body K (1, 2, …) of the frog's scene alone, marked on the canvas."),
                                      QStringLiteral("K"));
    QCommandLineOption solverOption(QStringLiteral("solver"), say("Run the frog's scene on SOLVER: seed or stable."),
                                    QStringLiteral("SOLVER"));
    QCommandLineOption stepsOption(QStringLiteral("steps"), say("Run the frog's scene N steps (0 … 100000) before showing it."),
                                   QStringLiteral("N"));
    QCommandLineOption listFiguresOption(QStringLiteral("list-figures"),
                                         say("List the thesis's figures: number, variants, caption; and exit."));
    QCommandLineOption figureOption(QStringLiteral("figure"), say("Draw the thesis's figure N (2.1 … 4.13), with --export."),
                                    QStringLiteral("N"));
    QCommandLineOption variantOption(QStringLiteral("variant"), say("The figure's variant V (--list-figures names them)."),
                                     QStringLiteral("V"));
    QCommandLineOption exportOption(QStringLiteral("export"),
                                    say("Write the figure's view alone to FILE (.svg, .pdf, .png, .tex or .csv) and exit."),
                                    QStringLiteral("FILE"));
    QCommandLineOption dpiOption(QStringLiteral("dpi"), say("Resolution of a PNG export, 24 … 1200 (96: one pixel per pixel)."),
                                 QStringLiteral("D"));
    parser.addOptions({tabOption, langOption, exampleOption, sceneOption, presentOption, screenshotOption, sizeOption,
                       plotsOption, plotBodyOption, solverOption, stepsOption, listFiguresOption, figureOption, variantOption,
                       exportOption, dpiOption});
    parser.addPositionalArgument(QStringLiteral("document"), say("A .granota document to open."));
    // Bad arguments are errors as granota-cli's are (status 2, "error: "), in the language above.
    if (!parser.parse(arguments))
        return fail(parser.errorText());
    if (parser.isSet(helpOption))
        parser.showHelp(0);
    if (parser.isSet(versionOption))
        parser.showVersion();

    if (parser.isSet(langOption)) {
        language = parser.value(langOption);
        if (!granota::ui::availableLanguages().contains(language))
            return fail(say("unknown language “%1” (ca, en)").arg(language));
    }
    if (parser.isSet(listFiguresOption)) {
        QTextStream out(stdout);
        for (const granota::ThesisFigure& f : granota::thesisFigures())
            out << QString::fromStdString(f.number) << '\t' << QString::fromStdString(granota::figureVariantNames(f)) << '\t'
                << QString::fromStdString(f.caption.in(language.toStdString())) << '\n';
        return 0;
    }
    // A figure run: the figure and its variant, the file and its format, checked before
    // anything is built.
    const granota::ThesisFigure* figure = nullptr;
    const granota::FigureVariant* variant = nullptr;
    QString figureFormat;
    int dpi = 96;
    if (parser.isSet(figureOption) || parser.isSet(exportOption) || parser.isSet(variantOption) || parser.isSet(dpiOption)) {
        if (!parser.isSet(figureOption) || !parser.isSet(exportOption))
            return fail(say("--figure N and --export FILE go together (--variant and --dpi with them)"));
        figure = granota::findThesisFigure(parser.value(figureOption).toStdString());
        if (!figure)
            return fail(say("unknown figure “%1” (2.1 … 2.10, 4.1 … 4.13; --list-figures)").arg(parser.value(figureOption)));
        variant = granota::findFigureVariant(*figure, parser.value(variantOption).toStdString());
        if (!variant)
            return fail(say("Fig %1 has no variant “%2” (%3)")
                            .arg(parser.value(figureOption), parser.value(variantOption),
                                 QString::fromStdString(granota::figureVariantNames(*figure))));
        figureFormat = QFileInfo(parser.value(exportOption)).suffix().toLower();
        if (!granota::ui::thesisFigureFormats().contains(figureFormat))
            return fail(
                say("cannot tell the format of “%1”: end it in .svg, .pdf, .png, .tex or .csv").arg(parser.value(exportOption)));
        if (parser.isSet(dpiOption)) {
            bool ok = false;
            dpi = parser.value(dpiOption).toInt(&ok);
            if (!ok || dpi < 24 || dpi > 1200)
                return fail(say("bad resolution “%1” (24 … 1200)").arg(parser.value(dpiOption)));
        }
    }
    const bool screenshot = parser.isSet(screenshotOption) || figure;
    // A screenshot is a one-off render: what it changes (the language it was asked for, the
    // document in Open Recent, its autosave) goes to a scratch folder removed on exit, and the
    // user's settings and data stay as they were. The saved language was read above.
    QTemporaryDir scratch;
    if (screenshot) {
        if (!scratch.isValid())
            return fail(say("cannot make a scratch folder for the screenshot run"));
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, scratch.filePath(QStringLiteral("config")));
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, scratch.filePath(QStringLiteral("config")));
        qputenv("XDG_CONFIG_HOME", QFile::encodeName(scratch.filePath(QStringLiteral("config"))));
        qputenv("XDG_DATA_HOME", QFile::encodeName(scratch.filePath(QStringLiteral("data"))));
        qputenv("XDG_CACHE_HOME", QFile::encodeName(scratch.filePath(QStringLiteral("cache"))));
    }
    granota::ui::setLanguage(language, parser.isSet(langOption) && !screenshot);

    granota::ui::MainWindow window;
    // A document given on the command line (a double-click in the file manager): a
    // screenshot run stops on a bad one; a window opens anyway and says what is wrong.
    QString openError;
    if (!parser.positionalArguments().isEmpty() && !window.openFile(parser.positionalArguments().first(), &openError) &&
        screenshot)
        return fail(openError);
    if (parser.isSet(sceneOption)) {
        QString error;
        if (!window.frogTab()->setScene(parser.value(sceneOption), &error))
            return fail(error);
        window.showTab(QStringLiteral("frog"));
    }
    if (parser.isSet(solverOption)) {
        const auto solver = granota::parseSolverKind(parser.value(solverOption).toStdString());
        if (!solver)
            return fail(say("unknown solver “%1” (seed, stable)").arg(parser.value(solverOption)));
        QString error;
        if (!window.frogTab()->setSolver(*solver, &error))
            return fail(error);
        window.showTab(QStringLiteral("frog"));
    }
    if (parser.isSet(plotsOption)) {
        using View = granota::ui::FrogPlotPanel::View;
        const QString name = parser.value(plotsOption);
        const std::pair<const char*, View> views[] = {{"energy", View::Energy},
                                                      {"area", View::AreaError},
                                                      {"stretch", View::Stretch},
                                                      {"contacts", View::Contacts},
                                                      {"phase", View::Phase}};
        const auto found = std::find_if(std::begin(views), std::end(views),
                                        [&](const auto& v) { return name == QLatin1String(v.first); });
        if (found == std::end(views))
            return fail(say("unknown plot “%1” (energy, area, stretch, contacts, phase)").arg(name));
        window.frogTab()->setPlotsShown(true);
        window.frogTab()->plotPanel()->setView(found->second);
        if (window.frogTab()->plotPanel()->view() != found->second)
            return fail(say("the phase plot is the pendulums' only (--scene pendulum, pendulum-limits)"));
        window.showTab(QStringLiteral("frog"));
    }
    if (parser.isSet(stepsOption)) {
        bool ok = false;
        const int steps = parser.value(stepsOption).toInt(&ok);
        if (!ok || steps < 0 || steps > 100000)
            return fail(say("bad number of steps “%1” (0 … 100000)").arg(parser.value(stepsOption)));
        for (int i = 0; i < steps; ++i)
            window.frogTab()->frogRun()->step();
        window.frogTab()->plotPanel()->refresh(true);
    }
    if (parser.isSet(plotBodyOption)) {
        granota::ui::FrogTab* frog = window.frogTab();
        if (!frog->plotPanel()->isVisibleTo(&window) && !parser.isSet(plotsOption))
            frog->setPlotsShown(true);
        frog->plotPanel()->refresh(true);
        const int bodies = frog->frogRun()->series().bodies();
        bool ok = false;
        const int k = parser.value(plotBodyOption).toInt(&ok);
        if (bodies < 2)
            return fail(say("--plot-body: the scene has no bodies to choose from (it needs two or more)"));
        if (!ok || k < 1 || k > bodies)
            return fail(say("bad body “%1” (1 … %2)").arg(parser.value(plotBodyOption)).arg(bodies));
        frog->plotPanel()->setBody(k - 1);
        window.showTab(QStringLiteral("frog"));
    }
    if (parser.isSet(exampleOption) && !window.loadExample(parser.value(exampleOption)))
        return fail(say("unknown example “%1” (2.1 … 2.13)").arg(parser.value(exampleOption)));
    if (parser.isSet(tabOption) && !window.showTab(parser.value(tabOption)))
        return fail(
            say("unknown tab “%1” (decasteljau, bernstein, fit, catmull-rom, frog, bspline)").arg(parser.value(tabOption)));

    QSize size = screenshot ? QSize(1280, 800) : window.size();
    if (figure) {
        // The window is laid out as on a 1280×800 screen but never shown; the figure's view
        // alone is drawn at --size (800×600 unless asked).
        QSize figureSize(800, 600);
        if (parser.isSet(sizeOption)) {
            const QSize asked = sizeOf(parser.value(sizeOption));
            if (asked.isEmpty())
                return fail(say("bad size “%1” (WxH, e.g. 800x570)").arg(parser.value(sizeOption)));
            figureSize = asked;
        }
        window.resize(size);
        window.setAttribute(Qt::WA_DontShowOnScreen);
        window.show();
        QApplication::processEvents();
        QString error;
        if (!granota::ui::showThesisFigure(window, *figure, *variant, false, &error))
            return fail(error);
        QApplication::processEvents();
        if (auto* fit = qobject_cast<granota::ui::FitTab*>(window.currentTab()))
            fit->finishFit();
        if (const QString e = granota::ui::exportThesisFigure(window, *figure, figureFormat, parser.value(exportOption),
                                                              figureSize, dpi);
            !e.isEmpty())
            return fail(e);
        return 0;
    }
    if (parser.isSet(sizeOption)) {
        size = sizeOf(parser.value(sizeOption));
        if (size.isEmpty())
            return fail(say("bad size “%1” (WxH, e.g. 800x570)").arg(parser.value(sizeOption)));
    }
    window.resize(size);
    if (screenshot) {
        if (parser.isSet(presentOption))
            window.setPresentation(true, false);
        window.show();
        for (int i = 0; i < 5; ++i) // let layouts settle and the frog canvas draw a few frames
            QApplication::processEvents();
        // A long fit runs in the background: the picture of the Fitting tab shows it finished.
        if (auto* fit = qobject_cast<granota::ui::FitTab*>(window.currentTab()))
            fit->finishFit();
        const QString file = parser.value(screenshotOption);
        // Replaces the file whole (ui/files/exporter.h): a full disk keeps the old one.
        if (const QString error = granota::ui::writePngFile(window.grab().toImage(), file); !error.isEmpty())
            return fail(error);
        return 0;
    }
    if (parser.isSet(sizeOption))
        window.show(); // the size asked for
    else
        window.showFitted(); // maximised on a small screen
    if (parser.isSet(presentOption))
        window.setPresentation(true);
    if (!openError.isEmpty())
        window.showOpenError(openError);
    else
        window.offerRecovery();
    return app.exec();
}
