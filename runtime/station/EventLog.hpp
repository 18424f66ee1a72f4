#pragma once
// The station's events as a file other software reads line by line (JSON
// Lines, `output.events`): each person entering or leaving a zone, and
// each trigger firing and ending, on its frame and video time, so that two replays of one file write the same
// bytes. Each frame's lines are flushed before the next frame, so a crash
// or a power cut loses at most the frame in hand.
//
//   EventLog log("out/events.jsonl");
//   log.write(station.people(), &triggers);   // each new video frame
//   // {"frame":41,"seconds":1.64,"event":"enter","zone":"front","person":3}
//   // {"frame":41,"seconds":1.64,"event":"trigger","trigger":"sign","state":"fired","person":3}

#include "runtime/people/PeopleFrame.hpp"
#include "runtime/triggers/Triggers.hpp"

#include <filesystem>
#include <fstream>

namespace arcomp {

class EventLog {
public:
    // Starts the file anew; throws std::runtime_error naming it when it
    // cannot be written.
    explicit EventLog(const std::filesystem::path& file);

    // The frame's zone events, then its triggers' firings (`triggers`
    // after its update() for this frame; none: no trigger lines).
    void write(const PeopleFrame& frame, const Triggers* triggers = nullptr);
    std::uint64_t lines() const { return lines_; }

private:
    std::filesystem::path file_;
    std::ofstream out_;
    std::uint64_t lines_ = 0;
};

}  // namespace arcomp
