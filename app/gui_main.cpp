// granota: the desktop application (SPEC §1, §5).
#include "ui/main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTextStream>

int main(int argc, char* argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("Granota"));
    QApplication::setOrganizationName(QStringLiteral("Granota"));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Splines and soft bodies, for the classroom."));
    parser.addHelpOption();
    QCommandLineOption tabOption(QStringLiteral("tab"), QStringLiteral("Open on tab KEY."), QStringLiteral("KEY"));
    parser.addOption(tabOption);
    parser.process(app);

    granota::ui::MainWindow window;
    if (parser.isSet(tabOption) && !window.showTab(parser.value(tabOption))) {
        QTextStream(stderr) << "error: unknown tab '" << parser.value(tabOption)
                            << "' (decasteljau, bernstein, fit, catmull-rom, frog)\n";
        return 2;
    }
    window.show();
    return app.exec();
}
