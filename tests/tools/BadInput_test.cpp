// Every error that means "the input cannot be used" is one BadInput to its
// catcher (arcomp's exit code 2 rests on that), and reads as documented.

#include "graph/core/BadInput.hpp"
#include "graph/io/ModelError.hpp"
#include "runtime/config/ConfigError.hpp"
#include "runtime/station/GazeSource.hpp"
#include "tools/cli/Command.hpp"
#include "video/pixels/VideoError.hpp"

#include <gtest/gtest.h>

#include <functional>

using namespace arcomp;

namespace {

// What a `catch (const BadInput&)` sees of what `fail` throws (sliced on
// purpose: the catcher knows nothing more).
BadInput caughtAsBadInput(const std::function<void()>& fail) {
    try {
        fail();
    } catch (const BadInput& e) {
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a BadInput: " << e.what();
    }
    return BadInput("", "", "nothing caught");
}

}  // namespace

TEST(BadInput, readsSourceWhereReasonAndLeavesOutEmptyParts) {
    EXPECT_STREQ(BadInput("clips/a.avi", "frame 287 of 795", "decoder returned no image").what(),
                 "clips/a.avi: frame 287 of 795: decoder returned no image");
    EXPECT_STREQ(BadInput("clips/a.avi", "", "cannot open").what(), "clips/a.avi: cannot open");
    EXPECT_STREQ(BadInput("", "", "--size: expected WxH").what(), "--size: expected WxH");
}

TEST(BadInput, modelErrorKeepsItsFileAndReadsAsBadInput) {
    const BadInput e = caughtAsBadInput([] { throw ModelError("m.gltf", "/accessors/3/bufferView", "out of range"); });
    EXPECT_EQ(e.source, "m.gltf");
    EXPECT_EQ(e.where, "/accessors/3/bufferView");
    EXPECT_EQ(e.reason, "out of range");
    EXPECT_STREQ(e.what(), "m.gltf: /accessors/3/bufferView: out of range");
    EXPECT_EQ(ModelError("m.obj", "line 4", "bad face").file, "m.obj");
}

TEST(BadInput, videoErrorReadsAsBadInput) {
    const BadInput e = caughtAsBadInput([] { throw VideoError("clips/a.avi", "frame 287 of 795", "no image"); });
    EXPECT_EQ(e.source, "clips/a.avi");
    EXPECT_EQ(e.where, "frame 287 of 795");
    EXPECT_EQ(e.reason, "no image");
    EXPECT_STREQ(e.what(), "clips/a.avi: frame 287 of 795: no image");
}

TEST(BadInput, configErrorReadsAsItsFirstIssueAndListsThemAll) {
    const BadInput e = caughtAsBadInput([] {
        throw ConfigError({{"station.yaml", 12, 5, "expected a number"}, {"station.yaml", 14, 3, "unknown key 'x'"}});
    });
    EXPECT_EQ(e.source, "station.yaml");
    EXPECT_EQ(e.where, "line 12, column 5");
    EXPECT_EQ(e.reason, "expected a number (and 1 more)");
    EXPECT_STREQ(e.what(),
                 "2 errors in config\n  station.yaml:12:5: expected a number\n  station.yaml:14:3: unknown key 'x'");

    const BadInput wholeFile = caughtAsBadInput([] { throw ConfigError({{"calib.yaml", 0, 0, "cannot be read"}}); });
    EXPECT_EQ(wholeFile.source, "calib.yaml");
    EXPECT_EQ(wholeFile.where, "");
    EXPECT_EQ(wholeFile.reason, "cannot be read");
    EXPECT_STREQ(wholeFile.what(), "1 error in config\n  calib.yaml: cannot be read");
}

TEST(BadInput, gazeTrackErrorReadsAsBadInputAndKeepsFileLineText) {
    const BadInput e = caughtAsBadInput([] { parseGazeTrackCsv("0,0,0,0,1,0,0\n1,0,0,0,0,0,0\n", "track.csv"); });
    EXPECT_EQ(e.source, "track.csv");
    EXPECT_EQ(e.where, "line 2");
    EXPECT_EQ(e.reason, "gaze direction has no length");
    EXPECT_STREQ(e.what(), "track.csv:2: gaze direction has no length");

    const BadInput missing = caughtAsBadInput([] { readGazeTrackCsv("/nonexistent/track.csv"); });
    EXPECT_EQ(missing.source, "/nonexistent/track.csv");
    EXPECT_EQ(missing.where, "");
    EXPECT_EQ(missing.reason, "cannot open");
}

TEST(BadInput, inputErrorIsItsMessageAlone) {
    const BadInput e = caughtAsBadInput([] { throw InputError("--size: expected WIDTHxHEIGHT, got 'big'"); });
    EXPECT_EQ(e.source, "");
    EXPECT_EQ(e.where, "");
    EXPECT_EQ(e.reason, "--size: expected WIDTHxHEIGHT, got 'big'");
    EXPECT_STREQ(e.what(), "--size: expected WIDTHxHEIGHT, got 'big'");

    const BadInput placed = caughtAsBadInput([] { throw InputError("station.yaml", "", "gaze: cannot open"); });
    EXPECT_STREQ(placed.what(), "station.yaml: gaze: cannot open");
}
