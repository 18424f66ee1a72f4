#include "runtime/triggers/Cue.hpp"

namespace arcomp {

CueDecoded cueFromWords(std::string_view verb, const std::vector<std::string>& args) {
    const auto refuse = [&](const std::string& why) {
        return CueDecoded{std::nullopt, std::string(verb) + ": " + why};
    };
    if (verb == "reload" || verb == "snapshot") {
        if (!args.empty()) return refuse("takes no arguments, got " + std::to_string(args.size()));
        Cue c;
        if (verb == "reload")
            c.kind = Cue::Kind::Reload;
        else
            c.action.kind = ActionKind::Snapshot;
        return {c};
    }
    const std::optional<ActionKind> kind = actionKind(verb);
    const bool onObject = kind && (*kind == ActionKind::Play || *kind == ActionKind::Pause ||
                                   *kind == ActionKind::Stop || *kind == ActionKind::Show || *kind == ActionKind::Hide);
    if (!onObject)
        return {std::nullopt,
                "unknown cue '" + std::string(verb) + "'; expected play, pause, stop, show, hide, snapshot or reload"};
    const std::size_t most = *kind == ActionKind::Play ? 2 : 1;
    if (args.empty() || args.size() > most || args[0].empty())
        return refuse(most == 2 ? "expected an object's name and, if wanted, an animation's"
                                : "expected an object's name");
    Cue c;
    c.action.kind = *kind;
    c.action.object = args[0];
    if (args.size() == 2) c.action.animation = args[1];
    return {c};
}

}  // namespace arcomp
