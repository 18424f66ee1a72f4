// libFuzzer target: bytes a client sends to the status endpoint, through
// parseHttpRequestHead. Beyond "no crash", it checks what the server
// relies on: a complete head has a method and a path starting with '/',
// and the head's end is decided by bytes already received, so any prefix
// that parses as complete parses the same as the whole input.
#include "runtime/operator/HttpRequest.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using arcomp::HttpRequestHead;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const HttpRequestHead whole = arcomp::parseHttpRequestHead(bytes);
    if (whole.state == HttpRequestHead::Complete &&
        (whole.method.empty() || whole.path.empty() || whole.path[0] != '/'))
        std::abort();
    if (whole.state == HttpRequestHead::Bad && whole.error.empty()) std::abort();
    if (size == 0) return 0;
    const HttpRequestHead prefix = arcomp::parseHttpRequestHead(bytes.substr(0, data[0] % size));
    if (prefix.state == HttpRequestHead::Complete &&
        (whole.state != HttpRequestHead::Complete || prefix.method != whole.method || prefix.path != whole.path ||
         prefix.authorization != whole.authorization))
        std::abort();
    return 0;
}
