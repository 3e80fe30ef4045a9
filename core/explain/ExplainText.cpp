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

std::string unitText(const std::string& unit) { return unit.empty() ? std::string() : " " + unit; }

std::string stepMarkdown(const Step& s, int number)
{
    std::string out = "### " + std::to_string(number) + ". " + markupToText(s.title) + "\n\n";
    if (!s.law.empty()) out += markupToText(s.law) + "\n\n";
    out += "    " + markupToText(s.formula) + "\n\n";
    if (!s.inputs.empty()) {
        out += "Inputs:";
        for (const Quantity& q : s.inputs)
            out += " " + markupToText(q.symbol) + " = " + readable(q.value) + unitText(q.unit) + ";";
        out.back() = '\n';
        out += "\n";
    }
    if (!s.results.empty()) {
        out += "**Results:**";
        for (const Quantity& q : s.results)
            out += " **" + markupToText(q.symbol) + " = " + readable(q.value) + unitText(q.unit) + "**;";
        out.back() = '\n';
        out += "\n";
    }
    return out;
}

std::string heading(const Explanation& e)
{
    return e.title + " (event " + eventNumber(e.event) + ", t = " + readable(e.time) + " s)";
}

std::string quantitiesHtml(const std::vector<Quantity>& qs, bool result)
{
    std::string out;
    for (const Quantity& q : qs) {
        out += result ? "<tr><td style=\"background-color:#fff3c4\"><b>" : "<tr><td>";
        out += markupToHtml(q.symbol) + " = " + escape(readable(q.value)) + (q.unit.empty() ? "" : " " + escape(q.unit));
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

std::string toMarkdown(const Explanation& e)
{
    std::string out = "## " + markupToText(heading(e)) + "\n\n";
    if (!e.model.empty()) out += "Collision model: " + e.model + "\n\n";
    int n = 0;
    for (const Step& s : e.steps) out += stepMarkdown(s, ++n) + "\n";
    if (e.toi) {
        out += "Roots of f(τ):";
        for (const ToiRoot& r : e.toi->roots) {
            out += " τ = " + readable(r.tau) + " s (";
            out += r.chosen ? "chosen" : !r.inWindow ? "outside the window" : !r.closing ? "the bodies part" : !r.onSegment ? "off the segment" : "later";
            out += ");";
        }
        if (e.toi->roots.empty()) out += " none;";
        out.back() = '\n';
        out += "\n";
    }
    return out;
}

std::string toMarkdown(const std::vector<Explanation>& all, const std::string& title)
{
    std::string out = "# " + title + "\n\n";
    for (const Explanation& e : all) out += toMarkdown(e) + "\n";
    return out;
}

std::string toHtml(const Explanation& e)
{
    std::string out = "<h2>" + markupToHtml(heading(e)) + "</h2>";
    if (!e.model.empty()) out += "<p>Collision model: <b>" + escape(e.model) + "</b></p>";
    int n = 0;
    for (const Step& s : e.steps) {
        out += "<h3>" + std::to_string(++n) + ". " + markupToHtml(s.title) + "</h3>";
        if (!s.law.empty()) out += "<p>" + markupToHtml(s.law) + "</p>";
        out += "<p style=\"margin-left:12px\"><i>" + markupToHtml(s.formula) + "</i></p>";
        out += "<table cellspacing=\"0\" cellpadding=\"2\" style=\"margin-left:12px\">";
        out += quantitiesHtml(s.inputs, false) + quantitiesHtml(s.results, true) + "</table>";
    }
    return out;
}

std::string toHtmlDocument(const std::vector<Explanation>& all, const std::string& title)
{
    std::string out = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escape(title) +
                      "</title></head><body style=\"font-family:sans-serif\">\n<h1>" + escape(title) + "</h1>\n";
    for (const Explanation& e : all) out += toHtml(e) + "\n<hr>\n";
    out += "</body></html>\n";
    return out;
}

}  // namespace cuelab::explain
