#pragma once
// The one JSON object a benchmark prints as its last line, written field by
// field through nlohmann-json: strings escaped (bytes that are not UTF-8
// become U+FFFD), numbers that read back as the same value, NaN and
// infinities as null (an empty run has no median). Nested objects and
// arrays open with begin...() and close with end().
//
//   BenchJson j;
//   j.field("bench", "load").field("model", path).field("repeats", 5);
//   j.field("load_ms", Fixed{medianMs, 3});            // rounded to 3 decimals
//   j.beginArray("size").value(768).value(576).end();
//   j.beginObject("targets").field("fps_60", fps >= 60.0).end();
//   std::printf("%s\n", j.str().c_str());
//
// Misuse (a key inside an array, end() with nothing open, str() with
// something still open) throws std::logic_error: a bench bug, not input.

#include <nlohmann/json.hpp>

#include <concepts>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

// A number rounded to a count of decimals, where a bench reports a rounded
// figure on purpose (milliseconds to the microsecond). In JSON it is the
// double nearest the rounded decimal (2.000 reads 2.0); number() writes
// the decimals out, for captions and command lines.
struct Fixed {
    double value;
    int decimals;
};

// An integer, not a bool: a bool is written as true or false.
template <class T>
concept WholeNumber = std::integral<T> && !std::same_as<T, bool>;

class BenchJson {
public:
    BenchJson();  // the outer object, open
    // It points into itself: neither copied nor moved.
    BenchJson(const BenchJson&) = delete;
    BenchJson& operator=(const BenchJson&) = delete;

    // In an object: "key": value.
    BenchJson& field(std::string_view key, std::string_view text);
    BenchJson& field(std::string_view key, const char* text) { return field(key, std::string_view(text)); }
    BenchJson& field(std::string_view key, const std::string& text) { return field(key, std::string_view(text)); }
    BenchJson& field(std::string_view key, bool flag);
    BenchJson& field(std::string_view key, double x);
    BenchJson& field(std::string_view key, float x);  // 0.011f reads "0.011", not its double's digits
    BenchJson& field(std::string_view key, Fixed x);
    template <WholeNumber Int>
    BenchJson& field(std::string_view key, Int n) {
        return put(key, n);
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
    template <WholeNumber Int>
    BenchJson& value(Int n) {
        return push(n);
    }
    BenchJson& beginObject();
    BenchJson& beginArray();

    BenchJson& end();  // closes the innermost open object or array

    // The whole object on one line; everything opened since must be closed.
    std::string str() const;

    // `x` as text: the shortest that reads back as the same double (no
    // exponent between 1e-5 and 1e16), "null" when not finite. For
    // captions and command lines; the JSON line formats its own numbers.
    static std::string number(double x);
    static std::string number(float x);
    static std::string number(Fixed x);

private:
    using Json = nlohmann::ordered_json;

    BenchJson& put(std::string_view key, Json value);  // into the innermost open object
    BenchJson& push(Json value);                       // onto the innermost open array
    BenchJson& openIn(Json& container);                // container: the value just added

    Json root_ = Json::object();
    std::vector<Json*> open_;  // the innermost last; a child is open only while its parent takes nothing else
};

}  // namespace arcomp
