#include "NumberText.h"

#include <array>
#include <charconv>

namespace cuelab {

std::string roundTripText(double value)
{
    // 32 characters hold every double's shortest form (at most 24: "-2.2250738585072014e-308").
    std::array<char, 32> buffer{};
    const std::to_chars_result r = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), r.ptr);
}

}  // namespace cuelab
