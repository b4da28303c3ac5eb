#pragma once
/// \file knot_ruler.h
/// The knot vector u_0 ≤ … ≤ u_{n+p+1} of the B-spline tab on a line under the canvas: each
/// distinct knot a tick with a badge for its multiplicity, the domain [u_p, u_{n+1}] drawn
/// bold, the span [u_k, u_{k+1}) that holds u highlighted (the p + 1 knots' worth of local
/// support) and u itself marked. It only shows and asks: the tab owns the knots and makes
/// every change (one undo step each).
///
/// Mouse: drag a knot (bounded by its neighbours: it never passes them, it may meet them, and
/// from a stack of equal knots the one on the side of the move leaves it); double-click to
/// insert a knot there. Keys (the ruler takes the focus): Left/Right select the previous/next
/// knot, Shift+Left/Right move the selected knot by a step (bounded as a drag), Insert inserts a
/// knot at u, Delete removes the selected knot.

#include <QStringList>
#include <QWidget>

#include <vector>

namespace granota::ui {

class KnotRuler : public QWidget {
    Q_OBJECT
public:
    explicit KnotRuler(QWidget* parent = nullptr);

    /// The knots (non-decreasing), their texts under the ticks (the exact fractions; empty:
    /// the doubles) and the degree p (the domain is [u_p, u_{n+1}]). The scale of the ruler
    /// follows, but not during a drag (the knot stays under the mouse).
    void setKnots(const std::vector<double>& knots, int degree, const QStringList& texts = {});
    const std::vector<double>& knots() const { return m_knots; }
    /// u and its span k (u_k ≤ u < u_{k+1}), highlighted.
    void setParameter(double u, int span);
    int selected() const { return m_selected; }
    /// Selects knot `index` (−1: none).
    void setSelected(int index);
    /// Thicker lines and larger badges in presentation mode.
    void setStyleScale(double scale);

    /// Where value `v` is drawn (widget x) and the value at widget x, in the current scale.
    double toX(double v) const;
    double toValue(double x) const;
    /// Knot `index` may move to [lowerBound(index), upperBound(index)]: its neighbours.
    double lowerBound(int index) const;
    double upperBound(int index) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    /// A drag (or Shift+arrow) moves knot `index` to `value`, already within its bounds. A drag
    /// sends many; the tab merges them into one undo step until dragFinished().
    void knotMoved(int index, double value);
    void dragFinished();
    /// Double-click at `value`.
    void insertRequested(double value);
    /// Insert: a knot at u itself (the tab has u exactly).
    void insertAtParameterRequested();
    /// Delete with knot `index` selected.
    void removeRequested(int index);
    void selectionChanged(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    /// The first and one-past-the-last index of the stack of equal knots at the tick nearest
    /// to widget x, within the pick distance; {−1, −1} for none.
    std::pair<int, int> pickStack(double x) const;
    /// The range the ruler shows: the knots with a margin.
    void updateRange();
    double lineY() const;
    /// A keyboard step: 1/100 of the knots' extent.
    double keyStep() const;

    std::vector<double> m_knots;
    QStringList m_texts;
    int m_degree = 1;
    double m_u = 0;
    int m_span = -1;
    int m_selected = -1;
    double m_lo = 0, m_hi = 1; ///< the values at the ruler's left and right margins
    double m_scale = 1.0;
    /// A drag: the stack pressed, the knot that moves (chosen by the first move's direction).
    std::pair<int, int> m_pressedStack{-1, -1};
    int m_dragging = -1;
    double m_pressX = 0;
    bool m_moved = false;
};

} // namespace granota::ui
