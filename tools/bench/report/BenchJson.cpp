#include "tools/bench/report/BenchJson.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace arcomp {

BenchJson::BenchJson() { open('{'); }

std::string BenchJson::quoted(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out = "\"";
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (byte < 0x20) {
            out += "\\u00";
            out += kHex[byte >> 4];
            out += kHex[byte & 0xf];
        } else {
            out += c;  // UTF-8 passes through as it is
        }
    }
    return out + '"';
}

namespace {

// Shortest round-trip digits of `x` in its own type; fixed notation where
// it stays short, so that 20000 does not read "2e+04".
template <class Real>
std::string shortest(Real x) {
    if (!std::isfinite(x)) return "null";
    const Real size = std::abs(x);
    const bool fixed = size == 0 || (size >= Real(1e-5) && size < Real(1e16));
    char digits[64];
    const auto [last, error] = fixed ? std::to_chars(digits, digits + sizeof digits, x, std::chars_format::fixed)
                                     : std::to_chars(digits, digits + sizeof digits, x);
    if (error != std::errc{}) throw std::logic_error("BenchJson: a number did not fit its buffer");
    return std::string(digits, last);
}

} // namespace

std::string BenchJson::number(double x) { return shortest(x); }
std::string BenchJson::number(float x) { return shortest(x); }

std::string BenchJson::number(Fixed x) {
    if (!std::isfinite(x.value)) return "null";
    if (x.decimals < 0 || x.decimals > 17) throw std::logic_error("BenchJson: Fixed takes 0..17 decimals");
    char digits[400];  // DBL_MAX in fixed notation with 17 decimals
    const auto [last, error] = std::to_chars(digits, digits + sizeof digits, x.value, std::chars_format::fixed, x.decimals);
    if (error != std::errc{}) throw std::logic_error("BenchJson: a number did not fit its buffer");
    return std::string(digits, last);
}

BenchJson& BenchJson::raw(std::string_view json) {
    text_ += json;
    return *this;
}

BenchJson& BenchJson::keyed(std::string_view key) {
    if (open_.empty() || open_.back().bracket != '{') throw std::logic_error("BenchJson: a key outside an object");
    if (!open_.back().empty) text_ += ',';
    open_.back().empty = false;
    return raw(quoted(key)).raw(":");
}

BenchJson& BenchJson::nextElement() {
    if (open_.empty() || open_.back().bracket != '[') throw std::logic_error("BenchJson: an element outside an array");
    if (!open_.back().empty) text_ += ',';
    open_.back().empty = false;
    return *this;
}

BenchJson& BenchJson::open(char bracket) {
    text_ += bracket;
    open_.push_back({bracket});
    return *this;
}

BenchJson& BenchJson::field(std::string_view key, std::string_view text) { return keyed(key).raw(quoted(text)); }
BenchJson& BenchJson::field(std::string_view key, bool flag) { return keyed(key).raw(flag ? "true" : "false"); }
BenchJson& BenchJson::field(std::string_view key, double x) { return keyed(key).raw(number(x)); }
BenchJson& BenchJson::field(std::string_view key, float x) { return keyed(key).raw(number(x)); }
BenchJson& BenchJson::field(std::string_view key, Fixed x) { return keyed(key).raw(number(x)); }
BenchJson& BenchJson::null(std::string_view key) { return keyed(key).raw("null"); }
BenchJson& BenchJson::beginObject(std::string_view key) { return keyed(key).open('{'); }
BenchJson& BenchJson::beginArray(std::string_view key) { return keyed(key).open('['); }

BenchJson& BenchJson::value(std::string_view text) { return nextElement().raw(quoted(text)); }
BenchJson& BenchJson::value(bool flag) { return nextElement().raw(flag ? "true" : "false"); }
BenchJson& BenchJson::value(double x) { return nextElement().raw(number(x)); }
BenchJson& BenchJson::value(float x) { return nextElement().raw(number(x)); }
BenchJson& BenchJson::value(Fixed x) { return nextElement().raw(number(x)); }
BenchJson& BenchJson::beginObject() { return nextElement().open('{'); }
BenchJson& BenchJson::beginArray() { return nextElement().open('['); }

BenchJson& BenchJson::end() {
    // The outer object closes in str(), so that str() can be asked twice.
    if (open_.size() < 2) throw std::logic_error("BenchJson: end() with nothing open");
    text_ += open_.back().bracket == '{' ? '}' : ']';
    open_.pop_back();
    return *this;
}

std::string BenchJson::str() const {
    if (open_.size() != 1) throw std::logic_error("BenchJson: str() with an object or array still open");
    return text_ + '}';
}

} // namespace arcomp
