// The layout on small screens (docs/classroom.md): every tab, in Catalan and in English, at
// 800×600 (a window of 800×570, the screen less a title bar), at the classroom size 1280×800,
// and in presentation mode at 1024×768 (1024×738), with the reports panel closed and open.
// Nothing may be elided or clipped — a label's, button's, group box's, combo box's or spin
// box's text fits its widget, a plot's axis titles fit the plot — and no widget lies outside
// the window (or outside the viewport of the scroll area that scrolls it); the window's
// minimumSizeHint fits the size, so a window manager lets the window be that small. In
// presentation mode the side panels are folded away (a drawer, View ▸ Side panel) and the
// canvas has the window's width; opened, the drawer shows everything whole too.
#include "main_window_steps.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/plot_tick_room.h"
#include "ui/frog/frog_canvas.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "gui_timeouts.h"

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScopeGuard>
#include <QStyleOptionComboBox>
#include <QTest>
#include "tests/test_main.h"
#include <QTextDocument>

#include <qcustomplot.h>

using granota::ui::MainWindow;

namespace {

/// A window the size of a screen less its title bar (a window manager's frame is ~30 px).
constexpr int kTitleBar = 30;

QString describe(const QWidget* w)
{
    QString text;
    if (auto* l = qobject_cast<const QLabel*>(w))
        text = l->text();
    else if (auto* b = qobject_cast<const QAbstractButton*>(w))
        text = b->text();
    else if (auto* g = qobject_cast<const QGroupBox*>(w))
        text = g->title();
    else if (auto* c = qobject_cast<const QComboBox*>(w))
        text = c->currentText();
    else if (auto* e = qobject_cast<const QLineEdit*>(w))
        text = e->text();
    if (text.size() > 60)
        text = text.left(57) + QStringLiteral("…");
    QString path;
    for (const QWidget* p = w->parentWidget(); p && !p->isWindow(); p = p->parentWidget())
        if (!p->objectName().isEmpty() && !p->objectName().startsWith(QLatin1String("qt_"))) {
            path = p->objectName();
            break;
        }
    return QStringLiteral("%1 \"%2\" [%3] in %4 at %5,%6 %7×%8")
        .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName(), text, path)
        .arg(w->mapTo(w->window(), QPoint()).x())
        .arg(w->mapTo(w->window(), QPoint()).y())
        .arg(w->width())
        .arg(w->height());
}

/// The scroll area viewport that `w` is scrolled in, if any.
const QWidget* scrollingViewport(const QWidget* w)
{
    for (const QWidget* p = w->parentWidget(); p && !p->isWindow(); p = p->parentWidget())
        if (auto* area = qobject_cast<const QAbstractScrollArea*>(p->parentWidget()))
            if (area->viewport() == p)
                return p;
    return nullptr;
}

QString plainOf(const QString& text, Qt::TextFormat format)
{
    if (format == Qt::RichText || (format == Qt::AutoText && Qt::mightBeRichText(text))) {
        QTextDocument doc;
        doc.setHtml(text);
        return doc.toPlainText();
    }
    return text;
}

