#include "runtime/showcontrol/OscBundle.hpp"

#include <new>

namespace arcomp {

OscBundle::Message& OscBundle::Message::i(std::int32_t v) {
    lo_message_add_int32(m_, v);
    return *this;
}

OscBundle::Message& OscBundle::Message::f(float v) {
    lo_message_add_float(m_, v);
    return *this;
}

OscBundle::Message& OscBundle::Message::s(const char* v) {
    lo_message_add_string(m_, v);
    return *this;
}

OscBundle::OscBundle() : bundle_(lo_bundle_new(LO_TT_IMMEDIATE)) {
    if (!bundle_) throw std::bad_alloc();
}

OscBundle::~OscBundle() { lo_bundle_free_recursive(bundle_); }

OscBundle::Message OscBundle::add(const char* path) {
    const lo_message m = lo_message_new();
    if (!m) throw std::bad_alloc();
    if (lo_bundle_add_message(bundle_, path, m) != 0) {
        lo_message_free(m);
        throw std::bad_alloc();
    }
    return Message(m);
}

std::vector<std::uint8_t> OscBundle::bytes() const {
    std::vector<std::uint8_t> out(lo_bundle_length(bundle_));
    std::size_t size = out.size();
    lo_bundle_serialise(bundle_, out.data(), &size);
    out.resize(size);
    return out;
}

}  // namespace arcomp
