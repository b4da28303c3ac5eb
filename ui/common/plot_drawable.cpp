#include "ui/common/plot_drawable.h"

#include <QPicture>
#include <qcustomplot.h>

namespace granota::ui {

QSizeF PlotDrawable::exportSize() const { return m_plot->size(); }

void PlotDrawable::render(QPainter& painter, const QRectF& target)
{
    QPicture picture;
    {
        QCPPainter recorder(&picture);
        m_plot->toPainter(&recorder, static_cast<int>(target.width()), static_cast<int>(target.height()));
    }
    painter.save();
    painter.fillRect(target, Qt::white);
    painter.drawPicture(target.topLeft(), picture);
    painter.restore();
}

} // namespace granota::ui