/// The problems of one widget's text: what is elided or clipped.
void checkText(QWidget* w, QStringList& problems)
{
    const QFontMetrics fm = w->fontMetrics();
    if (auto* l = qobject_cast<QLabel*>(w)) {
        if (l->text().isEmpty() || l->width() == 0)
            return;
        const QRect content = l->contentsRect();
        if (l->wordWrap()) {
            const int needed = l->heightForWidth(l->width());
            if (needed > l->height() + 1)
                problems << QStringLiteral("wrapped label needs height %1: %2").arg(needed).arg(describe(w));
        } else {
            const QSize hint = l->sizeHint();
            QString plain = plainOf(l->text(), l->textFormat());
            if (l->buddy()) // the mnemonic's & is not shown
                plain.replace(QRegularExpression(QStringLiteral("&(.)")), QStringLiteral("\\1"));
            int textWidth = 0;
            for (const QString& line : plain.split(QLatin1Char('\n')))
                textWidth = std::max(textWidth, fm.horizontalAdvance(line));
            if (textWidth > content.width() + 1 || hint.height() > l->height() + 1)
                problems << QStringLiteral("label text %1×%2 clipped: %3").arg(textWidth).arg(hint.height()).arg(describe(w));
        }
    } else if (auto* b = qobject_cast<QAbstractButton*>(w)) {
        if (b->text().isEmpty())
            return;
        const QSize hint = b->sizeHint();
        QString text = b->text();
        text.remove(QLatin1Char('&'));
        const int textWidth = fm.horizontalAdvance(text);
        const bool plain = qobject_cast<QPushButton*>(w) != nullptr;
        // A push button's hint has a minimum width of its own; its text is what must fit.
        const bool fits = hint.width() <= b->width() || (plain && textWidth + 6 <= b->width());
        if (!fits || fm.height() > b->height())
            problems << QStringLiteral("button needs %1×%2: %3").arg(hint.width()).arg(hint.height()).arg(describe(w));
    } else if (auto* g = qobject_cast<QGroupBox*>(w)) {
        if (g->title().isEmpty())
            return;
        QString title = g->title();
        title.remove(QLatin1Char('&'));
        const int needed = fm.horizontalAdvance(title) + (g->isCheckable() ? fm.height() + 8 : 4);
        if (needed > g->width())
            problems << QStringLiteral("group box title needs width %1: %2").arg(needed).arg(describe(w));
    } else if (auto* c = qobject_cast<QComboBox*>(w)) {
        if (c->currentText().isEmpty())
            return;
        QStyleOptionComboBox option;
        option.initFrom(c);
        option.editable = c->isEditable();
        const QRect field = c->style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, c);
        // Every choice, not only the current one: any of them may be chosen and then shown.
        for (int i = 0; i < c->count(); ++i) {
            const int textWidth = fm.horizontalAdvance(c->itemText(i)) +
                                  (c->itemIcon(i).isNull() ? 0 : c->iconSize().width() + 4);
            if (textWidth > field.width())
                problems << QStringLiteral("combo item “%1” needs %2 in a field of %3: %4")
                                .arg(c->itemText(i))
                                .arg(textWidth)
                                .arg(field.width())
                                .arg(describe(w));
        }
    } else if (auto* e = qobject_cast<QLineEdit*>(w)) {
        // A spin box's field: its value and suffix ("100.00 px/step²") must show whole.
        if (!qobject_cast<QAbstractSpinBox*>(w->parentWidget()) || e->text().isEmpty())
            return;
        const int textWidth = fm.horizontalAdvance(e->text());
        if (textWidth > e->contentsRect().width() - 2)
            problems << QStringLiteral("spin box text needs %1: %2").arg(textWidth).arg(describe(w));
    }
}

