#pragma once
// Numbers as the window shows them (issue 44): in the way of the interface's language, QLocale(),
// which the window sets from the language it shows (app/window/Translations.cpp): "0,293 s" beside
// Hungarian text, "0.293 s" beside English. Never with a group separator ("1234,5", as a spin box
// shows it). Machine formats (JSON, CSV, setup files, shot codes, the command line's output) never go
// through these: they keep the decimal point whatever the language.

#include <QString>

namespace cuelab {

// Fixed decimals; a value that rounds to zero is shown as zero, never as "-0.000".
QString uiNumber(double value, int decimals);
// Significant digits (printf's %g).
QString uiSignificant(double value, int digits);
// Between the numbers of a pair or a vector: ", ", or "; " where the decimal separator is a comma
// ("(0,5; 1,25)", not "(0,5, 1,25)").
QString uiListSeparator();

}  // namespace cuelab
