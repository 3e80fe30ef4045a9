#include "DiagramFiles.h"

#include <QFileInfo>
#include <QImage>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QSvgGenerator>

#include <cmath>

namespace cuelab {

namespace {

bool openSaveFile(QSaveFile& file, QString* error)
{
    if (file.open(QIODevice::WriteOnly)) return true;
    if (error) *error = QStringLiteral("%1: cannot write the file: %2").arg(file.fileName(), file.errorString());
    return false;
}

bool commit(QSaveFile& file, QString* error)
{
    if (file.commit()) return true;
    if (error) *error = QStringLiteral("%1: cannot write the file: %2").arg(file.fileName(), file.errorString());
    return false;
}

}  // namespace

bool diagramFormatOf(const QString& path, DiagramFormat* format)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("svg")) *format = DiagramFormat::Svg;
    else if (suffix == QLatin1String("pdf")) *format = DiagramFormat::Pdf;
    else if (suffix == QLatin1String("png")) *format = DiagramFormat::Png;
    else return false;
    return true;
}

bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error)
{
    QSaveFile file(path);
    if (!openSaveFile(file, error)) return false;
    if (file.write(bytes) != bytes.size()) {
        if (error) *error = QStringLiteral("%1: cannot write the file: %2").arg(path, file.errorString());
        file.cancelWriting();
        return false;
    }
    return commit(file, error);
}

bool writeDiagramSvg(const ShotDiagram& diagram, const QString& path, QString* error)
{
    QSaveFile file(path);
    if (!openSaveFile(file, error)) return false;
    // One SVG user unit per canvas unit: the diagram is painted without scaling, so that the file's
    // coordinates are the canvas's (ShotDiagram::tableToCanvas maps table metres to them).
    const QSizeF canvas(ShotDiagram::kCanvasWidth, diagram.canvasHeight());
    QSvgGenerator svg;
    svg.setOutputDevice(&file);
    svg.setSize(QSize(static_cast<int>(std::ceil(canvas.width())), static_cast<int>(std::ceil(canvas.height()))));
    svg.setViewBox(QRectF(QPointF(0, 0), canvas));
    svg.setTitle(QStringLiteral("CueLab shot diagram"));
    svg.setDescription(QStringLiteral("Top-down diagram of a simulated shot"));
    QPainter painter;
    if (!painter.begin(&svg)) {
        if (error) *error = QStringLiteral("%1: cannot draw the SVG").arg(path);
        file.cancelWriting();
        return false;
    }
    diagram.paint(painter, QRectF(QPointF(0, 0), canvas));
    painter.end();
    return commit(file, error);
}

bool writeDiagramPdf(const ShotDiagram& diagram, const QString& path, QString* error)
{
    QSaveFile file(path);
    if (!openSaveFile(file, error)) return false;
    {
        QPdfWriter pdf(&file);
        pdf.setTitle(QStringLiteral("CueLab shot diagram"));
        pdf.setCreator(QStringLiteral("CueLab"));
        pdf.setResolution(300);
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape, QMarginsF(12, 12, 12, 12),
                                      QPageLayout::Millimeter));
        QPainter painter;
        if (!painter.begin(&pdf)) {
            if (error) *error = QStringLiteral("%1: cannot draw the PDF").arg(path);
            file.cancelWriting();
            return false;
        }
        diagram.paint(painter, QRectF(pdf.pageLayout().paintRectPixels(pdf.resolution()).translated(
            -pdf.pageLayout().paintRectPixels(pdf.resolution()).topLeft())));
        painter.end();
    }
    return commit(file, error);
}

bool writeDiagramPng(const ShotDiagram& diagram, const QString& path, QSize size, QString* error)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        diagram.paint(painter, QRectF(QPointF(0, 0), QSizeF(size)));
    }
    QSaveFile file(path);
    if (!openSaveFile(file, error)) return false;
    if (!image.save(&file, "PNG")) {
        if (error) *error = QStringLiteral("%1: cannot write the image").arg(path);
        file.cancelWriting();
        return false;
    }
    return commit(file, error);
}

bool writeDiagram(const ShotDiagram& diagram, const QString& path, QString* error)
{
    DiagramFormat format = DiagramFormat::Png;
    if (!diagramFormatOf(path, &format)) {
        if (error) *error = QStringLiteral("%1: the extension must be .svg, .pdf or .png").arg(path);
        return false;
    }
    switch (format) {
    case DiagramFormat::Svg: return writeDiagramSvg(diagram, path, error);
    case DiagramFormat::Pdf: return writeDiagramPdf(diagram, path, error);
    case DiagramFormat::Png: {
        const int w = 2000;
        return writeDiagramPng(diagram, path, QSize(w, static_cast<int>(std::ceil(w * diagram.canvasHeight() / ShotDiagram::kCanvasWidth))), error);
    }
    }
    return false;
}

}  // namespace cuelab
