#include "runtime/station/EventLog.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace arcomp {

EventLog::EventLog(const std::filesystem::path& file) : file_(file) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    out_.open(file, std::ios::binary | std::ios::trunc);
    if (!out_) throw std::runtime_error("output.events: cannot write " + file.string());
}

void EventLog::write(const PeopleFrame& frame, const Triggers* triggers) {
    const std::size_t before = lines_;
    for (const ZoneEvent& e : frame.zoneEvents) {
        // Ordered keys, so that the lines read the same in every replay and to a person.
        nlohmann::ordered_json line{{"frame", frame.frame},
                                    {"seconds", frame.seconds},
                                    {"event", kindName(e.kind)},
                                    {"zone", frame.zones.at(static_cast<std::size_t>(e.zone)).name},
                                    {"person", e.person}};
        out_ << line.dump() << '\n';
        ++lines_;
    }
    if (triggers)
        for (const TriggerFiring& f : triggers->last().firings) {
            nlohmann::ordered_json line{{"frame", frame.frame},
                                        {"seconds", frame.seconds},
                                        {"event", "trigger"},
                                        {"trigger", triggers->triggers().at(static_cast<std::size_t>(f.trigger)).name},
                                        {"state", f.ended ? "ended" : "fired"}};
            if (f.person >= 0) line["person"] = f.person;
            out_ << line.dump() << '\n';
            ++lines_;
        }
    if (lines_ == before) return;
    out_.flush();
    if (!out_) throw std::runtime_error("output.events: cannot write " + file_.string());
}

}  // namespace arcomp
