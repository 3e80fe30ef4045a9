#include "ExplainText.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace cuelab::explain {

namespace {

// One UTF-8 character starting at s[i].
std::size_t charLength(const std::string& s, std::size_t i)
{
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) return 1;
    if ((c >> 5) == 0x6) return 2;
    if ((c >> 4) == 0xE) return 3;
    return 4;
}

// The script part after '_' or '^' at s[i]: "{...}" or one character; advances i past it.
std::string scriptAt(const std::string& s, std::size_t& i)
{
    if (i < s.size() && s[i] == '{') {
        const std::size_t close = s.find('}', i);
        const std::size_t end = close == std::string::npos ? s.size() : close;
        std::string inner = s.substr(i + 1, end - i - 1);
        i = end == s.size() ? end : end + 1;
        return inner;
    }
    if (i >= s.size()) return {};
    const std::size_t n = charLength(s, i);
    std::string one = s.substr(i, n);
    i += n;
    return one;
}

std::string escape(const std::string& s)
{
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else out += c;
    }
    return out;
}

bool scriptable(const std::string& s, std::size_t i)
{
    // A '_' or '^' followed by something that can be a script (not a space, not the end).
    return i + 1 < s.size() && s[i + 1] != ' ';
}

const std::map<std::string, std::string>& superscripts()
{
    static const std::map<std::string, std::string> m{
        {"0", "⁰"}, {"1", "¹"}, {"2", "²"}, {"3", "³"}, {"4", "⁴"}, {"5", "⁵"}, {"6", "⁶"}, {"7", "⁷"},
        {"8", "⁸"}, {"9", "⁹"}, {"−", "⁻"}, {"-", "⁻"}, {"+", "⁺"}, {"n", "ⁿ"}, {"i", "ⁱ"}};
    return m;
}

const std::map<std::string, std::string>& subscripts()
{
    static const std::map<std::string, std::string> m{
        {"0", "₀"}, {"1", "₁"}, {"2", "₂"}, {"3", "₃"}, {"4", "₄"}, {"5", "₅"}, {"6", "₆"}, {"7", "₇"},
        {"8", "₈"}, {"9", "₉"}, {"a", "ₐ"}, {"e", "ₑ"}, {"o", "ₒ"}, {"x", "ₓ"}, {"h", "ₕ"}, {"k", "ₖ"},
        {"l", "ₗ"}, {"m", "ₘ"}, {"n", "ₙ"}, {"p", "ₚ"}, {"s", "ₛ"}, {"t", "ₜ"}, {"i", "ᵢ"}, {"j", "ⱼ"},
        {"r", "ᵣ"}, {"u", "ᵤ"}, {"v", "ᵥ"}, {"+", "₊"}, {"−", "₋"}, {"-", "₋"}, {",", ","}};
    return m;
}

// The script in Unicode when it is one character or only digits and every character has a form;
// otherwise `_name` or `_(a,x)` (a mix of Unicode and plain letters reads worse than either).
std::string unicodeScript(const std::string& inner, bool super)
{
    const auto& table = super ? superscripts() : subscripts();
    const std::string mark = super ? "^" : "_";
    bool digits = true;
    for (char c : inner) digits = digits && ((c >= '0' && c <= '9') || c == '-');
    const bool single = !inner.empty() && charLength(inner, 0) == inner.size();
    std::string out;
    bool mapped = super || single || digits;
    for (std::size_t i = 0; i < inner.size() && mapped;) {
        const std::size_t n = charLength(inner, i);
        const auto it = table.find(inner.substr(i, n));
        if (it == table.end()) mapped = false;
        else out += it->second;
        i += n;
    }
    if (mapped) return out;
    const bool plain = inner.find_first_of(", +") == std::string::npos;
    return plain ? mark + inner : mark + "(" + inner + ")";
}

// The renderers' own words. (Text::tr calls stand in functions that return a Text: lupdate loses
// their context in a function that returns a std::string.)
enum class Word { Inputs, Results, Heading, CollisionModel, Roots, Chosen, OutsideWindow, BodiesPart, OffSegment, Later, None };

