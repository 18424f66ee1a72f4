// The event log: one JSON line an event, with its frame, video time, kind,
// zone and person, flushed each frame; a file that cannot be written is an
// error naming it.

#include "runtime/station/EventLog.hpp"

#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace arcomp;
using arcomp::test::TempDir;

TEST(EventLog, writesOneLineAnEventReadableWhileTheStationRuns) {
    TempDir dir;
    EventLog log(dir.path() / "logs/events.jsonl");
    PeopleFrame f;
    f.frame = 41;
    f.seconds = 1.64;
    f.zones = {{.name = "front", .people = 1, .entries = 1}, {.name = "dino", .people = 0, .entries = 1}};
    f.zoneEvents = {{.kind = ZoneEvent::Kind::Enter, .zone = 0, .person = 3},
                    {.kind = ZoneEvent::Kind::Leave, .zone = 1, .person = 3}};
    log.write(f);
    f.zoneEvents.clear();
    log.write(f);  // nothing happened: nothing written
    EXPECT_EQ(log.lines(), 2u);
    std::ifstream in(dir.path() / "logs/events.jsonl");  // before the log is closed: flushed
    std::string a, b, c;
    std::getline(in, a);
    std::getline(in, b);
    EXPECT_EQ(a, R"({"frame":41,"seconds":1.64,"event":"enter","zone":"front","person":3})");
    EXPECT_EQ(b, R"({"frame":41,"seconds":1.64,"event":"leave","zone":"dino","person":3})");
    EXPECT_FALSE(std::getline(in, c));
}

TEST(EventLog, aFileThatCannotBeWrittenIsAnErrorNamingIt) {
    TempDir dir;
    dir.write("taken", "a file where the folder would be");
    try {
        EventLog log(dir.path() / "taken/events.jsonl");
        ADD_FAILURE() << "opened a log under a file";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("taken"), std::string::npos) << e.what();
    }
}
