// libFuzzer target: a cue as show control sends it, through the decoders
// and on to the scene. The first byte picks the wire: even, an OSC datagram
// (decodeOscCue, liblo's deserialiser); odd, an MQTT JSON payload
// (decodeJsonCue). A cue that decodes is then done on a small world, with
// an object whose model has two clips and one that has none, as the station
// does (ObjectActions). Beyond "no crash": a refusal always says why, and
// a cue on a known object never fails for the name.
#include "graph/core/World.hpp"
#include "runtime/showcontrol/CueDecode.hpp"
#include "runtime/triggers/ObjectActions.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

arcomp::World makeWorld() {
    using namespace arcomp;
    World w;
    const NodeId sign = w.scene.addTransform(w.scene.root(), glm::mat4(1.0f), "sign");
    const NodeId walker = w.scene.addTransform(w.scene.root(), glm::mat4(1.0f), "walker");
    const NodeId leg = w.scene.addTransform(walker, glm::mat4(1.0f), "leg");
    AnimationChannel step{.target = 0,
                          .path = AnimationPath::Translation,
                          .interpolation = Interpolation::Linear,
                          .times = {0.0f, 1.0f},
                          .values = {glm::vec4(0.0f), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)}};
    const ModelAnimation walk{.clip = {.name = "walk", .channels = {step}}, .nodes = {{.node = leg, .rest = {}}}};
    ModelAnimation hop = walk;
    hop.clip.name = "hop";
    w.objects = {{"sign", sign}, {"walker", walker, {walk, hop}}};
    w.scene.update();
    return w;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::span<const std::uint8_t> wire(data + 1, size - 1);
    const arcomp::CueDecoded d = data[0] % 2 == 0
                                     ? arcomp::decodeOscCue(wire)
                                     : arcomp::decodeJsonCue({reinterpret_cast<const char*>(wire.data()), wire.size()});
    if (!d.cue) {
        if (d.error.empty()) std::abort();
        return 0;
    }
    if (d.cue->kind != arcomp::Cue::Kind::Action || d.cue->action.object.empty()) return 0;
    static arcomp::World world = makeWorld();
    static arcomp::ObjectActions objects;
    static double seconds = 0.0;
    const std::string why = objects.perform(world, d.cue->action, seconds += 0.04);
    objects.advance(world, seconds);
    const std::string& name = d.cue->action.object;
    if ((name == "sign" || name == "walker") && why.find("no object") != std::string::npos) std::abort();
    return 0;
}