Text word(Word w)
{
    switch (w) {
    case Word::Inputs: return Text::tr("Inputs:");
    case Word::Results: return Text::tr("Results:");
    case Word::Heading: return Text::tr("%1 (event %2, t = %3 s)");
    case Word::CollisionModel: return Text::tr("Collision model: %1");
    case Word::Roots: return Text::tr("Roots of f(τ):");
    case Word::Chosen: return Text::tr("chosen");
    case Word::OutsideWindow: return Text::tr("outside the window");
    case Word::BodiesPart: return Text::tr("the bodies part");
    case Word::OffSegment: return Text::tr("off the segment");
    case Word::Later: return Text::tr("later");
    case Word::None: return Text::tr("none");
    }
    return {};
}

std::string unitText(const std::string& unit) { return unit.empty() ? std::string() : " " + unit; }

// A number as the reader's language writes it (Text::Kind::Number).
std::string localNumber(const std::string& number, const Text::Lookup& language)
{
    return language ? language(Text::Kind::Number, number) : number;
}

std::string stepMarkdown(const Step& s, int number, const Text::Lookup& language)
{
    std::string out = "### " + std::to_string(number) + ". " + markupToText(s.title.in(language)) + "\n\n";
    const std::string law = s.law.in(language);
    if (!law.empty()) out += markupToText(law) + "\n\n";
    const std::string formula = s.formula.in(language);
    if (!formula.empty()) out += "    " + markupToText(formula) + "\n\n";
    if (!s.inputs.empty()) {
        out += word(Word::Inputs).in(language);
        for (const Quantity& q : s.inputs)
            out += " " + markupToText(q.symbol.in(language)) + " = " + localNumber(readable(q.value, q.scale), language) + unitText(q.unit) + ";";
        out.back() = '\n';
        out += "\n";
    }
    if (!s.results.empty()) {
        out += "**" + word(Word::Results).in(language) + "**";
        for (const Quantity& q : s.results)
            out += " **" + markupToText(q.symbol.in(language)) + " = " + localNumber(readable(q.value, q.scale), language) + unitText(q.unit) + "**;";
        out.back() = '\n';
        out += "\n";
    }
    return out;
}

std::string heading(const Explanation& e, const Text::Lookup& language)
{
    return word(Word::Heading).arg(e.title).arg(eventNumber(e.event)).arg(Text::numeral(readable(e.time))).in(language);
}

std::string quantitiesHtml(const std::vector<Quantity>& qs, bool result, const Text::Lookup& language)
{
    std::string out;
    for (const Quantity& q : qs) {
        out += result ? "<tr><td style=\"background-color:#fff3c4\"><b>" : "<tr><td>";
        out += markupToHtml(q.symbol.in(language)) + " = " + escape(localNumber(readable(q.value, q.scale), language)) + (q.unit.empty() ? "" : " " + escape(q.unit));
        out += result ? "</b></td></tr>" : "</td></tr>";
    }
    return out;
}

}  // namespace

std::string eventNumber(int index) { return "#" + std::to_string(index + 1); }

std::string readable(double value)
{
    if (std::isinf(value)) return value > 0 ? "∞" : "−∞";
    if (std::isnan(value)) return "NaN";
    if (value == 0.0) return "0";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    std::string s = buffer;
    if (!s.empty() && s[0] == '-') s = "−" + s.substr(1);
    return s;
}

std::string readable(double value, double scale)
{
    // (A component of a vector, or a difference of two near-equal numbers: 1e-12 is well below the
    // 6 digits shown and well above a double's rounding of the size it belongs to.)
    if (std::isfinite(value) && std::abs(value) <= 1e-12 * std::abs(scale)) return "0";
    return readable(value);
}

