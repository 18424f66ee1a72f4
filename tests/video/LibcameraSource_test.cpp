#include "video/sources/LibcameraSource.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

TEST(LibcameraSource, reportsDisconnectedWhenNoCameraIsListed) {
    if (!listLibcameraCameras().empty()) GTEST_SKIP() << "a real camera is attached";
    LibcameraOptions o;
    o.backoffInitial = std::chrono::milliseconds(0);
    o.backoffMax = std::chrono::milliseconds(0);
    LibcameraSource cam(o);
    GrabResult r = cam.grab();
    EXPECT_FALSE(r.frame);
    EXPECT_EQ(r.state.status, SourceStatus::Disconnected);
    EXPECT_NE(r.state.reason.find("no camera"), std::string::npos) << r.state.reason;
    EXPECT_EQ(cam.grab().state.status, SourceStatus::Disconnected);  // and keeps looking, without crashing
}
