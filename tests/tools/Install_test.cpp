// `cmake --install` lays out what a kiosk needs: the binary, the example
// configs and the systemd unit template.

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

TEST(Install, placesBinaryConfigsAndSystemdUnit) {
    arcomp::test::TempDir dir;
    const fs::path build = fs::path(ARCOMP_BINARY).parent_path();
    const std::string command = "cmake --install " + build.string() + " --prefix " + dir.path().string() + " > " +
                                (dir.path() / "install.log").string() + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_TRUE(fs::exists(dir.path() / "bin/arcomp"));
    EXPECT_TRUE(fs::exists(dir.path() / "share/arcomp/configs/demo-replay.yaml"));
    EXPECT_TRUE(fs::exists(dir.path() / "share/arcomp/configs/README.md"));
    const fs::path unit = dir.path() / "lib/systemd/system/arcomp@.service";
    ASSERT_TRUE(fs::exists(unit));
    std::ifstream in(unit);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("ExecStart=/usr/bin/env arcomp run /etc/arcomp/%i.yaml"), std::string::npos);
    EXPECT_NE(text.str().find("ExecReload=/bin/kill -HUP $MAINPID"), std::string::npos);
}