/// The problems of one plot: axis titles and tick labels outside the plot.
void checkPlot(QCustomPlot* plot, QStringList& problems)
{
    for (QCPAxisRect* axisRect : plot->axisRects()) {
        if (!axisRect->visible())
            continue;
        const QRect inner = axisRect->rect();
        if (inner.width() < 20 || inner.height() < 20)
            problems
                << QStringLiteral("plot area %1×%2 is too small: %3").arg(inner.width()).arg(inner.height()).arg(describe(plot));
        for (QCPAxis* axis : axisRect->axes()) {
            if (!axis->visible())
                continue;
            const QFontMetrics labelMetrics(axis->labelFont());
            const QFontMetrics tickMetrics(axis->tickLabelFont());
            const bool horizontal = axis->orientation() == Qt::Horizontal;
            // What sits outside the axis rect on this side: ticks, their labels and the title.
            int needed = axis->offset() + axis->tickLengthOut();
            if (axis->tickLabels()) {
                int widest = 0;
                for (const QString& tick : axis->tickVectorLabels())
                    widest = std::max(widest, tickMetrics.horizontalAdvance(tick));
                needed += axis->tickLabelPadding() + (horizontal ? tickMetrics.height() : widest);
            }
            if (!axis->label().isEmpty()) {
                needed += axis->labelPadding() + labelMetrics.height();
                // The title runs along the axis, centred on it: it must fit the plot that way too.
                const int length = labelMetrics.horizontalAdvance(axis->label());
                const int centre = horizontal ? inner.center().x() : inner.center().y();
                const int extent = horizontal ? plot->width() : plot->height();
                if (centre - length / 2 < 0 || centre + length / 2 > extent)
                    problems << QStringLiteral("axis title \"%1\" (%2 px) does not fit along the plot: %3")
                                    .arg(axis->label())
                                    .arg(length)
                                    .arg(describe(plot));
            }
            int margin = 0;
            int room = 0;
            switch (axis->axisType()) {
            case QCPAxis::atLeft:
                margin = axisRect->margins().left();
                room = inner.left();
                break;
            case QCPAxis::atRight:
                margin = axisRect->margins().right();
                room = plot->width() - inner.right();
                break;
            case QCPAxis::atTop:
                margin = axisRect->margins().top();
                room = inner.top();
                break;
            case QCPAxis::atBottom:
                margin = axisRect->margins().bottom();
                room = plot->height() - inner.bottom();
                break;
            }
            if (axis->label().isEmpty() && !axis->tickLabels())
                continue;
            // Each tick label is centred on its tick along the axis: the outermost ones must
            // not reach past the plot's edges ("−0,5" at the left end read "0,5").
            if (axis->tickLabels()) {
                const QVector<double> ticks = axis->tickVector();
                const QVector<QString> labels = axis->tickVectorLabels();
                const int extent = horizontal ? plot->width() : plot->height();
                for (int i = 0; i < ticks.size() && i < labels.size(); ++i) {
                    if (!axis->range().contains(ticks[i]) || labels[i].isEmpty())
                        continue;
                    const double at = axis->coordToPixel(ticks[i]);
                    const QRect box = tickMetrics.boundingRect(labels[i]);
                    const double half = 0.5 * (horizontal ? box.width() : box.height());
                    if (at - half < 0 || at + half > extent)
                        problems << QStringLiteral(
                                        "tick label \"%1\" of axis %2 reaches past the plot's edge (%3 ± %4 in %5): %6")
                                        .arg(labels[i])
                                        .arg(int(axis->axisType()))
                                        .arg(at)
                                        .arg(half)
                                        .arg(extent)
                                        .arg(describe(plot));
                }
            }
            if (std::min(margin, room) < needed)
                problems << QStringLiteral("axis %1 \"%2\" needs %3 px beside the plot area, has %4: %5")
                                .arg(int(axis->axisType()))
                                .arg(axis->label())
                                .arg(needed)
                                .arg(std::min(margin, room))
                                .arg(describe(plot));
        }
    }
}

/// Everything wrong with the window as shown now.
QStringList layoutProblems(MainWindow& window, QSize size)
{
    QStringList problems;
    const QRect frame(QPoint(), size);
    if (window.size() != size)
        problems << QStringLiteral("the window is %1×%2, not %3×%4 (its minimum size is %5×%6)")
                        .arg(window.width())
                        .arg(window.height())
                        .arg(size.width())
                        .arg(size.height())
                        .arg(window.minimumSize().width())
                        .arg(window.minimumSize().height());
    const QSize minimum = window.minimumSizeHint();
    if (minimum.width() > frame.width() || minimum.height() > frame.height())
        problems << QStringLiteral("the window's minimumSizeHint %1×%2 exceeds %3×%4")
                        .arg(minimum.width())
                        .arg(minimum.height())
                        .arg(frame.width())
                        .arg(frame.height());
    for (QWidget* w : window.findChildren<QWidget*>()) {
        if (!w->isVisible() || w->isWindow() || w->window() != &window)
            continue;
        const QRect inWindow(w->mapTo(&window, QPoint()), w->size());
        const QWidget* viewport = scrollingViewport(w);
        if (!viewport && !frame.contains(inWindow))
            problems << QStringLiteral("outside the window %1×%2: %3").arg(frame.width()).arg(frame.height()).arg(describe(w));
        // In a scroll area a widget may be scrolled out of view; what is in view must be whole.
        checkText(w, problems);
        if (auto* plot = qobject_cast<QCustomPlot*>(w))
            checkPlot(plot, problems);
        // A scroll area cuts off what is wider than it (or taller, if it cannot scroll that way).
        if (auto* area = qobject_cast<QScrollArea*>(w); area && area->widget()) {
            const QSize content = area->widget()->size(), view = area->viewport()->size();
            // Side panels scroll up and down only: a row cut at the side is a row nobody reads.
            if (content.width() > view.width() ||
                (area->verticalScrollBarPolicy() == Qt::ScrollBarAlwaysOff && content.height() > view.height()))
                problems << QStringLiteral("scroll area cuts its %1×%2 content to %3×%4: %5")
                                .arg(content.width())
                                .arg(content.height())
                                .arg(view.width())
                                .arg(view.height())
                                .arg(describe(w));
        }
    }
    return problems;
}

