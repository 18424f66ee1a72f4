// Every bad input we can find, each in its own child process so that a
// crash is counted rather than fatal: the glTF-Validator corpus and broken
// station configs through loadSceneFile (what `arcomp inspect` and
// `arcomp check` run; forked, not exec'd, since starting the CLI 300 times
// costs minutes here), and damaged videos replayed through the whole station
// by the CLI (`arcomp replay`).
// Prints the table inputs tried / accepted / rejected cleanly / crashed;
// crashed must be 0.

#include "../support/ChildProcess.hpp"
#include "../support/TempDir.hpp"
#include "graph/core/BadInput.hpp"
#include "runtime/station/SceneFile.hpp"
#include "tests/support/BoxStation.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cstdio>
#include <fstream>

using namespace arcomp::test;
namespace fs = std::filesystem;

namespace {

struct Tally {
    int tried = 0, accepted = 0, rejected = 0, crashed = 0;
    std::vector<std::string> crashes;

    void count(const std::string& input, const ChildResult& r) {
        ++tried;
        if (r.crashed() || r.code > 2) {
            ++crashed;
            crashes.push_back(input + " (" +
                              (r.exited ? "exit " + std::to_string(r.code) : "signal " + std::to_string(r.signal)) +
                              "):\n" + r.output.substr(r.output.size() > 3000 ? r.output.size() - 3000 : 0));
        } else if (r.code == 0) {
            ++accepted;
        } else {
            ++rejected;
        }
    }
};

void print(const std::vector<std::pair<std::string, Tally>>& rows) {
    std::printf("\n%-34s %7s %9s %18s %8s\n", "bad-input tally", "tried", "accepted", "rejected cleanly", "crashed");
    Tally sum;
    for (const auto& [name, t] : rows) {
        std::printf("%-34s %7d %9d %18d %8d\n", name.c_str(), t.tried, t.accepted, t.rejected, t.crashed);
        sum.tried += t.tried, sum.accepted += t.accepted, sum.rejected += t.rejected, sum.crashed += t.crashed;
    }
    std::printf("%-34s %7d %9d %18d %8d\n\n", "total", sum.tried, sum.accepted, sum.rejected, sum.crashed);
}

std::string cli() { return ARCOMP_BINARY; }

// What `arcomp inspect` and `arcomp check` do with a file, with their exit codes.
ChildResult loadInChild(const fs::path& file) {
    return runForked([&file] {
        try {
            const arcomp::SceneFile scene = arcomp::loadSceneFile(file);
            // check refuses a config whose models are skipped; a model with warnings still loads
            return scene.warnings.empty() || file.extension() != ".yaml" ? 0 : 2;
        } catch (const arcomp::BadInput& e) {  // ModelError, ConfigError
            std::fprintf(stderr, "%s\n", e.what());
            return 2;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "unexpected: %s\n", e.what());
            return 3;  // counted as a crash: the station would not survive it
        }
    });
}

const char* const kStation = arcomp::test::kBoxStation;

// Configs broken in every way we could think of, each alone. Models they
// name sit beside them: ok.obj (fine), garbage.obj (binary junk).
std::vector<std::pair<std::string, std::string>> brokenConfigs() {
    std::string deep(20000, '[');
    std::string deepMap;
    for (int i = 0; i < 5000; ++i) deepMap += "{a: ";
    std::string manyObjects = "scene:\n  objects:\n";
    for (int i = 0; i < 2000; ++i) manyObjects += "    - {shape: box, position: [" + std::to_string(i) + ", 0, -4]}\n";
    return {
        {"empty", ""},
        {"only-a-comment", "# nothing\n"},
        {"unclosed-flow", "scene: {objects: [\n"},
        {"binary-junk", std::string("\x7f"
                                    "ELF\x02\x01\x01\0\0\0\xff\xfe",
                                    12)},
        {"top-level-list", "- a\n- b\n"},
        {"top-level-scalar", "42\n"},
        {"tab-indent", "scene:\n\tobjects: []\n"},
        {"duplicate-keys", "camera: {fovy_deg: 40}\ncamera: {fovy_deg: 50}\n"},
        {"unknown-key", "scenery: {}\n"},
        {"unknown-shape", "scene:\n  objects:\n    - shape: cone\n"},
        {"fovy-out-of-range", "camera: {fovy_deg: 500}\n"},
        {"nan-and-inf", "camera: {eye: [.nan, .inf, -.inf], target: [0, 0, -1]}\n"},
        {"string-for-number", "camera: {fovy_deg: wide}\n"},
        {"map-for-list", "scene: {objects: {shape: box}}\n"},
        {"short-vector", "camera: {eye: [1, 2]}\n"},
        {"huge-size", "camera: {size: [99999999, 99999999]}\n"},
        {"negative-radius", "scene:\n  objects:\n    - {shape: sphere, radius: -1}\n"},
        {"missing-model", "scene:\n  objects:\n    - model: nowhere.glb\n"},
        {"garbage-model", "scene:\n  objects:\n    - model: garbage.obj\n"},
        {"model-outside-folder", "scene:\n  objects:\n    - model: ../../../../../../etc/passwd\n"},
        {"video-without-path", "video: {source: file}\n"},
        {"video-unknown-source", "video: {source: webcam}\n"},
        {"matte-bad-method", "matte: {kind: background, background: {method: magic}}\n"},
        {"budget-bad", "budget: {target_ms: -5}\n"},
        {"grouping-bad", "grouping: {forest: 12}\n"},
        {"status-port-text", "operator: {status: {port: http}}\n"},
        {"alias-loop-ish", "a: &x [*x]\n"},
        {"anchors-fan-out", "a: &a [1,1,1,1,1,1,1,1]\nb: &b [*a,*a,*a,*a,*a,*a,*a,*a]\nc: &c "
                            "[*b,*b,*b,*b,*b,*b,*b,*b]\nd: [*c,*c,*c,*c]\n"},
        {"deep-flow-nesting", "scene: " + deep + "\n"},
        {"deep-map-nesting", "scene: " + deepMap + "\n"},
        {"invalid-utf8", "scene:\n  objects:\n    - name: \"\xc3\x28\xa0\xa1\"\n      shape: box\n"},
        {"long-string", "scene:\n  objects:\n    - {shape: box, name: " + std::string(1 << 20, 'x') + "}\n"},
        {"many-objects-ok", manyObjects},
    };
}

}  // namespace

