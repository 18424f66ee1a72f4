#include "runtime/operator/HttpRequest.hpp"

#include <algorithm>
#include <cctype>

namespace arcomp {
namespace {

// RFC 9110's tchar: what a method or a header name may be made of.
bool isTokenChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

bool isToken(std::string_view s) { return !s.empty() && std::all_of(s.begin(), s.end(), isTokenChar); }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

HttpRequestHead bad(std::string error) {
    HttpRequestHead head;
    head.state = HttpRequestHead::Bad;
    head.error = std::move(error);
    return head;
}

// One line of the head without its line ending; RFC 9112 lets a server
// accept a bare LF as well as CRLF.
std::string_view takeLine(std::string_view& rest) {
    const std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
}

}  // namespace

HttpRequestHead parseHttpRequestHead(std::string_view received) {
    // The head ends at the first empty line.
    std::size_t end = std::string_view::npos;
    for (std::size_t i = received.find('\n'); i != std::string_view::npos; i = received.find('\n', i + 1)) {
        const std::size_t next = i + 1;
        if (next < received.size() && received[next] == '\n') {
            end = next + 1;
            break;
        }
        if (next + 1 < received.size() && received[next] == '\r' && received[next + 1] == '\n') {
            end = next + 2;
            break;
        }
    }
    if (end == std::string_view::npos || end > kMaxHttpHeadBytes) {
        HttpRequestHead head;
        if (received.size() > kMaxHttpHeadBytes) head.state = HttpRequestHead::TooLarge;
        return head;
    }
    std::string_view rest = received.substr(0, end);

    const std::string_view requestLine = takeLine(rest);
    const std::size_t s1 = requestLine.find(' ');
    const std::size_t s2 = s1 == std::string_view::npos ? s1 : requestLine.find(' ', s1 + 1);
    if (s2 == std::string_view::npos) return bad("the request line is not `METHOD /path HTTP/1.1`");
    const std::string_view method = requestLine.substr(0, s1);
    const std::string_view target = requestLine.substr(s1 + 1, s2 - s1 - 1);
    const std::string_view version = requestLine.substr(s2 + 1);
    if (!isToken(method)) return bad("the method is not a token");
    if (target.empty() || target.front() != '/' || std::any_of(target.begin(), target.end(), [](char c) {
            return static_cast<unsigned char>(c) <= ' ' || c == 0x7f;
        }))
        return bad("the target is not a path starting with /");
    if (version != "HTTP/1.1" && version != "HTTP/1.0") return bad("the version is not HTTP/1.0 or HTTP/1.1");

    HttpRequestHead head;
    head.state = HttpRequestHead::Complete;
    head.method = method;
    head.path = target.substr(0, target.find('?'));
    bool sawAuthorization = false;
    for (std::string_view line = takeLine(rest); !line.empty(); line = takeLine(rest)) {
        const std::size_t colon = line.find(':');
        if (colon == std::string_view::npos || !isToken(line.substr(0, colon)))
            return bad("a header line is not `Name: value`");
        const std::string_view value = trimmed(line.substr(colon + 1));
        if (std::any_of(value.begin(), value.end(),
                        [](char c) { return (c >= 0 && c < ' ' && c != '\t') || c == 0x7f; }))
            return bad("a header value holds a control character");
        if (equalsIgnoringCase(line.substr(0, colon), "authorization")) {
            // Two credentials would leave it to chance which one is checked.
            if (sawAuthorization) return bad("more than one Authorization header");
            sawAuthorization = true;
            head.authorization = value;
        }
    }
    return head;
}

}  // namespace arcomp
