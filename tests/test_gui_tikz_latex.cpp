// File ▸ Export ▸ TikZ (issue 14, item 15; docs/tabs.md): the picture of every tab, exported
// by the main window as the menu does, compiles with pdflatex inside an article and inside a
// beamer frame, and fits: no overfull box, no error, the picture no wider than the text and
// its bottom above the frame's navigation bar. Without pdflatex this test fails (CI
// installs it: .ci/deps.sh).
#include "core/io/thesis_figures.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "ui/shell/thesis_figure_export.h"
#include "ui/files/tikz_options.h"

#include "main_window_steps.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include "tests/test_main.h"

#include <vector>

using granota::ui::MainWindow;
using granota::ui::TikzOptions;

namespace {

constexpr double kPtPerCm = 72.27 / 2.54;

/// One exported figure: its file name (without .tex) and the tab it shows.
struct Figure {
    QString name;
    QString tab;
};

/// What the log of one pdflatex run says of each figure, in pt.
struct Measure {
    double width = 0, height = 0, textWidth = 0, bottom = -1;
};

/// Exports the TikZ picture of every tab into `dir` through the main window (the GUI's
/// own path), with `options`; De Casteljau shows Ex 2.2, the widest of chapter 2.
std::vector<Figure> exportFigures(MainWindow& window, const QDir& dir, const TikzOptions& options, const QString& suffix)
{
    std::vector<Figure> figures;
    const auto add = [&](const QString& tab, const char* example) {
        if (example && !window.loadExample(QString::fromLatin1(example)))
            return;
        if (!window.showTab(tab))
            return;
        const QString name = QStringLiteral("fig-%1%2-%3")
                                 .arg(tab, suffix, QString::fromLatin1(example ? example : "0"))
                                 .replace(QLatin1Char('.'), QLatin1Char('_'));
        if (window.exportCurrent(QStringLiteral("tikz"), dir.filePath(name + QStringLiteral(".tex")), 96, options).isEmpty())
            figures.push_back({name, tab});
    };
    add(QStringLiteral("decasteljau"), "2.2");
    // Ex 2.3 with the hodograph's inset (a scope of its own, clipped) and the comb.
    if (auto* dc = window.findChild<granota::ui::DeCasteljauTab*>()) {
        dc->setHodographVisible(true);
        dc->setCombVisible(true);
    }
    add(QStringLiteral("decasteljau"), "2.3");
    add(QStringLiteral("bernstein"), nullptr);
    add(QStringLiteral("bernstein"), "2.4");
    add(QStringLiteral("fit"), "2.8");
    add(QStringLiteral("fit"), "2.10");
    add(QStringLiteral("catmull-rom"), "2.11");
    add(QStringLiteral("catmull-rom"), "2.13");
    add(QStringLiteral("frog"), nullptr);
    return figures;
}

/// A document of class `documentClass` with every figure in it (each on its own beamer
/// frame, with a title and a line of text below), which writes each figure's size, the
/// text width and the height of the figure's bottom above the page's foot to the log.
QString documentWith(const QString& documentClass, const std::vector<Figure>& figures)
{
    QString tex = QStringLiteral("\\documentclass{%1}\n\\usepackage{tikz}\n\\begin{document}\n").arg(documentClass);
    const bool beamer = documentClass == QLatin1String("beamer");
    for (const Figure& f : figures) {
        tex += beamer ? QStringLiteral("\\begin{frame}{%1}\n").arg(f.tab) : QStringLiteral("\\section*{%1}\n").arg(f.tab);
        tex += QStringLiteral("\\setbox0=\\hbox{\\input{%1}}%%\n"
                              "\\typeout{GRANOTA %1 width=\\the\\wd0 \\space height=\\the\\dimexpr\\ht0+\\dp0\\relax"
                              "\\space textwidth=\\the\\textwidth}%%\n"
                              "\\noindent\\input{%1}\\par\n"
                              "\\pdfsavepos\\write-1{GRANOTA %1 bottom=\\the\\pdflastypos sp}%%\n"
                              "Text below the figure.\n")
                   .arg(f.name);
        tex += beamer ? QStringLiteral("\\end{frame}\n") : QStringLiteral("\\clearpage\n");
    }
    return tex + QStringLiteral("\\end{document}\n");
}

/// Runs pdflatex on `tex` in `dir`: the log, or a failure message in `error`.
QString compile(const QDir& dir, const QString& name, const QString& tex, QString* error)
{
    QFile file(dir.filePath(name + QStringLiteral(".tex")));
    if (!file.open(QIODevice::WriteOnly) || file.write(tex.toUtf8()) < 0) {
        *error = QStringLiteral("cannot write ") + file.fileName();
        return {};
    }
    file.close();
    const QString pdflatex = QStandardPaths::findExecutable(QStringLiteral("pdflatex"));
    if (pdflatex.isEmpty()) {
        *error = QStringLiteral("pdflatex not found: install texlive-pictures (see .ci/deps.sh)");
        return {};
    }
    QProcess p;
    p.setWorkingDirectory(dir.path());
    // One log line per message (TeX breaks them at 79 characters otherwise).
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("max_print_line"), QStringLiteral("100000"));
    p.setProcessEnvironment(env);
    p.start(pdflatex,
            {QStringLiteral("-halt-on-error"), QStringLiteral("-interaction=nonstopmode"), name + QStringLiteral(".tex")});
    if (!p.waitForFinished(300000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
        *error =
            QStringLiteral("pdflatex failed on %1:\n…%2").arg(name, QString::fromUtf8(p.readAllStandardOutput().right(1500)));
    QFile log(dir.filePath(name + QStringLiteral(".log")));
    if (!log.open(QIODevice::ReadOnly)) {
        *error += QStringLiteral("no log");
        return {};
    }
    return QString::fromUtf8(log.readAll());
}

double points(const QString& s) { return s.toDouble(); }

/// The sizes the log reports for `figure`.
Measure measure(const QString& log, const QString& figure)
{
    Measure m;
    const QRegularExpression size(QStringLiteral("GRANOTA %1 width=([0-9.]+)pt height=([0-9.]+)pt textwidth=([0-9.]+)pt")
                                      .arg(QRegularExpression::escape(figure)));
    const auto s = size.match(log);
    if (s.hasMatch()) {
        m.width = points(s.captured(1));
        m.height = points(s.captured(2));
        m.textWidth = points(s.captured(3));
    }
    const QRegularExpression bottom(QStringLiteral("GRANOTA %1 bottom=(-?[0-9]+)sp").arg(QRegularExpression::escape(figure)));
    const auto b = bottom.match(log);
    if (b.hasMatch())
        m.bottom = b.captured(1).toDouble() / 65536.0;
    return m;
}

} // namespace

class TestGuiTikzLatex : public QObject {
    Q_OBJECT

