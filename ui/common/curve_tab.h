#pragma once
/// \file curve_tab.h
/// What the three curve tabs (De Casteljau, Fitting, Catmull-Rom) share: points edited on a
/// CurveCanvas with a PointEditor and a PointTable, an ExactPanel beside them, and so the
/// same document format for the points ("points": [[x, y], …], and "exactPoints" beside them when
/// the doubles do not carry the exact forms; read with one set of checks),
/// the same export view (the canvas), zoom, fit-to-view and presentation mode. Each tab adds
/// its own settings, drawings and panels, and says in its own words what is wrong with a
/// document's points (PointListMessages).

#include "core/base/vec2.h"
#include "core/exact/exact_point.h"
#include "ui/common/tab_page.h"

#include <QRectF>
#include <QString>

#include <functional>
#include <optional>
#include <vector>

class QJsonValue;

namespace granota::ui {

class CurveCanvas;
class ExactPanel;
class PointEditor;
class PointTable;

/// What a curve tab says, in its own words, when it refuses the points of a document.
struct PointListMessages {
    QString notAList;                            ///< "points" is missing or not a list
    std::function<QString(int count)> badCount;  ///< fewer points than the editor's minimum or more than its maximum
    std::function<QString(int index)> notAPair;  ///< point `index` is not [x, y] (with finite numbers if notFinite is empty)
    std::function<QString(int index)> notFinite; ///< point `index` is a pair but not finite; empty: notAPair says it
    /// Empty: too few points is badCount, checked before the points one by one. Else too few
    /// points is this message, checked after them.
    std::function<QString()> tooFewAfterPoints;
};

class CurveTab : public TabPage {
    Q_OBJECT
public:
    PointEditor* pointEditor() const { return m_editor; }
    CurveCanvas* canvas() const { return m_canvas; }
    PointTable* pointTable() const { return m_table; }
    ExactPanel* exactPanel() const { return m_exact; }

    /// The points as "points": [[x, y], …], and the tab's settings (writeSettings()).
    QJsonObject saveState() const final;
    /// Checks the points (pointMessages()), then the tab checks and applies its settings
    /// (loadSettings()); then the view fits. A refused document changes nothing.
    bool loadState(const QJsonObject& state, QString* error) final;
    /// The canvas's and the exact panel's presentation scale, then presentationChanged().
    void setPresentation(bool on) final;
    bool presentation() const { return m_presentation; }
    void zoom(double factor) final;
    /// Frames contentBounds().
    void fitView() final;
    /// The curve canvas's keys (docs/classroom.md, "Keyboard").
    QString keyboardHint() const override;

protected:
    /// Makes the canvas (the export view). The tab makes the editor, the table and the exact
    /// panel where its layout wants them (the editor after the layers drawn under the handles).
    CurveTab(QString key, const char* title, QWidget* parent);

    /// The tab's refusals of a document's points (the counts are the editor's limits).
    virtual PointListMessages pointMessages() const = 0;
    /// The tab's settings into a document.
    virtual void writeSettings(QJsonObject& state) const = 0;
    /// Checks the tab's settings in `state`; if they are good, makes them and `points` current
    /// (without an undo step) and returns true, else sets `error` and changes nothing.
    virtual bool loadSettings(const QJsonObject& state, const std::vector<Point>& points, QString& error) = 0;
    /// The model rectangle the view frames (the points and what is drawn around them).
    virtual QRectF contentBounds() const = 0;
    /// What else presentation mode changes in the tab (plots, panels).
    virtual void presentationChanged(bool on) { (void)on; }
    /// Once shown (after the tab's own hint), the status bar says when the point labels are
    /// hidden because there are many points (PointEditor::labelsHiddenNote()).
    void showEvent(QShowEvent* event) override;

    CurveCanvas* const m_canvas;
    PointEditor* m_editor = nullptr;
    PointTable* m_table = nullptr;
    ExactPanel* m_exact = nullptr;

private:
    std::optional<std::vector<Point>> readPoints(const QJsonValue& value, QString& error) const;
    /// The points' exact forms ("exactPoints": [[x, y], …], each "p/q" or null), checked against
    /// the points' doubles.
    std::optional<std::vector<ExactPoint>> readExactPoints(const QJsonValue& value, const std::vector<Point>& points,
                                                           QString& error) const;

    bool m_presentation = false;
};

} // namespace granota::ui
