#pragma once
// Writing a shot diagram to a file: SVG (QSvgGenerator), PDF (QPdfWriter, one A4 landscape page) or
// PNG (a QImage of a chosen size), by the file's extension. Every write is atomic (QSaveFile): a file
// that cannot be written leaves any file already there intact, and *error says why.

#include "ShotDiagram.h"

#include <QSize>
#include <QString>

namespace cuelab {

enum class DiagramFormat { Svg, Pdf, Png };

// The format that a file name's extension asks for (case-insensitive); false when it is none of them.
bool diagramFormatOf(const QString& path, DiagramFormat* format);

bool writeDiagramSvg(const ShotDiagram& diagram, const QString& path, QString* error);
bool writeDiagramPdf(const ShotDiagram& diagram, const QString& path, QString* error);
bool writeDiagramPng(const ShotDiagram& diagram, const QString& path, QSize size, QString* error);
bool writeDiagram(const ShotDiagram& diagram, const QString& path, QString* error);  // by extension

// Any bytes, atomically (used for CSV and JSON exports too).
bool writeFileAtomically(const QString& path, const QByteArray& bytes, QString* error);

}  // namespace cuelab
