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
    readEncoding(s, "encoding", spec.encoding);
    const bool serves = spec.listener || spec.protocol == StreamProtocol::Rtsp;
    if (serves && !spec.host.empty() && !isLoopbackHost(spec.host) && passphraseFile.empty() &&
        spec.protocol == StreamProtocol::Srt)
        s.report().add(s.mark(), s.where() + ".url: a listener on " + spec.host +
                                     " is beyond loopback, so it needs passphrase_file: a file holding the "
                                     "passphrase receivers must give (10 to 79 characters)");
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
