#include "runtime/config/EncodingConfig.hpp"

#include "runtime/config/YamlMap.hpp"

namespace arcomp {

void readEncoding(YamlMap& parent, const char* key, H264Settings& out) {
    YamlMap e = parent.map(key);
    e.integer("bitrate_kbps", out.bitrateKbps, 100, 200000);
    e.number("keyframe_seconds", out.keyframeSeconds, 0.1, 60.0);
    if (e.has("size")) {
        glm::ivec2 size{0, 0};
        e.vec2i("size", size, 16, 7680);
        if (size.x % 2 != 0 || size.y % 2 != 0)
            e.report().add(e.mark(), e.where() + ".size: expected even width and height (H.264's 4:2:0), got " +
                                         std::to_string(size.x) + "x" + std::to_string(size.y));
        out.size = {size.x, size.y};
    }
    e.text("encoder", out.encoder);
    if (out.encoder.empty()) e.report().add(e.mark(), e.where() + ".encoder: expected x264, auto or an element name");
    e.finish();
}

}  // namespace arcomp
