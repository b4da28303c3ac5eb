#pragma once
/// \file exporter.h
/// Exports of any Drawable (docs/tabs.md): PNG at a chosen DPI, SVG and PDF, all through the
/// view's own render(), plus plain text files (CSV, TikZ). Each is made in memory and then
/// replaces the file whole (ui/files/user_file.h): a full disk keeps the old file. Each
/// returns an empty string on success and a translated message, with the reason, otherwise;
/// nothing here ever throws or aborts.

#include <QImage>
#include <QSizeF>
#include <QString>

namespace granota::ui {

class Drawable;

/// Screen pixels are 96 per inch: a PNG at `dpi` has exportSize × dpi/96 pixels, and
/// records its DPI in the file (pHYs), so slides place it at the size seen on screen.
QString exportPng(Drawable& view, const QString& file, int dpi = 96);
QString exportSvg(Drawable& view, const QString& file, const QString& title);
QString exportPdf(Drawable& view, const QString& file, const QString& title);
QString writeTextFile(const QString& file, const QString& text);
/// An image as a PNG file (the frog's frames, `granota --screenshot`).
QString writePngFile(const QImage& image, const QString& file);

/// The pixel size of a PNG export of `logical` at `dpi`.
QSize pngPixelSize(const QSizeF& logical, int dpi);

} // namespace granota::ui
