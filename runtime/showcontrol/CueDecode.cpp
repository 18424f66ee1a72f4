#include "runtime/showcontrol/CueDecode.hpp"

#include <lo/lo_lowlevel.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <vector>

namespace arcomp {

CueDecoded decodeOscCue(std::span<const std::uint8_t> datagram) {
    // liblo reads from a writable buffer; the datagram stays as it came.
    std::vector<std::uint8_t> bytes(datagram.begin(), datagram.end());
    const auto size = static_cast<ssize_t>(bytes.size());
    const char* path = bytes.empty() ? nullptr : lo_get_path(bytes.data(), size);
    if (!path) return {std::nullopt, "not an OSC packet: no address string at its start"};
    const std::string_view address(path);
    if (address == "#bundle")
        return {std::nullopt, "an OSC bundle; cues are taken as single messages (/arcomp/cue/<verb>)"};
    if (!address.starts_with(kOscCuePrefix))
        return {std::nullopt, "address '" + std::string(address).substr(0, 64) + "' is not a cue; expected " +
                                  std::string(kOscCuePrefix) + "<verb>"};
    int result = 0;
    const std::unique_ptr<std::remove_pointer_t<lo_message>, decltype(&lo_message_free)> message(
        lo_message_deserialise(bytes.data(), bytes.size(), &result), &lo_message_free);
    if (!message) return {std::nullopt, "a malformed OSC message (liblo error " + std::to_string(result) + ")"};
    const int argc = lo_message_get_argc(message.get());
    const char* types = lo_message_get_types(message.get());
    lo_arg** argv = lo_message_get_argv(message.get());
    std::vector<std::string> args;
    for (int i = 0; i < argc; ++i) {
        if (types[i] != LO_STRING && types[i] != LO_SYMBOL)
            return {std::nullopt, std::string(address) + ": argument " + std::to_string(i + 1) + " has type '" +
                                      types[i] + "'; cues take strings (s)"};
        // A string argument is the lo_arg's first byte on; liblo leaves the
        // arguments at 4-byte offsets, so the union itself is not accessed.
        args.emplace_back(reinterpret_cast<const char*>(argv[i]));
    }
    return cueFromWords(address.substr(kOscCuePrefix.size()), args);
}

CueDecoded decodeJsonCue(std::string_view payload) {
    const nlohmann::json j = nlohmann::json::parse(payload, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return {std::nullopt, R"(not a JSON object; expected {"cue": "play", "object": "dino"})"};
    std::string verb;
    std::vector<std::string> args;
    for (const auto& [key, value] : j.items()) {
        if (key != "cue" && key != "object" && key != "animation")
            return {std::nullopt, "unknown key '" + key + "'; a cue has cue, object and animation"};
        if (!value.is_string()) return {std::nullopt, "'" + key + "' is not a string"};
    }
    if (!j.contains("cue")) return {std::nullopt, R"(no "cue"; expected {"cue": "play", "object": "dino"})"};
    verb = j["cue"].get<std::string>();
    if (j.contains("object")) args.push_back(j["object"].get<std::string>());
    if (j.contains("animation")) {
        if (args.empty()) return {std::nullopt, R"("animation" without "object")"};
        args.push_back(j["animation"].get<std::string>());
    }
    return cueFromWords(verb, args);
}

}  // namespace arcomp