/// The tab's canvas (or, in the Bernstein tab, its plot): the largest drawing it shows.
QWidget* canvasOf(granota::ui::TabPage* page)
{
    QWidget* best = nullptr;
    const auto area = [](const QWidget* w) { return w->width() * w->height(); };
    for (QWidget* w : page->findChildren<QWidget*>())
        if (w->isVisible() &&
            (qobject_cast<granota::ui::CurveCanvas*>(w) || qobject_cast<granota::ui::FrogCanvas*>(w) ||
             qobject_cast<QCustomPlot*>(w)) &&
            (!best || area(w) > area(best)))
            best = w;
    return best;
}

/// In presentation mode with the drawer folded: the canvas has (nearly) the tab's width and
/// at least 40 % of its area (it was 545×225 in the Fitting tab at 1024×768).
QString canvasProblem(granota::ui::TabPage* page)
{
    const QWidget* canvas = canvasOf(page);
    if (!canvas)
        return QStringLiteral("no canvas");
    const double share = double(canvas->width()) * canvas->height() / (double(page->width()) * page->height());
    if (canvas->width() < page->width() * 9 / 10 || share < 0.4)
        return QStringLiteral("the canvas is %1×%2 in a tab of %3×%4 (%5 % of it)")
            .arg(canvas->width())
            .arg(canvas->height())
            .arg(page->width())
            .arg(page->height())
            .arg(int(share * 100));
    return QString();
}

} // namespace

