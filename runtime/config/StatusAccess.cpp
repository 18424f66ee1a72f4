#include "runtime/config/StatusAccess.hpp"

#include "graph/core/BadInput.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>
#include <fstream>

namespace arcomp {

bool isLoopbackAddress(const std::string& ipv4) {
    in_addr address{};
    return inet_pton(AF_INET, ipv4.c_str(), &address) == 1 && (ntohl(address.s_addr) >> 24) == 127;
}

std::string readSecretLine(const std::filesystem::path& file, const std::string& what, std::size_t minLength,
                           std::size_t maxLength) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw BadInput(file.string(), "", "cannot read the " + what + " file");
    std::string line;
    std::getline(in, line);
    const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
    line.erase(std::find_if_not(line.rbegin(), line.rend(), space).base(), line.end());
    line.erase(line.begin(), std::find_if_not(line.begin(), line.end(), space));
    if (line.empty())
        throw BadInput(file.string(), "line 1", "the " + what + " file is empty; expected it on its first line");
    if (line.size() < minLength || line.size() > maxLength)
        throw BadInput(file.string(), "line 1",
                       "the " + what + " is " + std::to_string(line.size()) + " characters; expected " +
                           (line.size() < minLength ? "at least " + std::to_string(minLength)
                                                    : "at most " + std::to_string(maxLength)) +
                           " (e.g. from `openssl rand -hex " +
                           std::to_string(std::min<std::size_t>(32, maxLength / 2)) + "`)");
    if (std::any_of(line.begin(), line.end(), [](unsigned char c) { return c < 0x21 || c > 0x7e; }))
        throw BadInput(file.string(), "line 1",
                       "the " + what + " holds a space or a non-ASCII character; expected printable ASCII");
    return line;
}

std::string readBearerToken(const std::filesystem::path& file) {
    return readSecretLine(file, "status token", kMinBearerTokenLength, 4096);
}

bool bearerTokenMatches(std::string_view authorization, std::string_view token) {
    constexpr std::string_view scheme = "bearer ";
    if (authorization.size() < scheme.size()) return false;
    for (std::size_t i = 0; i < scheme.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(authorization[i])) != scheme[i]) return false;
    std::string_view given = authorization.substr(scheme.size());
    while (!given.empty() && given.front() == ' ') given.remove_prefix(1);
    // Every byte of the token is compared, whatever the given length: the
    // time depends on the token's length only, which is no secret.
    unsigned difference = given.size() == token.size() ? 0u : 1u;
    for (std::size_t i = 0; i < token.size(); ++i)
        difference |=
            static_cast<unsigned char>(token[i]) ^ static_cast<unsigned char>(i < given.size() ? given[i] : 0);
    return difference == 0;
}

}  // namespace arcomp
