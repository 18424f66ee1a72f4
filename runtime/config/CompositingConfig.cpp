#include "runtime/config/CompositingConfig.hpp"

#include "runtime/config/EncodingConfig.hpp"
#include "runtime/config/YamlMap.hpp"

namespace arcomp {

namespace {

void readVideo(YamlMap& root, CompositingConfig& out) {
    if (!root.has("video")) return;
    YamlMap v = root.map("video");
    SourceSpec spec;
    std::string kind = "file";
    v.choice("source", kind, {"file", "pattern", "v4l2", "libcamera"});
    spec.kind = kind == "file"      ? SourceKind::File
                : kind == "pattern" ? SourceKind::Pattern
                : kind == "v4l2"    ? SourceKind::V4l2
                                    : SourceKind::Libcamera;
    if (spec.kind == SourceKind::File) {
        // Not required to exist: a missing file falls back (see `fallback`).
        std::filesystem::path p;
        v.path("path", p, false, Required::Yes);
        spec.path = p.string();
    } else {
        v.text("path", spec.path);
    }
    glm::ivec2 size{spec.width, spec.height};
    v.vec2i("size", size, 16, 16384);
    spec.width = size.x;
    spec.height = size.y;
    v.number("fps", spec.fps, 1.0, 1000.0);
    v.boolean("loop", spec.loop);
    std::string fallback = "none";
    v.choice("fallback", fallback, {"none", "pattern", "file", "image", "last_good"});
    spec.fallback.kind = fallback == "pattern"     ? FallbackKind::Pattern
                         : fallback == "file"      ? FallbackKind::File
                         : fallback == "image"     ? FallbackKind::Image
                         : fallback == "last_good" ? FallbackKind::LastGoodFrame
                                                   : FallbackKind::None;
    if (spec.fallback.kind == FallbackKind::File || spec.fallback.kind == FallbackKind::Image) {
        std::filesystem::path p;
        v.path("fallback_path", p, true, Required::Yes);
        spec.fallback.path = p.string();
    }
    v.finish();
    out.video = spec;
}

void readConsensus(YamlMap& b, ConsensusSpec& c) {
    b.integer("samples", c.samples, 2, 64);
    b.integer("matches", c.matches, 1, 64);
    if (c.matches > c.samples) b.report().add(b.mark(), "matte.background.matches: must not exceed samples");
    b.number("colour_radius", c.colourRadius, 1.0, 765.0);
    b.number("shadow_darkest", c.shadowDarkest, 0.01, 0.99);
    b.number("shadow_lightest", c.shadowLightest, 0.02, 1.0);
    if (c.shadowDarkest >= c.shadowLightest)
        b.report().add(b.mark(), "matte.background.shadow_darkest: must be below shadow_lightest");
    b.number("shadow_chroma", c.shadowChroma, 0.0, 0.99);
    b.integer("update_odds", c.updateOdds, 1, 1000);
    b.number("absorb_s", c.absorbSeconds, 0.1, 86400.0);
    b.number("warmup_s", c.warmupSeconds, 0.0, 600.0);
    b.number("fps", c.fps, 1.0, 1000.0);
    b.number("light_change_fraction", c.lightChangeFraction, 0.01, 1.0);
    b.number("min_blob_area", c.minBlobArea, 0.0, 0.5);
    b.number("max_hole_area", c.maxHoleArea, 0.0, 0.5);
    b.integer("gap_px", c.gapPx, 0, 99);
    b.integer("edge_radius_px", c.edgeRadiusPx, 0, 99);
}

void readMatte(YamlMap& root, MatteSpec& out, const std::optional<SourceSpec>& video) {
    YamlMap m = root.map("matte");
    std::string kind = "none";
    m.choice("kind", kind, {"none", "chroma", "background", "masks"});
    out.kind = kind == "chroma"       ? MatteKind::Chroma
               : kind == "background" ? MatteKind::Background
               : kind == "masks"      ? MatteKind::Masks
                                      : MatteKind::None;
    if (out.kind == MatteKind::Masks || m.has("masks")) {
        YamlMap k = m.map("masks", out.kind == MatteKind::Masks ? Required::Yes : Required::No);
        k.path("folder", out.masks.folder, true, Required::Yes);
        k.finish();
    }
    if (m.has("chroma")) {
        YamlMap c = m.map("chroma");
        glm::vec3 rgb(out.chroma.keyBgr[2], out.chroma.keyBgr[1], out.chroma.keyBgr[0]);
        c.vec3("key_rgb", rgb);
        if (glm::any(glm::lessThan(rgb, glm::vec3(0.0f))) || glm::any(glm::greaterThan(rgb, glm::vec3(255.0f))))
            c.report().add(c.mark(), "matte.chroma.key_rgb: components must lie in 0..255");
        out.chroma.keyBgr = cv::Vec3b(cv::saturate_cast<uchar>(rgb.b), cv::saturate_cast<uchar>(rgb.g),
                                      cv::saturate_cast<uchar>(rgb.r));
        c.number("similarity", out.chroma.similarity, 0.0, 1.0);
        c.number("smoothness", out.chroma.smoothness, 0.0, 1.0);
        c.number("spill", out.chroma.spill, 0.0, 1.0);
        c.finish();
    }
    // The consensus model's times are in seconds; the video's rate turns them into frames.
    if (video) out.background.consensus.fps = video->fps;
    if (m.has("background")) {
        YamlMap b = m.map("background");
        BackgroundSpec& s = out.background;
        std::string method = "consensus";
        b.choice("method", method, {"consensus", "mog2", "knn", "cnt", "clean_plate"});
        s.method = method == "mog2"          ? BackgroundMethod::Mog2
                   : method == "knn"         ? BackgroundMethod::Knn
                   : method == "cnt"         ? BackgroundMethod::Cnt
                   : method == "clean_plate" ? BackgroundMethod::CleanPlate
                                             : BackgroundMethod::Consensus;
        readConsensus(b, s.consensus);
        std::filesystem::path plate;
        b.path("clean_plate", plate, true);
        s.cleanPlate = plate.string();
        b.number("threshold", s.threshold, 1e-3, 1e4);
        b.number("learning_rate", s.learningRate, -1.0, 1.0);
        b.integer("history", s.history, 1, 100000);
        b.number("scale", s.scale, 0.1, 1.0);
        b.integer("open_px", s.openPx, 0, 99);
        b.integer("close_px", s.closePx, 0, 99);
        b.integer("feather_px", s.featherPx, 0, 99);
        b.number("temporal", s.temporal, 0.0, 0.95);
        b.finish();
    }
    m.finish();
}

void readCompositor(YamlMap& root, CompositorConfig& out) {
    YamlMap c = root.map("compositor");
    c.number("person_plane_m", out.personPlaneMetres, 1e-3, 1e5);
    std::string personDepth = "feet";
    c.choice("person_depth", personDepth, {"feet", "plane"});
    out.personDepthFromFeet = personDepth == "feet";
    c.number("holdout_region_m", out.holdoutRegionMetres, 1e-3, 1e3);
    std::string holdout = "silhouette";
    c.choice("holdout", holdout, {"silhouette", "full"});
    out.holdout = holdout == "full" ? HoldoutMesh::Full : HoldoutMesh::Silhouette;
    std::string cache;
    c.text("bake_cache", cache);
    if (cache == "none")
        out.bakeCache = "none";
    else if (!cache.empty())
        c.path("bake_cache", out.bakeCache, false);
    std::string backdrop = "video";
    c.choice("backdrop", backdrop, {"video", "color"});
    out.backdropVideo = backdrop == "video";
    c.vec4("backdrop_color", out.backdropColor);
    if (c.has("shadow")) {
        YamlMap sh = c.map("shadow");
        bool enabled = true;
        if (sh.has("enabled")) {
            sh.boolean("enabled", enabled);
            out.shadow.enabled = enabled;
        }
        glm::vec3 light = out.shadow.light;
        sh.vec3("light", light);
        // Below about 6 degrees the shadows would reach to the horizon.
        if (const float length = glm::length(light); !(length > 0.0f) || !(light.y / length > 0.1f))
            sh.report().add(sh.mark(), sh.where() + ".light: expected a direction towards a light above the floor, "
                                                    "[x, y, z] with y well above 0 (e.g. [-0.4, 0.8, 0.45])");
        else
            out.shadow.light = light / length;
        sh.number("strength", out.shadow.strength, 0.0, 1.0);
        sh.finish();
    }
    c.finish();
}

void readOutput(YamlMap& root, OutputConfig& out) {
    YamlMap o = root.map("output");
    o.path("png_dir", out.pngDir, false);
    o.path("video_file", out.videoFile, false);
    if (o.has("video_file")) out.videoFileAt = o.report().place(o.take("video_file").Mark());
    o.text("video_fourcc", out.videoFourcc);
    if (out.videoFourcc.size() != 4) o.report().add(o.mark(), "output.video_fourcc: expected 4 characters, e.g. MJPG");
    readEncoding(o, "encoding", out.videoEncoding);
    readStreams(o, out.streams);
    o.path("matte_dir", out.matteDir, false);
    o.path("events", out.events, false);
    o.boolean("window", out.window);
    o.finish();
}

}  // namespace

void readCompositingConfig(YamlMap& root, CompositingConfig& out) {
    readVideo(root, out);
    readMatte(root, out.matte, out.video);
    readCompositor(root, out.compositor);
    readOutput(root, out.output);
}

}  // namespace arcomp
