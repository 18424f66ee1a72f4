#pragma once
// Feeds every input kept under tests/fuzz-regressions/<target>/ (inputs that
// once broke a parser, found by tools/fuzz) to `parse`: each must load or be
// refused with `Expected`; any other exception fails the test.
//
//   eachLoadsOrIsRefused<ModelError>("gltf", [](const fs::path& f) { loadModel(f); });
//   eachRegressionInput("http", [](const fs::path& f) { check(parseHttpRequestHead(bytesOf(f))); });

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <typeinfo>

namespace arcomp::test {

// Calls `use` on every input kept under tests/fuzz-regressions/<target>/;
// a folder with none fails the test.
inline void eachRegressionInput(const std::string& target,
                                const std::function<void(const std::filesystem::path&)>& use) {
    const std::filesystem::path dir = std::filesystem::path(ARCOMP_SOURCE_DIR) / "tests/fuzz-regressions" / target;
    int inputs = 0;
    if (std::filesystem::exists(dir))
        for (const auto& e : std::filesystem::directory_iterator(dir)) {
            if (!e.is_regular_file()) continue;
            ++inputs;
            use(e.path());
        }
    EXPECT_GT(inputs, 0) << dir << " holds no inputs";
}

template <class Expected>
void eachLoadsOrIsRefused(const std::string& target, const std::function<void(const std::filesystem::path&)>& parse) {
    eachRegressionInput(target, [&](const std::filesystem::path& file) {
        try {
            parse(file);
        } catch (const Expected&) {
        } catch (const std::exception& x) {
            ADD_FAILURE() << file << ": escaped as " << typeid(x).name() << ": " << x.what();
        }
    });
}

}  // namespace arcomp::test
