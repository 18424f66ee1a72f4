#pragma once
// What a subcommand declares on its command line: positionals, --options
// bound to variables, flags. CLI11 parses, but only tools/arcomp/main.cpp
// and CommandLine.cpp see it: it is header-only, and every file that
// included it compiled its parser again (about 10 s a file under the
// sanitizers, most of a command file's build).
//
//   [](CommandLine& line) {
//       auto o = std::make_shared<Options>();
//       line.option("model", o->model, "Model file").required();
//       line.option("--frames", o->frames, "frames to run").range(1, 1000).showDefault();
//       line.flag("--windowed", o->windowed, "A window instead of full screen");
//       return [o] { return run(*o); };
//   }

#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace arcomp {

// One declared option, for chaining its constraints.
class CommandOption {
public:
    explicit CommandOption(CLI::Option* option) : option_(option) {}
    CommandOption& required();
    // --help shows the bound variable's value at declaration as the default.
    CommandOption& showDefault();
    CommandOption& range(int min, int max);
    CommandOption& range(double min, double max);
    CommandOption& oneOf(const std::vector<std::string>& values);

private:
    CLI::Option* option_;
};

class CommandLine {
public:
    explicit CommandLine(CLI::App& app) : app_(app) {}

    // `name` without dashes is a positional argument; "--name" an option.
    CommandOption option(const std::string& name, std::string& value, const std::string& help = {});
    CommandOption option(const std::string& name, int& value, const std::string& help = {});
    CommandOption option(const std::string& name, long& value, const std::string& help = {});
    CommandOption option(const std::string& name, unsigned& value, const std::string& help = {});
    CommandOption option(const std::string& name, unsigned long& value, const std::string& help = {});
    CommandOption option(const std::string& name, float& value, const std::string& help = {});
    CommandOption option(const std::string& name, double& value, const std::string& help = {});
    CommandOption option(const std::string& name, std::vector<std::string>& values, const std::string& help = {});
    CommandOption flag(const std::string& name, bool& value, const std::string& help = {});

private:
    CLI::App& app_;
};

}  // namespace arcomp
