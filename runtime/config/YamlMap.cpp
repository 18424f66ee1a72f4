#include "runtime/config/YamlMap.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace arcomp {

namespace fs = std::filesystem;

namespace {
// An absent node; YAML::Node{} would be a defined null.
YAML::Node absent() { return YAML::Node(YAML::NodeType::Undefined); }
}  // namespace

void ConfigReport::add(const YAML::Mark& mark, std::string message) {
    issues_.push_back(
        {file_.string(), mark.line < 0 ? 0 : mark.line + 1, mark.column < 0 ? 0 : mark.column + 1, std::move(message)});
}

std::string ConfigReport::place(const YAML::Mark& mark) const {
    return file_.string() + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

void ConfigReport::addFileLevel(std::string message) { issues_.push_back({file_.string(), 0, 0, std::move(message)}); }

void ConfigReport::throwIfAny() const {
    if (!issues_.empty()) throw ConfigError(issues_);
}

YAML::Node loadYamlFile(ConfigReport& report) {
    std::ifstream in(report.file());
    if (!in) {
        report.addFileLevel("cannot be read (missing or no permission)");
        return absent();
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
        YAML::Node root = YAML::Load(text.str());
        if (!root.IsMap()) {
            report.add(root.Mark(), "expected a YAML mapping (key: value lines) at the top level");
            return absent();
        }
        return root;
    } catch (const YAML::Exception& e) {
        report.add(e.mark, "YAML syntax: " + e.msg);
        return absent();
    }
}

YamlMap::YamlMap(YAML::Node node, std::string path, ConfigReport& report)
    : node_(std::move(node)), path_(std::move(path)), report_(report), mark_(node_.Mark()) {
    if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
        report_.add(mark_, (path_.empty() ? std::string("the file") : path_) + ": expected a mapping of keys");
        valid_ = false;
    }
    // An absent section was reported where it was asked for; its own
    // required keys are not reported again.
    if (!node_.IsDefined() || node_.IsNull()) valid_ = false;
}

bool YamlMap::has(const char* key) const {
    const YAML::Node& map = node_;
    return valid_ && node_.IsMap() && map[key].IsDefined() && !map[key].IsNull();
}

YAML::Node YamlMap::child(const char* key, Required r) {
    read_.insert(key);
    if (!valid_ || !node_.IsMap()) {
        if (r == Required::Yes && valid_) report_.add(mark_, keyPath(key) + ": required key is missing");
        return absent();
    }
    const YAML::Node& map = node_;  // the const lookup never inserts the key
    YAML::Node n = map[key];
    if (!n.IsDefined() || n.IsNull()) {
        if (r == Required::Yes) report_.add(mark_, keyPath(key) + ": required key is missing");
        return absent();
    }
    return n;
}

YAML::Node YamlMap::take(const char* key) { return child(key, Required::No); }

void YamlMap::number(const char* key, double& out, double min, double max, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    double v = 0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v)) {
        report_.add(n.Mark(), keyPath(key) + ": expected a number, got '" +
                                  (n.IsScalar() ? n.Scalar() : "a " + std::string(n.IsMap() ? "mapping" : "list")) +
                                  "'");
        return;
    }
    if (v < min || v > max) {
        std::ostringstream s;
        s << keyPath(key) << ": " << v << " is out of range; expected " << min << " to " << max;
        report_.add(n.Mark(), s.str());
        return;
    }
    out = v;
}

void YamlMap::number(const char* key, float& out, double min, double max, Required r) {
    double v = out;
    number(key, v, min, max, r);
    out = static_cast<float>(v);
}

void YamlMap::integer(const char* key, int& out, int min, int max, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    int v = 0;
    if (!n.IsScalar() || !YAML::convert<int>::decode(n, v)) {
        report_.add(n.Mark(),
                    keyPath(key) + ": expected a whole number, got '" + (n.IsScalar() ? n.Scalar() : "") + "'");
        return;
    }
    if (v < min || v > max) {
        report_.add(n.Mark(), keyPath(key) + ": " + std::to_string(v) + " is out of range; expected " +
                                  std::to_string(min) + " to " + std::to_string(max));
        return;
    }
    out = v;
}

void YamlMap::boolean(const char* key, bool& out, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    bool v = false;
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) {
        report_.add(n.Mark(), keyPath(key) + ": expected true or false");
        return;
    }
    out = v;
}

void YamlMap::text(const char* key, std::string& out, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    if (!n.IsScalar()) {
        report_.add(n.Mark(), keyPath(key) + ": expected a text value");
        return;
    }
    out = n.Scalar();
}

