#pragma once
// `output.streams`: the composite as live streams (video/streams/StreamSpec.hpp),
// each checked at its lines: the URL, the secrets' files, and that nothing
// listens beyond loopback without one.
//
//   output:
//     streams:
//       - name: obs
//         url: srt://192.168.1.20:9000
//         passphrase_file: srt.key
//         encoding: {bitrate_kbps: 6000, size: [1280, 720]}

#include "video/streams/StreamSpec.hpp"

#include <string>
#include <vector>

namespace arcomp {

class YamlMap;

struct StreamConfig {
    StreamSpec spec;
    std::string at;  // "station.yaml:12:10", the URL's place, for what only the machine can say (a port taken)
};

void readStreams(YamlMap& output, std::vector<StreamConfig>& out);

}  // namespace arcomp
