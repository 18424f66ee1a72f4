#pragma once
// The one JSON object a benchmark prints as its last line, written field by
// field: strings escaped, numbers that read back as the same value, NaN
// and infinities as null (an empty run has no median). Nested objects and
// arrays open with begin...() and close with end().
//
//   BenchJson j;
//   j.field("bench", "load").field("model", path).field("repeats", 5);
//   j.field("load_ms", Fixed{medianMs, 3});            // as printf("%.3f")
//   j.beginArray("size").value(768).value(576).end();
//   j.beginObject("targets").field("fps_60", fps >= 60.0).end();
//   std::printf("%s\n", j.str().c_str());
//
// Misuse (a key inside an array, end() with nothing open, str() with
// something still open) throws std::logic_error: a bench bug, not input.

#include <charconv>
#include <concepts>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

// A number written with a fixed count of decimals, where a bench reports a
// rounded figure on purpose (milliseconds to the microsecond).
struct Fixed {
    double value;
    int decimals;
};

class BenchJson {
public:
    BenchJson();  // the outer object, open

    // In an object: "key": value.
    BenchJson& field(std::string_view key, std::string_view text);
    BenchJson& field(std::string_view key, const char* text) { return field(key, std::string_view(text)); }
    BenchJson& field(std::string_view key, const std::string& text) { return field(key, std::string_view(text)); }
    BenchJson& field(std::string_view key, bool flag);
    BenchJson& field(std::string_view key, double x);
    BenchJson& field(std::string_view key, float x);  // 0.011f reads "0.011", not its double's digits
    BenchJson& field(std::string_view key, Fixed x);
    template <std::integral Int>
        requires(!std::same_as<Int, bool>)
    BenchJson& field(std::string_view key, Int n) {
        return keyed(key).integer(n);
    }
    BenchJson& null(std::string_view key);
    BenchJson& beginObject(std::string_view key);
    BenchJson& beginArray(std::string_view key);

    // In an array: the next element.
    BenchJson& value(std::string_view text);
    BenchJson& value(const char* text) { return value(std::string_view(text)); }
    BenchJson& value(const std::string& text) { return value(std::string_view(text)); }
    BenchJson& value(bool flag);
    BenchJson& value(double x);
    BenchJson& value(float x);
    BenchJson& value(Fixed x);
    template <std::integral Int>
        requires(!std::same_as<Int, bool>)
    BenchJson& value(Int n) {
        return nextElement().integer(n);
    }
    BenchJson& beginObject();
    BenchJson& beginArray();

    BenchJson& end();  // closes the innermost open object or array

    // The whole object on one line; everything opened since must be closed.
    std::string str() const;

    // `text` as a JSON string literal, quotes included.
    static std::string quoted(std::string_view text);
    // `x` as JSON: the shortest text that reads back as the same double
    // (no exponent between 1e-5 and 1e16), null when not finite.
    static std::string number(double x);
    static std::string number(float x);
    static std::string number(Fixed x);

private:
    struct Open {
        char bracket;  // '{' or '['
        bool empty = true;
    };

    BenchJson& keyed(std::string_view key);  // the separator, the key and its colon
    BenchJson& nextElement();               // the separator before an array element
    BenchJson& open(char bracket);
    BenchJson& raw(std::string_view json);
    template <std::integral Int>
    BenchJson& integer(Int n) {
        char digits[24];
        const char* last = std::to_chars(digits, digits + sizeof digits, n).ptr;
        return raw(std::string_view(digits, static_cast<std::size_t>(last - digits)));
    }

    std::string text_;
    std::vector<Open> open_;
};

} // namespace arcomp
