#pragma once
// Words of a derivation, kept translatable without Qt (issue 21, item 5). A Text is an English
// template with %1…%9 placeholders and its arguments (ball ids, numbers, table elements, the core's
// names of motion states, other templates), not a finished sentence: english() fills it in as the
// command-line tool prints it, in(lookup) fills it in a language whose templates and names `lookup`
// gives (the window asks Qt's translations, widgets/explain/ExplainLanguage.h).
//
// Templates are written Text::tr("..."), string literals only: lupdate reads this class as one
// translation context, "cuelab::explain" (CUELAB_TRANSLATION_CONTEXT is Q_DECLARE_TR_FUNCTIONS to
// lupdate, app/CMakeLists.txt), and resources/translations/cuelab_hu.ts holds their Hungarian.
// A template is the whole sentence, so that a translation can order its arguments as its language
// wants; markup (Explanation.h) is allowed in templates and arguments alike.

#include <functional>
#include <string>
#include <vector>

// For lupdate only (see above); nothing for the compiler.
#define CUELAB_TRANSLATION_CONTEXT(context)

namespace cuelab::explain {

class Text {
    CUELAB_TRANSLATION_CONTEXT(cuelab::explain)

public:
    enum class Kind {
        Literal,   // shown as it is in every language: a formula, a number, a ball's id
        Template,  // English with %1…%9, translated as a whole (context "cuelab::explain")
        Element,   // a table element's id ("pocket-tr", "rail-r"): the window names it in words
        Name,      // a core name (Names.h): a motion state ("rolling"), an event kind ("slide-to-roll")
        Join,      // the arguments one after the other, `source` between them
        Number,    // a number or a list of numbers, written with a decimal point and ", " between
                   // them: the window writes them its language's way ("0,5; 1,25" in Hungarian)
    };

    Text() = default;
    Text(std::string literal) : source_(std::move(literal)) {}  // NOLINT: a literal reads as itself
    Text(const char* literal) : source_(literal) {}             // NOLINT

    static Text tr(const char* englishTemplate);
    static Text element(std::string id);
    static Text name(std::string coreName);
    static Text join(std::vector<Text> parts, std::string separator);
    static Text numeral(std::string formatted);

    // The next placeholder's argument (%1 first).
    Text& arg(Text value) &;
    Text arg(Text value) &&;

    Kind kind() const { return kind_; }
    const std::string& source() const { return source_; }
    const std::vector<Text>& args() const { return args_; }
    bool empty() const { return kind_ == Kind::Literal && source_.empty(); }

    // The text in a language: `lookup(kind, source)` gives a Template's, Element's or Name's words in
    // it (returning `source` itself keeps the English); placeholders are filled after the lookup.
    using Lookup = std::function<std::string(Kind kind, const std::string& source)>;
    std::string in(const Lookup& lookup) const;
    std::string english() const;

    // Every template in this text and its arguments, for the checks of the translation.
    void collectTemplates(std::vector<std::string>& out) const;

private:
    Kind kind_ = Kind::Literal;
    std::string source_;
    std::vector<Text> args_;
};

}  // namespace cuelab::explain
