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

namespace arcomp::fuzz {

inline std::filesystem::path fuzzInputFile(const std::uint8_t* data, std::size_t size, const std::string& name) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("arcomp-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const auto file = dir / name;
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
    } catch (const DocumentedError&) {
    }
    return 0;
}

} // namespace arcomp::fuzz
