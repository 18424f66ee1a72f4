#include "tools/cli/CommandLine.hpp"

#include <CLI/CLI.hpp>

namespace arcomp {

CommandOption& CommandOption::required() {
    option_->required();
    return *this;
}

CommandOption& CommandOption::showDefault() {
    option_->capture_default_str();
    return *this;
}

CommandOption& CommandOption::range(int min, int max) {
    option_->check(CLI::Range(min, max));
    return *this;
}

CommandOption& CommandOption::range(double min, double max) {
    option_->check(CLI::Range(min, max));
    return *this;
}

CommandOption& CommandOption::oneOf(const std::vector<std::string>& values) {
    option_->check(CLI::IsMember(values));
    return *this;
}

CommandOption CommandLine::option(const std::string& name, std::string& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, int& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, long& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, unsigned& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, unsigned long& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, float& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, double& value, const std::string& help) {
    return CommandOption(app_.add_option(name, value, help));
}
CommandOption CommandLine::option(const std::string& name, std::vector<std::string>& values, const std::string& help) {
    return CommandOption(app_.add_option(name, values, help));
}
CommandOption CommandLine::flag(const std::string& name, bool& value, const std::string& help) {
    return CommandOption(app_.add_flag(name, value, help));
}

}  // namespace arcomp
