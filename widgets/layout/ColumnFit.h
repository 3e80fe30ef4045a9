#pragma once
// A table's columns fitted to its width, for narrow docks (the Outcome dock at 800x600 scrolled
// sideways): every column gets the width its header and cells want while they fit; when they do not,
// the columns give up their slack (down to their longest word) in proportion to it and their text
// wraps onto more lines, so nothing is cut and nothing scrolls sideways. The spare width of a wide
// dock goes to the last column. Call it after the cells change and whenever the table is resized.

// A table whose rows keep one line (compact rows, numbers) only gives up the slack between the widths
// its columns have now and their texts': `ColumnText::OneLine`.

class QTableView;

namespace cuelab {

enum class ColumnText { Wraps, OneLine };

void fitColumnsToWidth(QTableView* table, ColumnText text = ColumnText::Wraps);

}  // namespace cuelab
