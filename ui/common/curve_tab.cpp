#include "ui/common/curve_tab.h"

#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "ui/common/presentation_scale.h"

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

bool CurveTab::loadState(const QJsonObject& state, QString* error)
{
    // Validate everything first: a bad document changes nothing (loadSettings checks the
    // settings before it applies anything).
    QString message;
    const std::optional<std::vector<Point>> points = readPoints(state.value(QStringLiteral("points")), message);
    const QJsonValue labels = state.value(QStringLiteral("pointLabels"));
    if (points && !labels.isUndefined() && !labels.isBool())
        message = tr("“pointLabels” is not true or false.");
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
