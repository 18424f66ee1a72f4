#include "runtime/operator/StationLog.hpp"

#include <spdlog/sinks/rotating_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

namespace arcomp {

void configureLogging(const LogSettings& settings) {
    std::vector<spdlog::sink_ptr> sinks{std::make_shared<spdlog::sinks::stderr_color_sink_mt>()};
    if (!settings.file.empty()) {
        try {
            if (settings.file.has_parent_path()) std::filesystem::create_directories(settings.file.parent_path());
            sinks.push_back(std::make_shared<spdlog::sinks::rotating_file_sink_mt>(
                settings.file.string(), static_cast<std::size_t>(settings.maxMegabytes) * 1024 * 1024,
                static_cast<std::size_t>(settings.files)));
        } catch (const std::exception& e) {
            throw std::runtime_error("log file " + settings.file.string() + ": " + e.what());
        }
    }
    auto logger = std::make_shared<spdlog::logger>("arcomp", sinks.begin(), sinks.end());
    logger->set_level(spdlog::level::from_str(settings.level));
    // Warnings reach the file at once: a station that is killed must not
    // take its last complaint with it.
    logger->flush_on(spdlog::level::warn);
    spdlog::set_default_logger(logger);
}

}  // namespace arcomp