class TestGuiLayout : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { useTestSettings(); }
    void cleanupTestCase() { granota::ui::setLanguage(QStringLiteral("en"), false); }

    /// The window opens no larger than the screen it is on.
    void opensWithinTheScreen()
    {
        MainWindow window;
        const QRect available = window.screen()->availableGeometry();
        QVERIFY2(window.width() <= available.width() && window.height() <= available.height(),
                 qPrintable(QStringLiteral("%1×%2 on a screen of %3×%4")
                                .arg(window.width())
                                .arg(window.height())
                                .arg(available.width())
                                .arg(available.height())));
    }

    // Issue 34, item 8: "−0,5" read "0,5" at the left edge. The canvas's grid labels: a label
    // starts 3 px right of its line, so the line just off the left edge had its label cut there,
    // minus sign first. Every label drawn lies wholly inside the canvas, and names its own line.
    void gridLabelsAreWholeAndTheirLines()
    {
        granota::ui::CurveCanvas canvas;
        canvas.resize(400, 300);
        canvas.show();
        QVERIFY(waitExposed(&canvas));
        int labelled = 0;
        // The view's left edge slides across the grid lines near x = −0.5, a pixel at a time.
        for (int shift = 0; shift < 60; ++shift) {
            canvas.setContentBounds(QRectF(-0.45 + shift * 0.002, -1, 2, 2));
            canvas.fitToContent();
            const auto& view = canvas.view();
            for (const auto& label : canvas.gridLabels()) {
                QVERIFY2(view.viewport().contains(label.box), qPrintable(QStringLiteral("\"%1\" at %2 in a canvas from %3")
                                                                             .arg(label.text)
                                                                             .arg(label.box.left())
                                                                             .arg(view.viewport().left())));
                // An x label's line is 3 px left of its start, a y label's 3 px below its baseline
                // (curve_canvas.cpp), at the value it names.
                const double value = label.text.toDouble();
                const bool xLine = std::fabs(view.toModel(label.baseline - QPointF(3, 0)).x - value) < 1e-6;
                const bool yLine = std::fabs(view.toModel(label.baseline + QPointF(0, 3)).y - value) < 1e-6;
                QVERIFY2(xLine || yLine, qPrintable(label.text));
                labelled += xLine && value < 0;
            }
        }
        QVERIFY(labelled > 0); // negative x labels were there to check
    }

    // Issue 34, item 8, for the plots: a QCustomPlot centres a tick label on its tick, so the
    // label of a tick at the left end of the x axis reaches half its width into the left margin.
    // keepTickLabelsInside (every plot of the application has it) widens the margin to hold it.
    void plotTickLabelsStayInsideThePlot()
    {
        for (const bool kept : {false, true}) {
            QCustomPlot plot;
            if (kept)
                granota::ui::keepTickLabelsInside(&plot);
            plot.resize(300, 200);
            QFont large; // presentation mode's size, and a y axis whose labels take no room
            large.setPointSizeF(large.pointSizeF() * 1.6);
            plot.xAxis->setTickLabelFont(large);
            plot.yAxis->setTickLabels(false);
            plot.xAxis->setRange(-0.25, 1);
            plot.yAxis->setRange(0, 1);
            plot.replot();
            plot.replot(); // the margins of the first layout are the estimate of the second
            const QFontMetrics metrics(large);
            const QVector<double> ticks = plot.xAxis->tickVector();
            const QVector<QString> labels = plot.xAxis->tickVectorLabels();
            QVERIFY(!ticks.isEmpty() && ticks.first() == -0.25);
            // In the desktop's locale: "-0,25" on a Catalan desktop, as the CI's sanitizer run has it.
            QCOMPARE(QString(labels.first()).replace(QLatin1Char(','), QLatin1Char('.')), QStringLiteral("-0.25"));
            const double left = plot.xAxis->coordToPixel(ticks.first()) - metrics.boundingRect(labels.first()).width() / 2.0;
            // Unkept, QCustomPlot's margin (15 px) cuts the label: the case the helper is for.
            QVERIFY2((left >= 0) == kept, qPrintable(QStringLiteral("kept %1: the label starts at %2").arg(kept).arg(left)));
        }
    }

    // Issue 34, item 4: Catmull-Rom's "Totes les τ" (Every τ) beside the plot's title was cut
    // with the drawer open in presentation mode at 1024×768, in Catalan; at 800×600 in Catalan
    // (granota --lang ca --tab catmull-rom --size 800x570 --screenshot) it ran past the right
    // edge of the plot's column. Entered as a teacher does — the window shown, then presentation
    // mode, then View ▸ Side panel (F9) — it has its whole size hint, inside its column.
    void everyTauWhole_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("presentation");
        for (const char* language : {"ca", "en"}) {
            QTest::addRow("%s 1024x768 presentation side panel", language)
                << QString::fromLatin1(language) << QSize(1024, 768 - kTitleBar) << true;
            QTest::addRow("%s 800x600", language) << QString::fromLatin1(language) << QSize(800, 600 - kTitleBar) << false;
        }
    }
    void everyTauWhole()
    {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        QFETCH(bool, presentation);
        QVERIFY(granota::ui::setLanguage(language, false));
        const auto english = qScopeGuard([] { granota::ui::setLanguage(QStringLiteral("en"), false); });
        MainWindow window;
        window.resize(size);
        window.show();
        QVERIFY(waitExposed(&window));
        QVERIFY(window.showTab(QStringLiteral("catmull-rom")));
        if (presentation) {
            window.setPresentation(true, false);
            window.resize(size);
            QApplication::processEvents();
            window.setSidePanelsShown(true);
        }
        QApplication::processEvents();
        QApplication::processEvents();
        QCheckBox* every = nullptr;
        for (QCheckBox* box : window.tab(QStringLiteral("catmull-rom"))->findChildren<QCheckBox*>())
            if (box->text() == QCoreApplication::translate("granota::ui::CatmullRomTab", "Every &τ"))
                every = box;
        QVERIFY(every);
        QVERIFY(every->isVisible());
        const QSize hint = every->sizeHint();
        const QRect column = every->parentWidget()->rect();
        const QRect box = every->geometry();
        const QStringList problems = layoutProblems(window, size);
        if (presentation)
            window.setPresentation(false, false); // the application's font back for the next test
        QVERIFY2(hint.width() <= box.width() && column.contains(box),
                 qPrintable(QStringLiteral("needs %1, has %2 at %3 in a column of %4")
                                .arg(hint.width())
                                .arg(box.width())
                                .arg(box.left())
                                .arg(column.width())));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    // Issue 34, item 11: at 800×600 the Catmull-Rom blending plot's area was ~60 px tall, the
    // κ(s) plot's ~110 px. The plot area keeps at least kMinPlotArea pixels in both views.
    void catmullRomPlotsTallEnoughAt800x600_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("ca") << QStringLiteral("ca");
    }
    void catmullRomPlotsTallEnoughAt800x600()
    {
        QFETCH(QString, language);
        QVERIFY(granota::ui::setLanguage(language, false));
        const auto english = qScopeGuard([] { granota::ui::setLanguage(QStringLiteral("en"), false); });
        constexpr int kMinPlotArea = 100; ///< pixels of the plot's area, between its axes
        MainWindow window;
        const QSize size(800, 600 - kTitleBar);
        window.resize(size);
        window.show();
        QVERIFY(waitExposed(&window));
        QVERIFY(window.showTab(QStringLiteral("catmull-rom")));
        auto* tab = qobject_cast<granota::ui::CatmullRomTab*>(window.tab(QStringLiteral("catmull-rom")));
        QVERIFY(tab);
        for (const bool curvature : {false, true}) {
            tab->setCurvaturePlot(curvature);
            QApplication::processEvents();
            QApplication::processEvents();
            QCustomPlot* plot = tab->blendingPlot();
            plot->replot();
            const QRect area = plot->axisRect()->rect();
            QVERIFY2(area.height() >= kMinPlotArea,
                     qPrintable(QStringLiteral("%1: a plot area of %2 px in a plot of %3 px")
                                    .arg(curvature ? QStringLiteral("κ(s)") : QStringLiteral("blending"))
                                    .arg(area.height())
                                    .arg(plot->height())));
            const QStringList problems = layoutProblems(window, size);
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        }
    }

    void everyTabFits_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("presentation");
        QTest::addColumn<bool>("reports");
        QTest::addColumn<bool>("drawer"); // presentation mode's side panels opened
        for (const char* language : {"en", "ca"})
            for (bool reports : {false, true}) {
                const char* r = reports ? " reports" : "";
                QTest::addRow("%s 800x600%s", language, r)
                    << QString::fromLatin1(language) << QSize(800, 600 - kTitleBar) << false << reports << true;
                QTest::addRow("%s 1280x800%s", language, r)
                    << QString::fromLatin1(language) << QSize(1280, 800 - kTitleBar) << false << reports << true;
                for (bool drawer : {false, true})
                    QTest::addRow("%s 1024x768 presentation%s%s", language, r, drawer ? " side panel" : "")
                        << QString::fromLatin1(language) << QSize(1024, 768 - kTitleBar) << true << reports << drawer;
            }
    }

    void everyTabFits()
    {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        QFETCH(bool, presentation);
        QFETCH(bool, reports);
        QFETCH(bool, drawer);
        QVERIFY(granota::ui::setLanguage(language, false));
        QStringList problems;
        {
            MainWindow window;
            if (presentation) {
                window.setPresentation(true, false);
                QVERIFY(!window.sidePanelsShown()); // folded away
                window.setSidePanelsShown(drawer);
            }
            window.resize(size);
            window.show();
            QVERIFY(waitExposed(&window));
            // Every tab visited first: a tab once shown keeps its widgets' sizes in the hint.
            for (granota::ui::TabPage* page : window.tabs()) {
                QVERIFY(window.showTab(page->key()));
                if (reports)
                    window.setWorkPrecisionVisible(true);
                QApplication::processEvents();
            }
            for (granota::ui::TabPage* page : window.tabs()) {
                QVERIFY(window.showTab(page->key()));
                window.resize(size);
                QApplication::processEvents();
                QApplication::processEvents();
                for (const QString& problem : layoutProblems(window, size))
                    problems << page->key() + QStringLiteral(": ") + problem;
                if (presentation && !drawer && !reports)
                    if (const QString problem = canvasProblem(page); !problem.isEmpty())
                        problems << page->key() + QStringLiteral(": ") + problem;
            }
            if (presentation)
                window.setPresentation(false, false);
        }
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("\n") + problems.join(QLatin1Char('\n'))));
    }
};

GRANOTA_TEST_MAIN(TestGuiLayout)
#include "test_gui_layout.moc"
