#include "tools/bench/report/BenchJson.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace arcomp {

BenchJson::BenchJson() { open_.push_back(&root_); }

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

}  // namespace

std::string BenchJson::number(double x) { return shortest(x); }
std::string BenchJson::number(float x) { return shortest(x); }

std::string BenchJson::number(Fixed x) {
    if (!std::isfinite(x.value)) return "null";
    if (x.decimals < 0 || x.decimals > 17) throw std::logic_error("BenchJson: Fixed takes 0..17 decimals");
    char digits[400];  // DBL_MAX in fixed notation with 17 decimals
    const auto [last, error] =
        std::to_chars(digits, digits + sizeof digits, x.value, std::chars_format::fixed, x.decimals);
    if (error != std::errc{}) throw std::logic_error("BenchJson: a number did not fit its buffer");
    return std::string(digits, last);
}

namespace {

// The double a reader gets from number()'s text: for a float, the nearest
// to its own shortest digits; for a Fixed, the nearest to the rounded value.
nlohmann::ordered_json asJson(const std::string& text) {
    if (text == "null") return nullptr;
    double x = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), x);
    return x;
}

}  // namespace

BenchJson& BenchJson::put(std::string_view key, Json value) {
    if (open_.back()->is_array()) throw std::logic_error("BenchJson: a key outside an object");
    (*open_.back())[std::string(key)] = std::move(value);
    return *this;
}

BenchJson& BenchJson::push(Json value) {
    if (!open_.back()->is_array()) throw std::logic_error("BenchJson: an element outside an array");
    open_.back()->push_back(std::move(value));
    return *this;
}

BenchJson& BenchJson::openIn(Json& container) {
    open_.push_back(&container);
    return *this;
}

BenchJson& BenchJson::field(std::string_view key, std::string_view text) { return put(key, std::string(text)); }
BenchJson& BenchJson::field(std::string_view key, bool flag) { return put(key, flag); }
BenchJson& BenchJson::field(std::string_view key, double x) { return put(key, asJson(number(x))); }
BenchJson& BenchJson::field(std::string_view key, float x) { return put(key, asJson(number(x))); }
BenchJson& BenchJson::field(std::string_view key, Fixed x) { return put(key, asJson(number(x))); }
BenchJson& BenchJson::null(std::string_view key) { return put(key, nullptr); }
BenchJson& BenchJson::beginObject(std::string_view key) {
    put(key, Json::object());
    return openIn((*open_.back())[std::string(key)]);
}
BenchJson& BenchJson::beginArray(std::string_view key) {
    put(key, Json::array());
    return openIn((*open_.back())[std::string(key)]);
}

BenchJson& BenchJson::value(std::string_view text) { return push(std::string(text)); }
BenchJson& BenchJson::value(bool flag) { return push(flag); }
BenchJson& BenchJson::value(double x) { return push(asJson(number(x))); }
BenchJson& BenchJson::value(float x) { return push(asJson(number(x))); }
BenchJson& BenchJson::value(Fixed x) { return push(asJson(number(x))); }
BenchJson& BenchJson::beginObject() {
    push(Json::object());
    return openIn(open_.back()->back());
}
BenchJson& BenchJson::beginArray() {
    push(Json::array());
    return openIn(open_.back()->back());
}

BenchJson& BenchJson::end() {
    // The outer object closes in str(), so that str() can be asked twice.
    if (open_.size() < 2) throw std::logic_error("BenchJson: end() with nothing open");
    open_.pop_back();
    return *this;
}

std::string BenchJson::str() const {
    if (open_.size() != 1) throw std::logic_error("BenchJson: str() with an object or array still open");
    return root_.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace arcomp
