#pragma once
/// \file bernstein_tab.h
/// The Bernstein tab (docs/tabs.md; thesis §2.1.2, Def 2.5, Lemma 2.1, Prop 2.1, Def 2.6,
/// Ex 2.4–2.6): the basis B_i^n(t) for a chosen n or for every degree up to N (the Matlab
/// Rep_Pol_Bernstein `tots`), their exact expansions, live checks of partition of unity,
/// symmetry and Lemma 2.1, and the weights B_i^n(t) that Def 2.6 applies to the De
/// Casteljau tab's control points at the shared parameter t.
///
/// The tab shares the De Casteljau tab's history (one curve, one t): its degree, mode and t
/// are steps on it, and loading Ex 2.5 or Ex 2.6 (the points, t and the degree) is one step.

#include "core/curves/bezier/bernstein_properties.h"
#include "ui/common/bezier_exact_html.h"
#include "ui/common/plot_drawable.h"
#include "ui/common/tab_page.h"

#include <QString>

#include <memory>
#include <utility>

class QCheckBox;
class QCPBars;
class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QGroupBox;
class QLabel;
class QMouseEvent;
class QSpinBox;
class QSplitter;
class QUndoStack;

namespace granota::ui {

class BezierCurveModel;
class DeCasteljauParameterControl;
class ExactPanel;

class BernsteinTab : public TabPage {
    Q_OBJECT
public:
    /// Shows the curve the De Casteljau tab edits: its control points, t and history (docs/tabs.md).
    explicit BernsteinTab(BezierCurveModel* curve, QWidget* parent = nullptr);
    ~BernsteinTab() override;

    void retranslate() override;
    QString hint() const override;
    QJsonObject saveState() const override;
    bool loadState(const QJsonObject& state, QString* error) override;
    bool loadExample(const granota::WorkedExample& example) override;
    QString csv() const override;
    void setPresentation(bool on) override;

    /// The degree n of the basis shown (the largest degree N in all-degrees mode).
    int degree() const { return m_degree; }
    void setDegree(int n);
    /// All degrees 0…N overlaid (the Matlab Rep_Pol_Bernstein(n, tots = true)).
    bool allDegrees() const { return m_allDegrees; }
    void setAllDegrees(bool on);
    /// The dashed line at the current t on the plot (and in its exports); off, the basis alone
    /// (Fig 2.4 as printed). The document's "t_marker".
    bool tMarkerVisible() const { return m_showMarker; }
    void setTMarkerVisible(bool on);
    /// The shared parameter t (the curve's, bezier_curve_model.h).
    double t() const;
    void setT(double t);

    QCustomPlot* basisPlot() const { return m_basisPlot; }
    QCustomPlot* weightsPlot() const { return m_weightsPlot; }
    QCPBars* weightBars() const { return m_bars; }
    ExactPanel* exactPanel() const { return m_exact; }
    DeCasteljauParameterControl* parameterControl() const { return m_parameter; }
    /// The checks of partition of unity, symmetry and Lemma 2.1 at the current n and t.
    const BernsteinChecks& checks() const { return m_checks; }
    /// The three check lines as shown (rich text), in that order.
    QStringList checkTexts() const;
    /// The comparison of Def 2.6 with De Casteljau at t, as shown.
    QString curvePointText() const;
    /// The hover readout for a parameter value (what the plot shows under the mouse).
    QString readout(double t) const;
    /// Whether the hover readout is on the plot.
    bool readoutShown() const;
    /// The x position (t) of the vertical line marking the current t.
    double markerT() const;

    static constexpr int kMaxDegree = 30;                        ///< the spin box's range: 0…30
    static constexpr int kMaxExactCurve = kMaxExactBezierDegree; ///< the curve in powers of t up to this degree
    static constexpr int kPlotSamples = 201;                     ///< t samples per graph (Matlab linspace(0, 1, 200))

protected:
    void drawTikz(TikzWriter& w) const override;

private:
    void rebuildBasisPlot();
    void updateMarker();
    void updateWeights();
    void updateChecks();
    void updateExactPanel();
    void applyPlotStyle();
    /// What the document keeps of this tab besides t: the degree and the all-degrees view.
    struct View {
        int degree = 3;
        bool allDegrees = false;
        bool marker = true;
        bool operator==(const View& o) const { return degree == o.degree && allDegrees == o.allDegrees && marker == o.marker; }
    };
    View view() const { return {m_degree, m_allDegrees, m_showMarker}; }
    void applyView(const View& v);
    /// The user's changes: each is one undo step on this tab (docs/tabs.md, "Undo").
    void userChangedView(const View& after, const QString& undoText, int mergeId = -1);
    void userMovedT(double t, int mergeId);
    int plotDragMergeId() const;
    void plotMouseMove(QMouseEvent* event);
    void plotMousePress(QMouseEvent* event);

    BezierCurveModel* m_curve;
    QCustomPlot* m_basisPlot;
    QCustomPlot* m_weightsPlot;
    std::unique_ptr<Drawable> m_drawable; ///< the basis plot for File ▸ Export, without the hover readout
    QCPBars* m_bars = nullptr;
    QCPItemStraightLine* m_marker = nullptr;
    QCPItemText* m_readout = nullptr;
    ExactPanel* m_exact;
    DeCasteljauParameterControl* m_parameter;
    QLabel* m_degreeLabel;
    QSpinBox* m_degreeBox;
    QCheckBox* m_allBox;
    QCheckBox* m_markerBox;
    QGroupBox* m_checksGroup;
    QLabel* m_checkLabels[3];
    QGroupBox* m_weightsGroup;
    QLabel* m_curveLabel;
    QSplitter* m_mainSplitter = nullptr;

    int m_degree = 3;
    bool m_allDegrees = false;
    bool m_showMarker = true;
    bool m_presentation = false;
    bool m_dragging = false;
    int m_plotDrags = 0; ///< drags of t on the basis plot so far: one drag is one undo step
    BernsteinChecks m_checks;
};

} // namespace granota::ui
