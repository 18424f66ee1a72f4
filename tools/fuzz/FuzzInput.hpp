#pragma once
// Hands a fuzzer's bytes to a parser that only reads files: writes them to
// one file in a private folder (per process, so parallel fuzzers never
// share it) and gives its path.
//
//   return parseAsFile<ConfigError>(data, size, "station.yaml", loadStationConfig);
//
// Only the exceptions a parser documents may be caught by a target; anything
// else escaping (std::bad_alloc, std::out_of_range, ...) is a finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace arcomp::fuzz {

// The private folder, removed when the fuzzer exits normally (its time or
// run count used up), so that hours of campaign leave nothing in /tmp. A
// crash skips the removal; tools/fuzz/run keeps its input in
// build-fuzz/findings/ either way.
class FuzzFolder {
public:
    FuzzFolder() : path_(std::filesystem::temp_directory_path() / ("arcomp-fuzz-" + std::to_string(::getpid()))) {
        std::filesystem::create_directories(path_);
    }
    ~FuzzFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    FuzzFolder(const FuzzFolder&) = delete;
    FuzzFolder& operator=(const FuzzFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

inline std::filesystem::path fuzzInputFile(const std::uint8_t* data, std::size_t size, const std::string& name) {
    static const FuzzFolder dir;
    const auto file = dir.path() / name;
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) std::abort();  // the harness itself failed, not the parser
    return file;
}

// A target's whole body for a parser that reads a file: the bytes as file
// `name`, through `parse`, with the parser's documented error caught.
template <class DocumentedError, class Parse>
int parseAsFile(const std::uint8_t* data, std::size_t size, const std::string& name, Parse&& parse) {
    const auto file = fuzzInputFile(data, size, name);
    try {
        parse(file);
    } catch (const DocumentedError&) {}
    return 0;
}

}  // namespace arcomp::fuzz
