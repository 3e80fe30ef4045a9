#pragma once
// The derivations of core/explain in the window's language (issue 21, item 5): their templates
// (context "cuelab::explain", resources/translations), the core's names (DisplayNames) and the
// table's elements ("pocket-tr" → "top-right pocket") from Qt's installed translations. In English
// the words are the command-line tool's, except that table elements are named in words.

#include "Text.h"

#include <QString>

namespace cuelab {

inline constexpr char kExplainContext[] = "cuelab::explain";

explain::Text::Lookup explainLanguage();
QString translated(const explain::Text& text);  // filled in the window's language, markup kept

}  // namespace cuelab