TEST(BadInputTally, noInputCrashesTheCli) {
    std::vector<std::pair<std::string, Tally>> rows;
    std::vector<std::string> crashes;
    const auto collect = [&](const std::string& name, Tally t) {
        crashes.insert(crashes.end(), t.crashes.begin(), t.crashes.end());
        rows.emplace_back(name, std::move(t));
    };

    const fs::path corpus = sharedData() / "gltf/validator-corpus";
    if (fs::exists(corpus)) {
        Tally gltf;
        for (const auto& e : fs::recursive_directory_iterator(corpus)) {
            const auto ext = e.path().extension();
            if (ext == ".gltf" || ext == ".glb") gltf.count(e.path().string(), loadInChild(e.path()));
        }
        EXPECT_GT(gltf.tried, 200);
        collect("glTF-Validator corpus (load)", std::move(gltf));
    } else {
        std::printf("glTF corpus absent (%s): skipped\n", corpus.c_str());
    }

    TempDir dir;
    const fs::path station = dir.write("station.yaml", kStation);
    const std::string data = "/usr/share/doc/opencv-doc/examples/data/";
    if (fs::exists(data + "vtest.avi")) {
        Tally videos;
        std::vector<fs::path> damaged;
        if (fs::exists(data + "Megamind_bugy.avi")) damaged.push_back(data + "Megamind_bugy.avi");
        // Cut at the header, inside the first frames and a little later
        // (about 10 kB a frame): later cuts only add frames before the same
        // kind of end. Replays stop after 60 frames; Megamind_bugy's damage
        // further in is played whole by FileSource.megamindBugyPlaysWithoutCrashing.
        for (const std::uintmax_t cut : {0, 600, 5000, 60000, 250000, 500000}) {
            const fs::path copy = dir.path() / ("vtest-cut-" + std::to_string(cut) + ".avi");
            fs::copy_file(data + "vtest.avi", copy);
            fs::resize_file(copy, cut);
            damaged.push_back(copy);
        }
        {  // Noise over the middle of the first 60 frames' bytes, and a file of noise.
            const fs::path noisy = dir.path() / "vtest-noise-middle.avi";
            fs::copy_file(data + "vtest.avi", noisy);
            fs::resize_file(noisy, 500000);
            std::fstream f(noisy, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(300000);
            cv::RNG rng(3);
            for (int i = 0; i < 100000; ++i) f.put(static_cast<char>(rng.uniform(0, 256)));
            damaged.push_back(noisy);
            const fs::path junk = dir.path() / "noise.avi";
            std::ofstream j(junk, std::ios::binary);
            for (int i = 0; i < 200000; ++i) j.put(static_cast<char>(rng.uniform(0, 256)));
            damaged.push_back(junk);
        }
        for (const fs::path& v : damaged) {
            const fs::path out = dir.path() / ("out-" + v.stem().string());
            videos.count(v.string(), runChild({cli(), "replay", station.string(), "--video", v.string(), "--out",
                                               out.string(), "--frames", "60", "--log-level", "error"}));
        }
        collect("damaged videos (replay)", std::move(videos));
    } else {
        std::printf("opencv-doc videos absent: skipped\n");
    }

    dir.write("ok.obj", "v 0 0 -4\nv 1 0 -4\nv 0 1 -4\nf 1 2 3\n");
    dir.write("garbage.obj", std::string("\0\x01\x02garbage\xff", 11));
    Tally configs;
    for (const auto& [name, text] : brokenConfigs()) {
        const fs::path file = dir.write(name + ".yaml", text);
        configs.count(name, loadInChild(file));
    }
    collect("broken configs (load)", std::move(configs));

    print(rows);
    for (const std::string& c : crashes) ADD_FAILURE() << "crashed: " << c;
}
