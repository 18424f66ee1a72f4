#include "runtime/config/StreamConfig.hpp"

#include "runtime/config/EncodingConfig.hpp"
#include "runtime/config/StatusAccess.hpp"
#include "runtime/config/YamlMap.hpp"

#include <set>
#include <stdexcept>

namespace arcomp {

namespace {

// SRT's own bounds on a passphrase.
constexpr std::size_t kSrtPassphraseMin = 10, kSrtPassphraseMax = 79;
// RTSP's user:password; a password shorter than this is guessed.
constexpr std::size_t kRtspPasswordMin = 10;

// "user:password" from the credentials file's first line; throws BadInput.
void readCredentials(const std::filesystem::path& file, StreamSpec& spec) {
    const std::string line = readSecretLine(file, "RTSP credentials", 3, 200);
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos || colon == 0) throw BadInput(file.string(), "line 1", "expected user:password");
    if (line.size() - colon - 1 < kRtspPasswordMin)
        throw BadInput(file.string(), "line 1",
                       "the password is " + std::to_string(line.size() - colon - 1) +
                           " characters; expected at least " + std::to_string(kRtspPasswordMin));
    spec.user = line.substr(0, colon);
    spec.password = line.substr(colon + 1);
}

void readOne(YamlMap& s, StreamConfig& out) {
    std::string name, url;
    s.text("name", name, Required::Yes);
    s.text("url", url, Required::Yes);
    if (s.has("url")) {
        out.at = s.report().place(s.take("url").Mark());
        try {
            out.spec = parseStreamUrl(url);
        } catch (const std::invalid_argument& e) {
            s.report().add(s.take("url").Mark(), s.where() + ".url: " + e.what());
        }
    }
    out.spec.name = name;
    StreamSpec& spec = out.spec;
    s.integer("latency_ms", spec.latencyMs, 20, 8000);
    s.integer("queue_frames", spec.queueFrames, 1, 60);
    std::filesystem::path passphraseFile;
    s.path("passphrase_file", passphraseFile, true);
    if (!passphraseFile.empty() && std::filesystem::exists(passphraseFile)) {
        try {
            spec.passphrase = readSecretLine(passphraseFile, "SRT passphrase", kSrtPassphraseMin, kSrtPassphraseMax);
        } catch (const BadInput& e) {
            s.report().add(s.mark(), s.where() + ".passphrase_file: " + e.what());
        }
    }
    if (!passphraseFile.empty() && spec.protocol != StreamProtocol::Srt)
        s.report().add(s.mark(), s.where() + ".passphrase_file: only for srt:// (RTSP takes credentials_file)");
    std::filesystem::path credentialsFile;
    s.path("credentials_file", credentialsFile, true);
    if (!credentialsFile.empty() && std::filesystem::exists(credentialsFile)) {
        try {
            readCredentials(credentialsFile, spec);
        } catch (const BadInput& e) {
            s.report().add(s.mark(), s.where() + ".credentials_file: " + e.what());
        }
    }
    if (!credentialsFile.empty() && spec.protocol != StreamProtocol::Rtsp)
        s.report().add(s.mark(), s.where() + ".credentials_file: only for rtsp:// (SRT takes passphrase_file)");
    readEncoding(s, "encoding", spec.encoding);
    const bool beyondLoopback = !spec.host.empty() && !isLoopbackHost(spec.host);
    if (beyondLoopback && spec.listener && passphraseFile.empty())
        s.report().add(s.mark(), s.where() + ".url: a listener on " + spec.host +
                                     " is beyond loopback, so it needs passphrase_file: a file holding the "
                                     "passphrase receivers must give (10 to 79 characters)");
    if (beyondLoopback && spec.protocol == StreamProtocol::Rtsp && credentialsFile.empty())
        s.report().add(s.mark(), s.where() + ".url: an RTSP server on " + spec.host +
                                     " is beyond loopback, so it needs credentials_file: a file holding the "
                                     "user:password players must give");
    s.finish();
}

}  // namespace

void readStreams(YamlMap& output, std::vector<StreamConfig>& out) {
    std::set<std::string> names;
    for (YamlMap& s : output.list("streams")) {
        StreamConfig stream;
        readOne(s, stream);
        if (!stream.spec.name.empty() && !names.insert(stream.spec.name).second)
            s.report().add(s.mark(), s.where() + ".name: " + stream.spec.name + " is used by another stream");
        if (s.has("name") && stream.spec.name.empty())
            s.report().add(s.mark(), s.where() + ".name: expected a name (it labels the stream in /status)");
        out.push_back(std::move(stream));
    }
}

}  // namespace arcomp
