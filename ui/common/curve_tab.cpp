#include "ui/common/curve_tab.h"

#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "ui/common/presentation_scale.h"

#include "core/exact/exact_point.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QTimer>

namespace granota::ui {

CurveTab::CurveTab(QString key, const char* title, QWidget* parent)
    : TabPage(std::move(key), title, parent), m_canvas(new CurveCanvas(this))
{
    setExportView(m_canvas);
}

QJsonObject CurveTab::saveState() const
{
    QJsonArray points;
    for (const Point& p : m_editor->points())
        points.append(QJsonArray{p.x, p.y});
    QJsonObject state;
    state.insert(QStringLiteral("points"), points);
    // The exact forms beside the doubles, when a double alone does not carry them (a point
    // molded to 108/1225, or one without an exact form): documents that need none stay as before.
    const std::vector<ExactPoint>& exact = m_editor->exactPoints();
    if (exact != writtenExact(m_editor->points())) {
        const auto text = [](const ExactCoordinate& q) {
            return q ? QJsonValue(QString::fromStdString(toString(*q))) : QJsonValue();
        };
        QJsonArray exactPoints;
        for (const ExactPoint& q : exact)
            exactPoints.append(QJsonArray{text(q.x), text(q.y)});
        state.insert(QStringLiteral("exactPoints"), exactPoints);
    }
    if (const std::optional<bool> labels = m_editor->labelChoice())
        state.insert(QStringLiteral("pointLabels"), *labels);
    writeSettings(state);
    return state;
}

std::optional<std::vector<Point>> CurveTab::readPoints(const QJsonValue& value, QString& error) const
{
    const PointListMessages say = pointMessages();
    if (!value.isArray()) {
        error = say.notAList;
        return std::nullopt;
    }
    const QJsonArray array = value.toArray();
    const int count = static_cast<int>(array.size());
    const bool tooFew = count < m_editor->minimumCount();
    if (count > m_editor->maximumCount() || (tooFew && !say.tooFewAfterPoints)) {
        error = say.badCount(count);
        return std::nullopt;
    }
    std::vector<Point> points;
    points.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const QJsonArray xy = array.at(i).toArray();
        const bool pair = xy.size() == 2 && xy.at(0).isDouble() && xy.at(1).isDouble();
        const Point p = pair ? Point(xy.at(0).toDouble(), xy.at(1).toDouble()) : Point();
        if (!pair || (!say.notFinite && !isFinite(p))) {
            error = say.notAPair(i);
            return std::nullopt;
        }
        if (!isFinite(p)) {
            error = say.notFinite(i);
            return std::nullopt;
        }
        points.push_back(p);
    }
    if (tooFew) {
        error = say.tooFewAfterPoints();
        return std::nullopt;
    }
    return points;
}

std::optional<std::vector<ExactPoint>> CurveTab::readExactPoints(const QJsonValue& value, const std::vector<Point>& points,
                                                                 QString& error) const
{
    const QJsonArray array = value.toArray();
    if (!value.isArray() || array.size() != static_cast<qsizetype>(points.size())) {
        error = tr("“exactPoints” is not a list of [x, y] pairs, one for each point.");
        return std::nullopt;
    }
    std::vector<ExactPoint> exact;
    exact.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const QJsonArray xy = array.at(static_cast<qsizetype>(i)).toArray();
        // Each entry is a fraction or decimal that the stored double rounds, or null (no exact form).
        const auto read = [](const QJsonValue& v, double d, ExactCoordinate& q) {
            if (v.isNull())
                return true;
            q = v.isString() ? parseRational(v.toString().toStdString()) : std::nullopt;
            return q && toDouble(*q) == d;
        };
        ExactPoint p;
        if (xy.size() != 2 || !read(xy.at(0), points[i].x, p.x) || !read(xy.at(1), points[i].y, p.y)) {
            error =
                tr("“exactPoints” entry %1 is not a pair of exact values of point %1 (fractions such as “1/3”, or null).").arg(i);
            return std::nullopt;
        }
        exact.push_back(std::move(p));
    }
    return exact;
}

bool CurveTab::loadState(const QJsonObject& state, QString* error)
{
    // Validate everything first: a bad document changes nothing (loadSettings checks the
    // settings before it applies anything).
    QString message;
    const std::optional<std::vector<Point>> points = readPoints(state.value(QStringLiteral("points")), message);
    const QJsonValue labels = state.value(QStringLiteral("pointLabels"));
    if (points && !labels.isUndefined() && !labels.isBool())
        message = tr("“pointLabels” is not true or false.");
    // Absent (older documents, and points whose doubles carry their exact forms): the editor takes
    // the small fractions the doubles were written as (writtenExact).
    const QJsonValue exactValue = state.value(QStringLiteral("exactPoints"));
    std::optional<std::vector<ExactPoint>> exact;
    if (points && message.isEmpty() && !exactValue.isUndefined())
        exact = readExactPoints(exactValue, *points, message);
    // The choice of labels is made first, so that the points arrive under it (no note that
    // their labels are hidden when the document shows them); a refused document restores it.
    const std::optional<bool> labelsBefore = m_editor->labelChoice();
    if (points && message.isEmpty())
        m_editor->setLabelChoice(labels.isBool() ? std::optional<bool>(labels.toBool()) : std::nullopt);
    if (!points || !message.isEmpty() || !loadSettings(state, *points, message)) {
        m_editor->setLabelChoice(labelsBefore);
        if (error)
            *error = message;
        return false;
    }
    // The tab made the points current with the exact forms their doubles carry; a document that
    // holds others (exactPoints) restores them.
    if (exact && m_editor->points() == *points && m_editor->exactPoints() != *exact)
        m_editor->applyPoints(*points, *exact);
    fitView();
    return true;
}

void CurveTab::setPresentation(bool on)
{
    m_presentation = on;
    m_canvas->setStyleScale(presentationScale(on));
    m_exact->setPresentation(on);
    presentationChanged(on);
}

void CurveTab::showEvent(QShowEvent* event)
{
    TabPage::showEvent(event);
    // Queued: the tab's showEvent emits its hint after this one returns.
    QTimer::singleShot(0, this, [this] {
        if (isVisible())
            if (const QString note = m_editor->labelsHiddenNote(); !note.isEmpty())
                emit statusMessage(note);
    });
}

QString CurveTab::keyboardHint() const
{
    return tr("Keys: ] and [ select a point, the arrows nudge it (Shift: ten times more), Delete removes it; Tab "
              "leaves the canvas.");
}

void CurveTab::zoom(double factor) { m_canvas->zoom(factor); }

void CurveTab::fitView()
{
    m_canvas->setContentBounds(contentBounds());
    m_canvas->fitToContent();
}

} // namespace granota::ui
