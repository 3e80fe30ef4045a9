#include "layout/ColumnFit.h"

#include <QAbstractItemModel>
#include <QFontMetrics>
#include <QHeaderView>
#include <QRegularExpression>
#include <QStyle>
#include <QTableView>

#include <algorithm>
#include <numeric>
#include <vector>

namespace cuelab {

namespace {

// The widest unbreakable piece of `text` (it wraps at spaces only).
int longestWord(const QFontMetrics& metrics, const QString& text)
{
    static const QRegularExpression space(QStringLiteral("\\s+"));
    int widest = 0;
    for (const QString& word : text.split(space, Qt::SkipEmptyParts)) widest = std::max(widest, metrics.horizontalAdvance(word));
    return widest;
}

}  // namespace

void fitColumnsToWidth(QTableView* table, ColumnText text)
{
    QAbstractItemModel* model = table->model();
    QHeaderView* header = table->horizontalHeader();
    if (!model || header->count() == 0) return;
    const int columns = header->count();
    const bool wraps = text == ColumnText::Wraps;
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    if (wraps) {
        table->setWordWrap(true);
        table->setTextElideMode(Qt::ElideNone);
    }

    // Padding of a cell beyond its text: the item delegate's text margin on each side (the style's
    // focus frame margin + 1, as QStyledItemDelegate lays text out) and the grid line.
    const int pad = 2 * (table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1) + (table->showGrid() ? 1 : 0);
    const QFontMetrics cell(table->font());
    std::vector<int> want(columns), least(columns);
    for (int c = 0; c < columns; ++c) {
        // One-line tables were sized by their owner (room for values to come): those widths are wanted.
        want[c] = wraps ? std::max(static_cast<QAbstractItemView*>(table)->sizeHintForColumn(c), header->sectionSizeHint(c)) : header->sectionSize(c);
        const auto unbreakable = [&](const QFontMetrics& m, const QString& s) { return wraps ? longestWord(m, s) : m.horizontalAdvance(s); };
        // A header section does not wrap: its whole title and margins stay.
        least[c] = header->sectionSizeHint(c);
        for (int r = 0; r < model->rowCount(); ++r)
            least[c] = std::max(least[c], unbreakable(cell, model->index(r, c).data().toString()) + pad);
        least[c] = std::min(least[c], want[c]);
    }
    const int available = table->viewport()->width();
    const int wanted = std::accumulate(want.begin(), want.end(), 0);
    std::vector<int> width = want;
    if (wanted <= available) {
        width.back() += available - wanted;
    } else {
        const int slack = wanted - std::accumulate(least.begin(), least.end(), 0);
        const int excess = wanted - available;
        if (slack <= excess) {
            width = least;  // even every column at its longest word does not fit: the scroll bar shows
        } else {
            int given = 0;
            for (int c = 0; c < columns; ++c) {
                const int share = static_cast<int>(static_cast<long long>(excess) * (want[c] - least[c]) / slack);
                width[c] = want[c] - share;
                given += share;
            }
            // Rounding: the last column that can still give takes the rest.
            for (int c = columns - 1; c >= 0 && given < excess; --c) {
                const int more = std::min(excess - given, width[c] - least[c]);
                width[c] -= more;
                given += more;
            }
        }
    }
    for (int c = 0; c < columns; ++c) header->resizeSection(c, width[c]);
    if (wraps) table->resizeRowsToContents();
}

}  // namespace cuelab
