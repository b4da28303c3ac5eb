// granota-cli report NAME|all --out DIR: the work-precision reports of docs/work-precision.md as files —
// NAME.csv (with the machine and the build in its header), NAME.svg and NAME.png, drawn by
// the same plotting code as the tabs.
#include "app/cli/command.h"
#include "app/cli/output_file.h"
#include "core/base/display_text.h"
#include "core/reports/work_precision.h"

#include <QApplication>
#include <QBuffer>
#include <QLocale>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>
#include <QSysInfo>
#include <qcustomplot.h>

#include "ui/common/work_precision_plot.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

#ifndef GRANOTA_BUILD_TYPE
#define GRANOTA_BUILD_TYPE "unknown"
#endif

namespace granota::cli {

namespace {

std::string cpuModel()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "unknown";
}

std::vector<std::string> context()
{
    return {"machine: " + cpuModel() + ", " + std::to_string(std::thread::hardware_concurrency()) + " threads, " +
                QSysInfo::prettyProductName().toStdString(),
            std::string("build: ") + GRANOTA_BUILD_TYPE + ", " + "g++ " + __VERSION__, "command: granota-cli report"};
}

/// Renders the report's plot to SVG and PNG with QCustomPlot. Needs a QApplication: the
/// command makes one on the offscreen platform (no display needed). The images are drawn
/// in memory and written by writeFile(), so that a failed write says which file and why.
Expected<void> writePlots(const WorkPrecisionReport& report, const std::string& base)
{
    QCustomPlot plot;
    plot.resize(900, 600);
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(
        0, 0, new QCPTextElement(&plot, QString::fromStdString(report.title), QFont(QStringLiteral("Sans"), 12, QFont::Bold)));
    ui::plotWorkPrecision(&plot, report);

    QImage image = plot.toPixmap(900, 600, 1.0).toImage();
    constexpr int kDotsPerMeter = 3780; // 96 dpi, what QCustomPlot::savePng writes
    image.setDotsPerMeterX(kDotsPerMeter);
    image.setDotsPerMeterY(kDotsPerMeter);
    QByteArray png;
    QBuffer pngBuffer(&png);
    if (!pngBuffer.open(QIODevice::WriteOnly) || !image.save(&pngBuffer, "PNG"))
        return makeError(ErrorCode::InvalidInput, "cannot draw " + quotedForDisplay(base + ".png"));
    if (auto written = writeFile(base + ".png", std::string_view(png.constData(), static_cast<std::size_t>(png.size())));
        !written)
        return written.error();

    QByteArray svgBytes;
    QBuffer svgBuffer(&svgBytes);
    svgBuffer.open(QIODevice::WriteOnly);
    {
        QSvgGenerator svg;
        svg.setOutputDevice(&svgBuffer);
        svg.setSize(QSize(900, 600));
        svg.setViewBox(QRect(0, 0, 900, 600));
        svg.setTitle(QString::fromStdString(report.title));
        QCPPainter painter;
        if (!painter.begin(&svg))
            return makeError(ErrorCode::InvalidInput, "cannot draw " + quotedForDisplay(base + ".svg"));
        plot.toPainter(&painter, 900, 600);
        painter.end();
    }
    return writeFile(base + ".svg", std::string_view(svgBytes.constData(), static_cast<std::size_t>(svgBytes.size())));
}

Expected<CommandOutput> run(const Arguments& args)
{
    const std::string name = args.positional().empty() ? "" : args.positional().front();
    if (name.empty())
        return makeError(ErrorCode::InvalidInput, "report needs a NAME (curve-sampling, catmull-rom-sampling, "
                                                  "bezier-evaluation, least-squares, integrators, energy-drift, soft-body, "
                                                  "arc-length, bspline-evaluation, all)");
    const auto out = args.value("out");
    if (!out || out->empty())
        return makeError(ErrorCode::InvalidInput, "report needs --out DIR");
    std::vector<std::string> names;
    if (name == "all")
        names = workPrecisionReportNames();
    else
        names.push_back(name);
    for (const auto& n : names) {
        const auto known = workPrecisionReportNames();
        if (std::find(known.begin(), known.end(), n) == known.end())
            return runWorkPrecisionReport(n).error(); // the core's message lists the names
    }
    const QString dir = QString::fromStdString(*out);
    if (!QDir().mkpath(dir))
        return makeError(ErrorCode::InvalidInput, "cannot create directory " + quotedForDisplay(*out));

    // QCustomPlot draws with QtGui: an offscreen application is enough, no display.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char arg0[] = "granota-cli";
    static char* argv[] = {arg0, nullptr};
    std::unique_ptr<QApplication> app;
    if (!QCoreApplication::instance()) {
        // Starting Qt's GUI side headless prints notes (no XDG_RUNTIME_DIR…) that are not
        // errors of ours: keep stderr for real errors.
        const QtMessageHandler previous = qInstallMessageHandler([](QtMsgType type, const QMessageLogContext&, const QString& m) {
            if (type == QtCriticalMsg || type == QtFatalMsg)
                std::fprintf(stderr, "%s\n", qPrintable(m));
        });
        app = std::make_unique<QApplication>(argc, argv);
        qInstallMessageHandler(previous);
    }
    // The plots' axes and legends are files the scripter keeps: numbers with a point, not
    // in the desktop's locale (QApplication has just set LC_NUMERIC from the environment).
    QLocale::setDefault(QLocale::c());

    WorkPrecisionOptions options;
    options.quick = args.flag("quick");
    CommandOutput output;
    Json files = Json::array();
    std::ostringstream text;
    for (const auto& n : names) {
        auto report = runWorkPrecisionReport(n, options);
        if (!report)
            return report.error();
        const std::string base = QDir(dir).filePath(QString::fromStdString(n)).toStdString();
        if (auto csv = writeFile(base + ".csv", workPrecisionCsv(*report, context())); !csv)
            return csv.error();
        auto plots = writePlots(*report, base);
        if (!plots)
            return plots.error();
        Json entry = Json::object();
        entry.set("report", n).set("csv", base + ".csv").set("svg", base + ".svg").set("png", base + ".png");
        files.push(entry);
        text << n << ": " << report->lesson << "\n  wrote " << base + ".csv"
             << ", .svg, .png\n";
    }
    output.json.set("reports", files);
    output.text = text.str();
    return output;
}

} // namespace

Command reportCommand()
{
    return {"report", "NAME|all --out DIR [--quick] [--json]",
            "error against run time as CSV, SVG and PNG: curve-sampling, catmull-rom-sampling, bezier-evaluation, "
            "least-squares, integrators, energy-drift (energy against step), soft-body, arc-length, bspline-evaluation",
            CommandSyntax{{"out"}, {"quick", "json"}, {}, 1}, run};
}

} // namespace granota::cli
