#include "ui/shell/thesis_figure_export.h"

#include "core/base/number_format.h"
#include "core/io/thesis_figures.h"
#include "ui/common/drawable.h"
#include "ui/common/path_recorder.h"
#include "ui/common/value_command.h"
#include "ui/frog/frog_art_view.h"
#include "ui/frog/frog_json.h"
#include "ui/files/exporter.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "ui/files/tikz_writer.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QPainter>
#include <QWidget>

#include <functional>
#include <memory>

namespace granota::ui {

namespace {

QString say(const char* text) { return QCoreApplication::translate("granota::ui::ThesisFigures", text); }

QString fromStd(const std::string& s) { return QString::fromStdString(s); }

/// Keys of `over` replace those of `base`; an object replaces an object whole except
/// "overlays", whose keys are set one by one.
void mergeInto(QJsonObject& base, const QJsonObject& over)
{
    for (auto it = over.begin(); it != over.end(); ++it) {
        if (it.key() == QLatin1String("overlays") && base.value(it.key()).isObject() && it.value().isObject()) {
            QJsonObject inner = base.value(it.key()).toObject();
            mergeInto(inner, it.value().toObject());
            base.insert(it.key(), inner);
        } else {
            base.insert(it.key(), it.value());
        }
    }
}

/// A view drawn at a size of the caller's choosing instead of its size on screen.
class SizedView : public Drawable {
public:
    /// An empty `size`: the view's own.
    SizedView(Drawable& view, QSizeF size) : m_view(view), m_size(size.isEmpty() ? view.exportSize() : size) {}
    QSizeF exportSize() const override { return m_size; }
    void render(QPainter& painter, const QRectF& target) override { m_view.render(painter, target); }

private:
    Drawable& m_view;
    QSizeF m_size;
};

/// The shapes an art figure paints, recorded at its export size (y down, pixels).
std::vector<PathRecorder::Shape> artShapes(FrogArtView& art, QSizeF size)
{
    PathRecorder recorder(size.toSize());
    {
        QPainter painter(&recorder);
        art.render(painter, QRectF(QPointF(0, 0), size));
    }
    return recorder.shapes();
}

/// TikZ of the art: each recorded outline as a closed line of its colour (y up).
QString artTikz(const std::vector<PathRecorder::Shape>& shapes)
{
    TikzWriter writer;
    for (const PathRecorder::Shape& shape : shapes)
        for (const QPolygonF& polygon : shape.path.toSubpathPolygons()) {
            if (polygon.size() < 2)
                continue;
            std::vector<Point> points;
            for (const QPointF& p : polygon)
                points.push_back({p.x(), -p.y()});
            const QColor colour = shape.fill.isValid() ? shape.fill : shape.stroke;
            writer.polyline(points, QColor(colour.red(), colour.green(), colour.blue()), 0.4, false, polygon.isClosed());
        }
    return writer.str();
}

/// CSV of the art: every outline's vertices, `shape,x,y` (pixels, y down).
QString artCsv(const std::vector<PathRecorder::Shape>& shapes)
{
    QString csv = QStringLiteral("shape,x,y\n");
    int index = 0;
    for (const PathRecorder::Shape& shape : shapes) {
        for (const QPolygonF& polygon : shape.path.toSubpathPolygons())
            for (const QPointF& p : polygon)
                csv +=
                    QStringLiteral("%1,%2,%3\n").arg(index).arg(fromStd(formatFixed(p.x(), 3)), fromStd(formatFixed(p.y(), 3)));
        ++index;
    }
    return csv;
}

} // namespace

QStringList thesisFigureFormats()
{
    return {QStringLiteral("svg"), QStringLiteral("pdf"), QStringLiteral("png"), QStringLiteral("tex"), QStringLiteral("csv")};
}

QString thesisFigureCaption(const ThesisFigure& figure)
{
    const std::string& text = figure.caption.in(currentLanguage().toStdString());
    return say("Fig %1 — %2").arg(fromStd(figure.number), fromStd(text));
}

QString thesisFigureVariantLabel(const FigureVariant& variant)
{
    const std::string& name = variant.name;
    if (name == "definition")
        return say("as defined");
    if (name == "thesis")
        return say("as the thesis computed it");
    if (name == "all")
        return say("every degree");
    if (name == "rest")
        return say("(a) at rest");
    if (name == "grabbed")
        return say("(b) grabbed");
    if (name.size() == 2 && name[0] == 'n')
        return say("degree n = %1").arg(QChar::fromLatin1(name[1]));
    return fromStd(name);
}

QString thesisFigureNote(const FigureVariant& variant) { return fromStd(variant.note.in(currentLanguage().toStdString())); }

QJsonObject thesisFigureState(const TabPage& page, const ThesisFigure& figure, const FigureVariant& variant)
{
    QJsonObject state;
    if (!figure.scene.empty()) {
        // The Frog tab: the scene alone on the seed solver, the thesis's constants, nothing
        // drawn over it, paused where the figure is.
        QJsonObject overlays = page.saveState().value(QStringLiteral("overlays")).toObject();
        for (auto it = overlays.begin(); it != overlays.end(); ++it)
            it.value() = false;
        state.insert(QStringLiteral("scene"), fromStd(figure.scene));
        state.insert(QStringLiteral("solver"), QStringLiteral("seed"));
        state.insert(QStringLiteral("overlays"), overlays);
        state.insert(QStringLiteral("bezier_outline"), QStringLiteral("precomputed"));
        state.insert(QStringLiteral("paused"), true);
        state.insert(QStringLiteral("speed"), 1.0);
        QJsonObject run;
        run.insert(QStringLiteral("steps"), static_cast<double>(figure.steps));
        run.insert(QStringLiteral("step"), static_cast<double>(figure.steps));
        run.insert(QStringLiteral("events"), toQJson(variant.events));
        state.insert(QStringLiteral("recording"), run);
    } else {
        state = page.saveState();
        mergeInto(state, toQJson(figure.state).toObject());
    }
    mergeInto(state, toQJson(variant.state).toObject());
    return state;
}

bool showThesisFigure(MainWindow& window, const ThesisFigure& figure, const FigureVariant& variant, bool undoable, QString* error)
{
    TabPage* page = window.tab(fromStd(figure.tab));
    if (!page) {
        if (error)
            *error = say("Fig %1 names no tab of Granota.").arg(fromStd(figure.number));
        return false;
    }
    window.showTab(page->key());
    if (!figure.art.empty())
        return true;
    const bool asStep = undoable && figure.scene.empty();
    const QString stepName = say("Fig %1").arg(fromStd(figure.number));
    if (asStep)
        page->undoStack()->beginMacro(stepName);
    bool ok = figure.example.empty() || window.loadExample(fromStd(figure.example));
    QString why;
    if (ok) {
        const QJsonObject before = page->saveState();
        const QJsonObject after = thesisFigureState(*page, figure, variant);
        ok = page->loadState(after, &why);
        if (ok && asStep) {
            auto apply = [page](const QJsonObject& state) {
                QString ignored; // states this tab wrote or took already: not refused
                page->loadState(state, &ignored);
            };
            page->undoStack()->push(
                new ValueCommand<QJsonObject>(apply, before, after, stepName, -1, {false, /*appliedAlready=*/true}));
        }
    }
    if (asStep)
        page->undoStack()->endMacro();
    if (!ok) {
        if (error)
            *error = why.isEmpty() ? say("Fig %1 could not be shown.").arg(fromStd(figure.number))
                                   : say("Fig %1 could not be shown: %2").arg(fromStd(figure.number), why);
        return false;
    }
    page->fitView();
    return true;
}

QString exportThesisFigure(MainWindow& window, const ThesisFigure& figure, const QString& format, const QString& file, QSize size,
                           int dpi)
{
    if (!thesisFigureFormats().contains(format))
        return say("Unknown export format “%1” (svg, pdf, png, tex, csv).").arg(format);
    const QString title = QStringLiteral("Granota — ") + thesisFigureCaption(figure);
    // The view drawn and, for the two text formats, the figure's TikZ and CSV.
    std::unique_ptr<FrogArtView> art;
    Drawable* drawn = nullptr;
    std::function<QString()> tikz, csv;
    if (!figure.art.empty()) {
        art = std::make_unique<FrogArtView>(figure.art == "head" ? FrogArtView::Piece::Head : FrogArtView::Piece::Background);
        drawn = art.get();
        tikz = [&art] { return artTikz(artShapes(*art, art->exportSize())); };
        csv = [&art] { return artCsv(artShapes(*art, art->exportSize())); };
    } else if (TabPage* page = window.tab(fromStd(figure.tab)); page && page->exportView()) {
        // The view laid out at the size asked, as on a screen of that size, and fitted there:
        // its margins keep the points clear of the key. What the window's smallest size does
        // not allow, the drawing's own scaling does.
        if (auto* widget = dynamic_cast<QWidget*>(page->exportView()); widget && !size.isEmpty() && widget->size() != size) {
            window.resize(window.size() + (size - widget->size()));
            QCoreApplication::processEvents();
            page->fitView();
        }
        drawn = page->exportView();
        tikz = [page] { return page->tikz(); };
        csv = [page] { return page->csv(); };
    } else {
        return say("Fig %1 names no tab of Granota.").arg(fromStd(figure.number));
    }
    SizedView view(*drawn, size);
    if (format == QLatin1String("svg"))
        return exportSvg(view, file, title);
    if (format == QLatin1String("pdf"))
        return exportPdf(view, file, title);
    if (format == QLatin1String("png"))
        return exportPng(view, file, dpi);
    return writeTextFile(file, format == QLatin1String("tex") ? tikz() : csv());
}

} // namespace granota::ui
