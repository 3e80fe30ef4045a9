#include "Text.h"

#include <utility>

namespace cuelab::explain {

Text Text::tr(const char* englishTemplate)
{
    Text t(englishTemplate);
    t.kind_ = Kind::Template;
    return t;
}

Text Text::element(std::string id)
{
    Text t(std::move(id));
    t.kind_ = Kind::Element;
    return t;
}

Text Text::name(std::string coreName)
{
    Text t(std::move(coreName));
    t.kind_ = Kind::Name;
    return t;
}

Text Text::join(std::vector<Text> parts, std::string separator)
{
    Text t(std::move(separator));
    t.kind_ = Kind::Join;
    t.args_ = std::move(parts);
    return t;
}

Text Text::numeral(std::string formatted)
{
    Text t;
    t.kind_ = Kind::Number;
    t.source_ = std::move(formatted);
    return t;
}

Text& Text::arg(Text value) &
{
    args_.push_back(std::move(value));
    return *this;
}

Text Text::arg(Text value) &&
{
    args_.push_back(std::move(value));
    return std::move(*this);
}

std::string Text::in(const Lookup& lookup) const
{
    switch (kind_) {
    case Kind::Literal: return source_;
    case Kind::Element:
    case Kind::Name:
    case Kind::Number: return lookup ? lookup(kind_, source_) : source_;
    case Kind::Join: {
        std::string out;
        bool first = true;
        for (const Text& part : args_) {
            const std::string words = part.in(lookup);
            if (words.empty()) continue;  // (an optional sentence left out)
            if (!first) out += source_;
            out += words;
            first = false;
        }
        return out;
    }
    case Kind::Template: break;
    }
    // One pass over the template, so that an argument's own '%' is never read as a placeholder.
    const std::string words = lookup ? lookup(kind_, source_) : source_;
    std::string out;
    out.reserve(words.size());
    for (std::size_t i = 0; i < words.size(); ++i) {
        const char c = words[i];
        if (c == '%' && i + 1 < words.size() && words[i + 1] >= '1' && words[i + 1] <= '9') {
            const std::size_t k = static_cast<std::size_t>(words[i + 1] - '1');
            if (k < args_.size()) out += args_[k].in(lookup);
            ++i;
            continue;
        }
        out += c;
    }
    return out;
}

std::string Text::english() const { return in(Lookup()); }

void Text::collectTemplates(std::vector<std::string>& out) const
{
    if (kind_ == Kind::Template) out.push_back(source_);
    for (const Text& a : args_) a.collectTemplates(out);
}

}  // namespace cuelab::explain