    /// Exports every tab with `options` and compiles the figures in an article and in beamer.
    void compileAndCheck(const TikzOptions& options, const QString& suffix)
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::vector<Figure> figures = exportFigures(window, QDir(dir.path()), options, suffix);
        QCOMPARE(figures.size(), std::size_t(9));
        checkDocuments(dir, figures, options);
    }

    /// Compiles `figures` (in `dir`) in an article and in beamer: no error, no overfull box,
    /// each as wide as `options` ask at most and above beamer's navigation bar.
    void checkDocuments(const QTemporaryDir& dir, const std::vector<Figure>& figures, const TikzOptions& options)
    {
        for (const QString& documentClass : {QStringLiteral("article"), QStringLiteral("beamer")}) {
            QString error;
            const QString log = compile(QDir(dir.path()), documentClass, documentWith(documentClass, figures), &error);
            QVERIFY2(error.isEmpty(), qPrintable(error));
            QVERIFY2(!log.contains(QStringLiteral("Overfull \\hbox")),
                     qPrintable(documentClass + QStringLiteral(": overfull \\hbox")));
            QVERIFY2(!log.contains(QStringLiteral("Overfull \\vbox")),
                     qPrintable(documentClass + QStringLiteral(": overfull \\vbox")));
            QVERIFY2(!log.contains(QRegularExpression(QStringLiteral("^! "), QRegularExpression::MultilineOption)),
                     qPrintable(documentClass + QStringLiteral(": a LaTeX error")));
            for (const Figure& f : figures) {
                const Measure m = measure(log, f.name);
                const QString what = QStringLiteral("%1 in %2: %3 × %4 pt, text width %5 pt, bottom %6 pt")
                                         .arg(f.name, documentClass)
                                         .arg(m.width)
                                         .arg(m.height)
                                         .arg(m.textWidth)
                                         .arg(m.bottom);
                QVERIFY2(m.width > 0 && m.height > 0, qPrintable(what));
                QVERIFY2(m.width <= m.textWidth, qPrintable(what));
                // The width asked for, give or take what the labels take beyond their margin.
                QVERIFY2(m.width <= options.widthCm * kPtPerCm + 0.5, qPrintable(what));
                QVERIFY2(m.height <= options.maxHeightCm * kPtPerCm + 0.5, qPrintable(what));
                // Beamer's navigation bar takes the frame's lowest ~0.5 cm; the figure stays above it.
                if (documentClass == QLatin1String("beamer"))
                    QVERIFY2(m.bottom >= 0.5 * kPtPerCm, qPrintable(what));
            }
        }
    }

private slots:
    // The default export (a beamer frame's text width with a margin) of every tab.
    void everyTabFitsArticleAndBeamer() { compileAndCheck(TikzOptions(), QString()); }

    // The thesis's 23 figures (issue 33; granota --figure N --export F.tex), each in its
    // default variant, compile in one beamer document (and an article) and fit their frames.
    void everyThesisFigureCompiles()
    {
        MainWindow window;
        window.resize(1280, 800);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        std::vector<Figure> figures;
        for (const granota::ThesisFigure& f : granota::thesisFigures()) {
            QString error;
            QVERIFY2(granota::ui::showThesisFigure(window, f, f.variants.front(), false, &error), qPrintable(error));
            const QString name =
                QStringLiteral("thesis-fig-%1").arg(QString::fromStdString(f.number)).replace(QLatin1Char('.'), QLatin1Char('_'));
            const QString exported = granota::ui::exportThesisFigure(window, f, QStringLiteral("tex"),
                                                                     dir.filePath(name + QStringLiteral(".tex")), QSize(), 96);
            QVERIFY2(exported.isEmpty(), qPrintable(exported));
            figures.push_back({name, QStringLiteral("Fig ") + QString::fromStdString(f.number)});
        }
        QCOMPARE(figures.size(), std::size_t(23));
        checkDocuments(dir, figures, TikzOptions());
    }

    // With axes, tick labels and a grid it still compiles and fits.
    void withAxesAndGrid()
    {
        TikzOptions options;
        options.axes = true;
        options.grid = true;
        compileAndCheck(options, QStringLiteral("-axes"));
    }
};

GRANOTA_TEST_MAIN(TestGuiTikzLatex)
#include "test_gui_tikz_latex.moc"
