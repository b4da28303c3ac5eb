#include "ui/files/exporter.h"

#include "ui/common/drawable.h"
#include "ui/files/user_file.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QImage>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>

#include <cmath>

namespace granota::ui {

namespace {
constexpr double kScreenDpi = 96.0;


QString cannotWrite(const QString& file)
{
    return QCoreApplication::translate("granota::ui::Exporter", "Cannot write “%1”.").arg(file);
}

/// Replaces `file` with `bytes`; the message says why it could not, and that an old file is
/// as it was.
QString writeExport(const QString& file, const QByteArray& bytes)
{
    QString reason;
    if (writeUserFile(file, bytes, &reason))
        return QString();
    return QCoreApplication::translate("granota::ui::Exporter", "Cannot write “%1”: %2.").arg(file, reason);
}
} // namespace

QSize pngPixelSize(const QSizeF& logical, int dpi)
{
    const double f = dpi / kScreenDpi;
    return {std::max(1, static_cast<int>(std::lround(logical.width() * f))),
            std::max(1, static_cast<int>(std::lround(logical.height() * f)))};
}

QString exportPng(Drawable& view, const QString& file, int dpi)
{
    if (dpi < 24 || dpi > 1200)
        return QCoreApplication::translate("granota::ui::Exporter", "The resolution must be between 24 and 1200 DPI.");
    const QSizeF logical = view.exportSize();
    const QSize pixels = pngPixelSize(logical, dpi);
    if (static_cast<qint64>(pixels.width()) * pixels.height() > 400LL * 1000 * 1000)
        return QCoreApplication::translate("granota::ui::Exporter", "The image would be too large: choose a lower resolution.");
    QImage image(pixels, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return QCoreApplication::translate("granota::ui::Exporter", "Not enough memory for an image of %1×%2 pixels.")
            .arg(pixels.width())
            .arg(pixels.height());
    image.fill(Qt::white);
    // Drawn as the screen draws it, at 96 DPI, only scaled: fonts given in points would
    // otherwise take the image's DPI as well and come out dpi/96 times too large again.
    const auto setDpi = [&image](double d) {
        const int dotsPerMeter = static_cast<int>(std::lround(d / 0.0254));
        image.setDotsPerMeterX(dotsPerMeter);
        image.setDotsPerMeterY(dotsPerMeter);
    };
    setDpi(kScreenDpi);
    {
        QPainter painter(&image);
        painter.scale(dpi / kScreenDpi, dpi / kScreenDpi);
        view.render(painter, QRectF(QPointF(0, 0), logical));
    }
    setDpi(dpi); // what the file says: printed at this resolution, it has the screen's size
    return writePngFile(image, file);
}

QString writePngFile(const QImage& image, const QString& file)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG"))
        return cannotWrite(file);
    buffer.close();
    return writeExport(file, bytes);
}

QString exportSvg(Drawable& view, const QString& file, const QString& title)
{
    const QSizeF logical = view.exportSize();
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(logical.toSize());
    svg.setViewBox(QRectF(QPointF(0, 0), logical));
    svg.setTitle(title);
    svg.setDescription(QCoreApplication::translate("granota::ui::Exporter", "Made with Granota"));
    svg.setResolution(static_cast<int>(kScreenDpi));
    QPainter painter;
    if (!painter.begin(&svg))
        return cannotWrite(file);
    view.render(painter, QRectF(QPointF(0, 0), logical));
    painter.end();
    buffer.close();
    return writeExport(file, bytes);
}

QString exportPdf(Drawable& view, const QString& file, const QString& title)
{
    const QSizeF logical = view.exportSize();
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QPdfWriter pdf(&buffer);
    pdf.setTitle(title);
    pdf.setCreator(QStringLiteral("Granota"));
    pdf.setResolution(static_cast<int>(kScreenDpi));
    // One page the size of the view, in points (1/72 in): the figure is the page.
    pdf.setPageSize(QPageSize(QSizeF(logical.width() * 72.0 / kScreenDpi, logical.height() * 72.0 / kScreenDpi), QPageSize::Point,
                              QString(), QPageSize::ExactMatch));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
    QPainter painter;
    if (!painter.begin(&pdf))
        return cannotWrite(file);
    const QRectF page = painter.viewport();
    painter.scale(page.width() / logical.width(), page.height() / logical.height());
    view.render(painter, QRectF(QPointF(0, 0), logical));
    painter.end();
    buffer.close();
    return writeExport(file, bytes);
}

QString writeTextFile(const QString& file, const QString& text) { return writeExport(file, text.toUtf8()); }

} // namespace granota::ui
