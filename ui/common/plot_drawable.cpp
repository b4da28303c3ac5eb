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
        // Pens as wide as on screen whatever the scale of the target (a 300 DPI PNG): a
        // cosmetic pen would stay one device pixel wide, a third of the screen's line.
        recorder.setMode(QCPPainter::pmVectorized);
        recorder.setMode(QCPPainter::pmNonCosmetic);
        m_plot->toPainter(&recorder, static_cast<int>(target.width()), static_cast<int>(target.height()));
    }
    painter.save();
    painter.fillRect(target, Qt::white);
    painter.drawPicture(target.topLeft(), picture);
    painter.restore();
}

} // namespace granota::ui
