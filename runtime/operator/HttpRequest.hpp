#pragma once
// The head of one HTTP/1.x request, as the status endpoint reads it from
// bytes that may still be arriving. The endpoint answers GET only and
// closes after each reply, so it needs the method, the path and the
// Authorization header; everything else is checked for shape and skipped.
//
//   HttpRequestHead head = parseHttpRequestHead(received);
//   if (head.state == HttpRequestHead::Incomplete) return;   // wait for more
//   if (head.state == HttpRequestHead::Bad) reply(400, head.error);
//
// Pure (no sockets), so that it is unit-tested and fuzzed on its own.

#include <cstddef>
#include <string>
#include <string_view>

namespace arcomp {

struct HttpRequestHead {
    enum State { Incomplete, Complete, Bad, TooLarge };
    State state = Incomplete;
    std::string method;
    std::string path;           // the target without its query string
    std::string authorization;  // the header's value, empty when absent
    std::string error;          // why a Bad head is bad
};

// A head longer than this is refused (TooLarge) before it ends: a scraper's
// request is a few hundred bytes.
constexpr std::size_t kMaxHttpHeadBytes = 8192;

HttpRequestHead parseHttpRequestHead(std::string_view received);

}  // namespace arcomp