void YamlMap::choice(const char* key, std::string& out, const std::vector<std::string>& choices, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    std::string list;
    for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
    if (!n.IsScalar() || std::find(choices.begin(), choices.end(), n.Scalar()) == choices.end()) {
        report_.add(n.Mark(), keyPath(key) + ": '" + (n.IsScalar() ? n.Scalar() : "") + "' is not one of " + list);
        return;
    }
    out = n.Scalar();
}

void YamlMap::expectedFloats(const YAML::Node& n, const char* key, std::size_t count, float* out) {
    std::vector<float> values;
    bool ok = n.IsSequence() && n.size() == count;
    for (std::size_t i = 0; ok && i < count; ++i) {
        double v = 0;
        ok = n[i].IsScalar() && YAML::convert<double>::decode(n[i], v) && std::isfinite(v);
        values.push_back(static_cast<float>(v));
    }
    if (!ok) {
        report_.add(n.Mark(), keyPath(key) + ": expected a list of " + std::to_string(count) + " numbers");
        return;
    }
    std::copy(values.begin(), values.end(), out);
}

void YamlMap::vec2i(const char* key, glm::ivec2& out, int min, int max, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    glm::vec2 v;
    const std::size_t before = report_.issues().size();
    expectedFloats(n, key, 2, &v.x);
    if (report_.issues().size() != before) return;
    if (v.x != std::floor(v.x) || v.y != std::floor(v.y) || v.x < min || v.y < min || v.x > max || v.y > max) {
        report_.add(n.Mark(), keyPath(key) + ": expected two whole numbers from " + std::to_string(min) + " to " +
                                  std::to_string(max));
        return;
    }
    out = glm::ivec2(v);
}

void YamlMap::vec3(const char* key, glm::vec3& out, Required r) {
    if (const YAML::Node n = child(key, r)) expectedFloats(n, key, 3, &out.x);
}

void YamlMap::vec4(const char* key, glm::vec4& out, Required r) {
    if (const YAML::Node n = child(key, r)) expectedFloats(n, key, 4, &out.x);
}

void YamlMap::path(const char* key, fs::path& out, bool mustExist, Required r) {
    const YAML::Node n = child(key, r);
    if (!n) return;
    if (!n.IsScalar() || n.Scalar().empty()) {
        report_.add(n.Mark(), keyPath(key) + ": expected a file path");
        return;
    }
    fs::path p(n.Scalar());
    if (p.is_relative()) p = report_.file().parent_path() / p;
    std::error_code ec;
    if (mustExist && !fs::exists(p, ec)) {
        report_.add(n.Mark(), keyPath(key) + ": file '" + p.string() + "' does not exist");
        return;
    }
    out = p.lexically_normal();
}

void YamlMap::numbers(const char* key, std::vector<float>& out, double min, double max, Required r) {
    const YAML::Node list = child(key, r);
    if (!list) return;
    if (!list.IsSequence()) {
        report_.add(list.Mark(), keyPath(key) + ": expected a list of numbers");
        return;
    }
    std::vector<float> values;
    for (const YAML::Node& item : list) {
        double v = 0.0;
        if (!item.IsScalar() || !YAML::convert<double>::decode(item, v) || !std::isfinite(v) || v < min || v > max) {
            std::ostringstream s;
            s << keyPath(key) << ": expected numbers from " << min << " to " << max;
            report_.add(item.Mark(), s.str());
            return;
        }
        values.push_back(static_cast<float>(v));
    }
    out = std::move(values);
}

YamlMap YamlMap::map(const char* key, Required r) { return YamlMap(child(key, r), keyPath(key), report_); }

std::vector<YamlMap> YamlMap::list(const char* key, Required r) {
    const YAML::Node n = child(key, r);
    std::vector<YamlMap> out;
    if (!n) return out;
    if (!n.IsSequence()) {
        report_.add(n.Mark(), keyPath(key) + ": expected a list");
        return out;
    }
    for (std::size_t i = 0; i < n.size(); ++i)
        out.emplace_back(n[i], keyPath(key) + "[" + std::to_string(i) + "]", report_);
    return out;
}

void YamlMap::finish() {
    if (!valid_ || !node_.IsMap()) return;
    std::string known;
    for (const std::string& k : read_) known += (known.empty() ? "" : ", ") + k;
    for (const auto& kv : node_) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
        if (!read_.contains(key))
            report_.add(kv.first.Mark(), keyPath(key.c_str()) + ": unknown key; expected one of " + known);
    }
}

}  // namespace arcomp
