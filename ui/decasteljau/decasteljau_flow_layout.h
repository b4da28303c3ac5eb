#pragma once
/// \file decasteljau_flow_layout.h
/// A layout that places its widgets in a row and wraps them onto the next row when the
/// width runs out (Qt's Flow Layout example): the tool rows of the De Casteljau and
/// Bernstein tabs stay tidy in Catalan, whose labels are longer, and in presentation mode.

#include <QLayout>
#include <QList>

namespace granota::ui {

class DeCasteljauFlowLayout : public QLayout {
public:
    explicit DeCasteljauFlowLayout(QWidget* parent = nullptr, int hSpacing = 10, int vSpacing = 4);
    ~DeCasteljauFlowLayout() override;

    void addItem(QLayoutItem* item) override;
    int count() const override { return static_cast<int>(m_items.size()); }
    QLayoutItem* itemAt(int index) const override { return m_items.value(index); }
    QLayoutItem* takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override { return doLayout(QRect(0, 0, width, 0), true); }
    QSize minimumSize() const override;
    QSize sizeHint() const override { return minimumSize(); }
    void setGeometry(const QRect& rect) override;

private:
    int doLayout(const QRect& rect, bool testOnly) const;

    QList<QLayoutItem*> m_items;
    int m_hSpacing;
    int m_vSpacing;
};

} // namespace granota::ui
