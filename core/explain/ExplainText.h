#pragma once
// Explanations for people: Markdown (cuelab-cli explain --format markdown, handouts) and HTML (the
// Explain dock, handouts). Formulas and symbols carry the markup of Explanation.h: HTML renders it
// as <sub>/<sup>, Markdown as Unicode sub- and superscripts where they exist.

#include "Explanation.h"

#include <string>
#include <vector>

namespace cuelab::explain {

// The number a person reads for event `index` (0-based, as in JSON and `--event N`): "#1" for the
// first event (CONTRACT.md, Extensions version 2: everything a person reads numbers events from 1).
std::string eventNumber(int index);

// A number for people: 6 significant digits ("0.292614", "1.2e-07"), "∞" for infinity.
std::string readable(double value);
// The same for a value that belongs to something of size `scale` (Quantity::scale): within 1e-12 of
// it the value is rounding noise and reads "0".
std::string readable(double value, double scale);

// Markup -> HTML (escaped, <sub>/<sup>) and -> plain Unicode text.
std::string markupToHtml(const std::string& markup);
std::string markupToText(const std::string& markup);

// `language` gives the words of another language (Text.h); without it the text is English, as the
// command-line tool prints it.
std::string toMarkdown(const Explanation& e, const Text::Lookup& language = {});
std::string toMarkdown(const std::vector<Explanation>& all, const std::string& heading, const Text::Lookup& language = {});

// An HTML fragment (for a QTextBrowser), or a whole standalone document for several explanations.
std::string toHtml(const Explanation& e, const Text::Lookup& language = {});
std::string toHtmlDocument(const std::vector<Explanation>& all, const std::string& heading,
                           const Text::Lookup& language = {});

}  // namespace cuelab::explain
