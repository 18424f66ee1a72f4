#include "runtime/config/GroupingConfig.hpp"

#include "runtime/config/YamlMap.hpp"

namespace arcomp {

void readGroupingConfig(YamlMap& root, GroupingConfig& out) {
    if (!root.has("grouping")) return;
    YamlMap g = root.map("grouping");
    out.enabled = true;
    g.boolean("enabled", out.enabled);
    GroupingParams& p = out.params;
    g.number("l0", p.l0, 1e-6, 1e9);
    g.number("alpha_p", p.alphaP, 0.0, 1e9);
    g.number("alpha_s", p.alphaS, 0.0, 1e9);
    g.number("alpha_c", p.alphaC, 0.0, 1e9);
    g.number("alpha_f", p.alphaF, 0.0, 1e9);
    g.number("omega_t", p.omegaT, 0.0, 1e3);
    g.number("omega_t_start", p.omegaStart, 1e-9, 1e3);
    g.number("omega_t_max", p.omegaMax, 1e-9, 1e3);
    g.number("omega_t_step", p.omegaStep, 1e-9, 1e3);
    if (p.omegaMax < p.omegaStart)
        g.report().add(g.mark(), "grouping: omega_t_max must not be below omega_t_start");
    else if ((double(p.omegaMax) - double(p.omegaStart)) / double(p.omegaStep) > 1e6)
        g.report().add(g.mark(), "grouping: omega_t_step too small: more than 1,000,000 steps");
    std::string proxy = "box";
    g.choice("proxy", proxy, {"box", "impostor"});
    out.proxy = proxy == "impostor" ? GroupingProxy::Impostor : GroupingProxy::Box;
    g.number("proxy_alpha", out.proxyAlpha, 0.0, 1.0);
    g.number("impostor_pixels_per_unit", out.impostorPixelsPerUnit, 1e-6, 1e3);
    g.boolean("objects", out.objects);
    std::string forest = "none";
    g.choice("forest", forest, {"none", "mixed", "green"});
    if (forest == "mixed") out.forest = ForestColouring::Mixed;
    if (forest == "green") out.forest = ForestColouring::Green;
    g.finish();
}

}  // namespace arcomp
