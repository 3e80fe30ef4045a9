#pragma once
// Writing JSON text by hand, so that keys keep the order a person expects (QJsonObject sorts them)
// and every number prints with the shortest text that reads back to the same double.

#include <string>
#include <string_view>
#include <vector>

namespace cuelab::io {

// The shortest decimal text that parses back to exactly `value` (cuelab::roundTripText, the one
// formatter), e.g. "0.1", "600", "1e-05", "-0". Not-a-number and infinities have no JSON form: they
// print as "null".
std::string roundTripNumber(double value);

// A streaming JSON writer. Objects and arrays are laid out either one member per line (Block) or
// all on one line (Line); anything inside a Line container is on that line too.
class JsonWriter {
public:
    enum class Layout { Block, Line };

    void beginObject(Layout layout = Layout::Line);
    void endObject();
    void beginArray(Layout layout = Layout::Line);
    void endArray();

    void key(std::string_view name);  // inside an object, before each value

    void value(double number);
    void value(int number);
    void value(long long number);  // a whole number, in digits ("100000", never "1e+05")
    void value(bool flag);
    void value(std::string_view text);
    void value(const char* text) { value(std::string_view(text)); }
    void null();                      // the literal null
    void numbers(const double* values, int count);  // a Line array of numbers

    // The text so far; once the outermost container is closed it ends with a newline.
    const std::string& text() const { return out_; }

private:
    struct Level {
        Layout layout;
        bool isObject;
        bool empty = true;
    };
    void beforeValue();
    void open(char bracket, Layout layout, bool isObject);
    void close(char bracket);
    void newline();
    void writeString(std::string_view text);

    std::vector<Level> levels_;
    std::string out_;
    bool afterKey_ = false;
};

}  // namespace cuelab::io
