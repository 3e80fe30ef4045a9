#pragma once
// The bundled examples' names and lesson notes in the window's language (issue 23's list: "the
// example lessons are not translated"). The files stay English (a setup has one `name` and one
// `notes`); the translations live with the window's in resources/translations (context
// "cuelab::examples"), keyed by the English text. ExampleStrings.cpp, generated from the files by
// scripts/example-strings.py, hands every string to lupdate.

#include "Setup.h"

#include <QString>

#include <string>
#include <vector>

namespace cuelab {

struct ExampleString {
    const char* file;   // "straight-shot.json"
    const char* name;   // the setup's `name`
    const char* notes;  // its `notes`
};

// Every bundled example's strings, as the generator read them from resources/examples.
const std::vector<ExampleString>& exampleStrings();

// An example's name or notes in the installed language; the text itself when it has no translation
// (a user's own file, an example newer than the translation, or English).
QString translatedExampleText(const std::string& english);

// The setup's name and notes in the installed language (an example opened from the Examples menu).
void translateExample(Setup& setup);

}  // namespace cuelab
