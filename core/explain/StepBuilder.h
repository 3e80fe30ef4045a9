#pragma once
// Filling a Step: named inputs and results, vectors as their components (internal to core/explain).

#include "Explanation.h"

#include <string>
#include <utility>

namespace cuelab::explain {

class StepBuilder {
public:
    StepBuilder(std::vector<Step>& steps, Text title, Text law, Text formula)
        : steps_(steps)
    {
        step_.title = std::move(title);
        step_.law = std::move(law);
        step_.formula = std::move(formula);
    }
    ~StepBuilder() { steps_.push_back(std::move(step_)); }
    StepBuilder(const StepBuilder&) = delete;
    StepBuilder& operator=(const StepBuilder&) = delete;

    StepBuilder& in(std::string key, Text symbol, double value, std::string unit = {}, double scale = 0.0)
    {
        step_.inputs.push_back({std::move(key), std::move(symbol), value, std::move(unit), scale});
        return *this;
    }
    StepBuilder& out(std::string key, Text symbol, double value, std::string unit = {}, double scale = 0.0)
    {
        step_.results.push_back({std::move(key), std::move(symbol), value, std::move(unit), scale});
        return *this;
    }
    // A vector: its components as key_x, key_y (, key_z), symbols "sym_{x}" or "sym_{sub,x}"; each
    // compared with the vector's length (Quantity::scale).
    StepBuilder& in(const std::string& key, const std::string& symbol, const Vec2& v, const std::string& unit)
    {
        for (int k = 0; k < 2; ++k) in(key + axis(k), component(symbol, k), v[k], unit, v.norm());
        return *this;
    }
    StepBuilder& in(const std::string& key, const std::string& symbol, const Vec3& v, const std::string& unit)
    {
        for (int k = 0; k < 3; ++k) in(key + axis(k), component(symbol, k), v[k], unit, v.norm());
        return *this;
    }
    StepBuilder& out(const std::string& key, const std::string& symbol, const Vec2& v, const std::string& unit)
    {
        for (int k = 0; k < 2; ++k) out(key + axis(k), component(symbol, k), v[k], unit, v.norm());
        return *this;
    }
    StepBuilder& out(const std::string& key, const std::string& symbol, const Vec3& v, const std::string& unit)
    {
        for (int k = 0; k < 3; ++k) out(key + axis(k), component(symbol, k), v[k], unit, v.norm());
        return *this;
    }
    Step& step() { return step_; }

    // "v_a" + x -> "v_{a,x}"; "v" + x -> "v_{x}"; "ω'_a" -> "ω'_{a,x}".
    static std::string component(const std::string& symbol, int k)
    {
        const char* names[] = {"x", "y", "z"};
        const std::string c = names[k];
        const std::size_t u = symbol.find('_');
        if (u == std::string::npos) return symbol + "_{" + c + "}";
        std::string sub = symbol.substr(u + 1);
        if (!sub.empty() && sub.front() == '{' && sub.back() == '}') sub = sub.substr(1, sub.size() - 2);
        return symbol.substr(0, u) + "_{" + sub + "," + c + "}";
    }

private:
    static std::string axis(int k) { return k == 0 ? "_x" : k == 1 ? "_y" : "_z"; }
    std::vector<Step>& steps_;
    Step step_;
};

// The ball's id as a symbol subscript ("cue" -> "cue", "1" -> "1").
std::string number(double value);  // shortest round-trip text ("0.1", "1e-05")

}  // namespace cuelab::explain
