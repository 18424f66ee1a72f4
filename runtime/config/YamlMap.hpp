#pragma once
// A checked view of one YAML mapping in a config file. Every read names its
// key, so whatever is left over at the end is an unknown key; every problem
// is recorded with its line and column instead of stopping at the first.
//
//   ConfigReport report("station.yaml");
//   YamlMap camera = root.map("camera");
//   camera.number("fovy_deg", cfg.fovy, 1, 179);     // optional
//   camera.vec3("eye", cfg.eye, Required::Yes);
//   camera.finish();                                 // unknown keys
//   report.throwIfAny();

#include "runtime/config/ConfigError.hpp"

#include <glm/glm.hpp>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace arcomp {

enum class Required { No, Yes };

class ConfigReport {
public:
    explicit ConfigReport(std::filesystem::path file) : file_(std::move(file)) {}
    void add(const YAML::Mark& mark, std::string message);
    void addFileLevel(std::string message);
    // "station.yaml:12:5", for a problem only found later (on the machine
    // that runs the config) that should still name its place.
    std::string place(const YAML::Mark& mark) const;
    void throwIfAny() const;
    const std::filesystem::path& file() const { return file_; }
    const std::vector<ConfigIssue>& issues() const { return issues_; }

private:
    std::filesystem::path file_;
    std::vector<ConfigIssue> issues_;
};

class YamlMap {
public:
    // `path` is the dotted key path used in messages ("scene.objects[2]").
    YamlMap(YAML::Node node, std::string path, ConfigReport& report);

    bool has(const char* key) const;
    void number(const char* key, double& out, double min, double max, Required r = Required::No);
    void number(const char* key, float& out, double min, double max, Required r = Required::No);
    void integer(const char* key, int& out, int min, int max, Required r = Required::No);
    void boolean(const char* key, bool& out, Required r = Required::No);
    void text(const char* key, std::string& out, Required r = Required::No);
    // One of `choices`; the message lists them.
    void choice(const char* key, std::string& out, const std::vector<std::string>& choices, Required r = Required::No);
    void numbers(const char* key, std::vector<float>& out, double min, double max, Required r = Required::No);
    void vec2i(const char* key, glm::ivec2& out, int min, int max, Required r = Required::No);
    void vec3(const char* key, glm::vec3& out, Required r = Required::No);
    void vec4(const char* key, glm::vec4& out, Required r = Required::No);
    // A path resolved against the config's folder; with mustExist, a missing
    // file is an error at this key.
    void path(const char* key, std::filesystem::path& out, bool mustExist, Required r = Required::No);
    // A nested mapping; an absent optional one is an empty map.
    YamlMap map(const char* key, Required r = Required::No);
    // A sequence of mappings.
    std::vector<YamlMap> list(const char* key, Required r = Required::No);
    // Records every key that no read asked for.
    void finish();

    const YAML::Mark& mark() const { return mark_; }
    const std::string& where() const { return path_; }
    ConfigReport& report() { return report_; }
    // The node at `key` after marking it read, for shapes not covered above.
    YAML::Node take(const char* key);

private:
    YAML::Node child(const char* key, Required r);
    std::string keyPath(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
    void expectedFloats(const YAML::Node& n, const char* key, std::size_t count, float* out);

    YAML::Node node_;
    std::string path_;
    ConfigReport& report_;
    YAML::Mark mark_;
    std::set<std::string> read_;
    bool valid_ = true;
};

// Parses the file and gives its root mapping; syntax errors are recorded
// with their place and leave the root empty.
YAML::Node loadYamlFile(ConfigReport& report);

}  // namespace arcomp
