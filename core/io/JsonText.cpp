#include "JsonText.h"

#include "NumberText.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace cuelab::io {

std::string roundTripNumber(double value)
{
    // JSON has no form for not-a-number and the infinities; the rest as every number prints
    // (core/setup/NumberText.h).
    return std::isfinite(value) ? roundTripText(value) : std::string("null");
}

void JsonWriter::newline()
{
    out_ += '\n';
    out_.append(2 * levels_.size(), ' ');
}

void JsonWriter::beforeValue()
{
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (levels_.empty()) return;
    Level& level = levels_.back();
    assert(!level.isObject && "a value inside an object needs a key first");
    if (!level.empty) out_ += level.layout == Layout::Block ? "," : ", ";
    if (level.layout == Layout::Block) newline();
    level.empty = false;
}

void JsonWriter::open(char bracket, Layout layout, bool isObject)
{
    beforeValue();
    // Inside a one-line container everything stays on that line.
    if (!levels_.empty() && levels_.back().layout == Layout::Line) layout = Layout::Line;
    out_ += bracket;
    levels_.push_back({layout, isObject});
}

void JsonWriter::close(char bracket)
{
    assert(!levels_.empty());
    const Level level = levels_.back();
    levels_.pop_back();
    if (!level.empty) {
        if (level.layout == Layout::Block)
            newline();
        else if (level.isObject)
            out_ += ' ';
    }
    out_ += bracket;
    if (levels_.empty()) out_ += '\n';
}

void JsonWriter::beginObject(Layout layout) { open('{', layout, true); }
void JsonWriter::endObject() { close('}'); }
void JsonWriter::beginArray(Layout layout) { open('[', layout, false); }
void JsonWriter::endArray() { close(']'); }

void JsonWriter::key(std::string_view name)
{
    assert(!levels_.empty() && levels_.back().isObject && !afterKey_);
    Level& level = levels_.back();
    if (!level.empty) out_ += level.layout == Layout::Block ? "," : ", ";
    if (level.layout == Layout::Block)
        newline();
    else if (level.empty)
        out_ += ' ';
    level.empty = false;
    writeString(name);
    out_ += ": ";
    afterKey_ = true;
}

void JsonWriter::value(double number)
{
    beforeValue();
    out_ += roundTripNumber(number);
}

void JsonWriter::value(int number)
{
    beforeValue();
    out_ += std::to_string(number);
}

void JsonWriter::value(long long number)
{
    beforeValue();
    out_ += std::to_string(number);
}

void JsonWriter::value(bool flag)
{
    beforeValue();
    out_ += flag ? "true" : "false";
}

void JsonWriter::value(std::string_view text)
{
    beforeValue();
    writeString(text);
}

void JsonWriter::null()
{
    beforeValue();
    out_ += "null";
}

void JsonWriter::writeString(std::string_view text)
{
    out_ += '"';
    for (const char c : text) {
        switch (c) {
        case '"': out_ += "\\\""; break;
        case '\\': out_ += "\\\\"; break;
        case '\n': out_ += "\\n"; break;
        case '\r': out_ += "\\r"; break;
        case '\t': out_ += "\\t"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                std::array<char, 8> escaped{};
                std::snprintf(escaped.data(), escaped.size(), "\\u%04x", static_cast<unsigned>(c));
                out_ += escaped.data();
            } else {
                out_ += c;  // UTF-8 passes through unchanged
            }
        }
    }
    out_ += '"';
}

void JsonWriter::numbers(const double* values, int count)
{
    beginArray(Layout::Line);
    for (int i = 0; i < count; ++i) value(values[i]);
    endArray();
}

}  // namespace cuelab::io
