#pragma once
// Who may read the status endpoint. On loopback, anyone on the machine (as
// Prometheus on the same box expects). Bound beyond loopback, only clients
// that send `Authorization: Bearer <token>`, the token read from a file the
// config names, so that it never sits in the config itself.
//
//   if (!isLoopbackAddress(bind) && tokenFile.empty()) refuse();
//   const std::string token = readBearerToken(tokenFile);        // throws BadInput
//   if (!bearerTokenMatches(request.authorization, token)) reply(401);

#include <filesystem>
#include <string>
#include <string_view>

namespace arcomp {

// An IPv4 address in 127.0.0.0/8.
bool isLoopbackAddress(const std::string& ipv4);

// The file's first line without surrounding whitespace. Throws BadInput
// naming the file when it cannot be read, is empty, or is shorter than
// kMinBearerTokenLength (guessable).
std::string readBearerToken(const std::filesystem::path& file);
// The first line of a secret's file, trimmed, `minLength` to `maxLength`
// printable ASCII characters; `what` names it in the errors ("status
// token", "SRT passphrase"). Throws BadInput naming the file.
std::string readSecretLine(const std::filesystem::path& file, const std::string& what, std::size_t minLength,
                           std::size_t maxLength);
constexpr std::size_t kMinBearerTokenLength = 16;

// True when an Authorization header's value is "Bearer <token>" (the scheme
// in any case). The comparison takes the same time wherever the first
// differing byte is, so response times do not reveal the token a byte at a
// time.
bool bearerTokenMatches(std::string_view authorization, std::string_view token);

}  // namespace arcomp