std::string markupToHtml(const std::string& m)
{
    std::string out;
    for (std::size_t i = 0; i < m.size();) {
        if ((m[i] == '_' || m[i] == '^') && scriptable(m, i)) {
            const bool super = m[i] == '^';
            ++i;
            const std::string inner = scriptAt(m, i);
            out += super ? "<sup>" : "<sub>";
            out += markupToHtml(inner);
            out += super ? "</sup>" : "</sub>";
            continue;
        }
        const std::size_t n = charLength(m, i);
        out += escape(m.substr(i, n));
        i += n;
    }
    return out;
}

std::string markupToText(const std::string& m)
{
    std::string out;
    for (std::size_t i = 0; i < m.size();) {
        if ((m[i] == '_' || m[i] == '^') && scriptable(m, i)) {
            const bool super = m[i] == '^';
            ++i;
            out += unicodeScript(scriptAt(m, i), super);
            continue;
        }
        const std::size_t n = charLength(m, i);
        out += m.substr(i, n);
        i += n;
    }
    return out;
}

std::string toMarkdown(const Explanation& e, const Text::Lookup& language)
{
    std::string out = "## " + markupToText(heading(e, language)) + "\n\n";
    if (!e.model.empty()) out += word(Word::CollisionModel).arg(e.model).in(language) + "\n\n";
    int n = 0;
    for (const Step& s : e.steps) out += stepMarkdown(s, ++n, language) + "\n";
    if (e.toi) {
        out += word(Word::Roots).in(language);
        for (const ToiRoot& r : e.toi->roots) {
            const Text status = r.chosen      ? word(Word::Chosen)
                                : !r.inWindow ? word(Word::OutsideWindow)
                                : !r.closing  ? word(Word::BodiesPart)
                                : !r.onSegment ? word(Word::OffSegment)
                                               : word(Word::Later);
            out += " τ = " + localNumber(readable(r.tau), language) + " s (" + status.in(language) + ");";
        }
        if (e.toi->roots.empty()) out += " " + word(Word::None).in(language) + ";";
        out.back() = '\n';
        out += "\n";
    }
    return out;
}

std::string toMarkdown(const std::vector<Explanation>& all, const std::string& title, const Text::Lookup& language)
{
    std::string out = "# " + title + "\n\n";
    for (const Explanation& e : all) out += toMarkdown(e, language) + "\n";
    return out;
}

std::string toHtml(const Explanation& e, const Text::Lookup& language)
{
    std::string out = "<h2>" + markupToHtml(heading(e, language)) + "</h2>";
    if (!e.model.empty()) {
        // The model's name in bold: its place in the sentence comes from the template.
        const std::string mark = "\x01";
        const std::string label = escape(word(Word::CollisionModel).arg(mark).in(language));
        const std::size_t at = label.find(mark);
        const std::string model = "<b>" + escape(e.model.in(language)) + "</b>";
        out += "<p>" + (at == std::string::npos ? label + " " + model : label.substr(0, at) + model + label.substr(at + 1)) + "</p>";
    }
    int n = 0;
    for (const Step& s : e.steps) {
        out += "<h3>" + std::to_string(++n) + ". " + markupToHtml(s.title.in(language)) + "</h3>";
        const std::string law = s.law.in(language);
        if (!law.empty()) out += "<p>" + markupToHtml(law) + "</p>";
        const std::string formula = s.formula.in(language);
        if (!formula.empty()) out += "<p style=\"margin-left:12px\"><i>" + markupToHtml(formula) + "</i></p>";
        out += "<table cellspacing=\"0\" cellpadding=\"2\" style=\"margin-left:12px\">";
        out += quantitiesHtml(s.inputs, false, language) + quantitiesHtml(s.results, true, language) + "</table>";
    }
    return out;
}

std::string toHtmlDocument(const std::vector<Explanation>& all, const std::string& title, const Text::Lookup& language)
{
    std::string out = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escape(title) +
                      "</title></head><body style=\"font-family:sans-serif\">\n<h1>" + escape(title) + "</h1>\n";
    for (const Explanation& e : all) out += toHtml(e, language) + "\n<hr>\n";
    out += "</body></html>\n";
    return out;
}

}  // namespace cuelab::explain
