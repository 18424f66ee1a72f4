#include "runtime/config/CameraFile.hpp"

#include "../support/TempDir.hpp"
#include "runtime/config/ConfigError.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace arcomp {

TEST(CameraFile, aWrittenCameraReadsBackTheSame) {
    test::TempDir dir;
    CalibratedCamera c;
    c.intrinsics = {.imageSize = {1280, 720},
                    .fx = 1001.25,
                    .fy = 999.5,
                    .cx = 640.75,
                    .cy = 355.125,
                    .distortion = {-0.21, 0.05, 0.001, -0.0005, 0.0}};
    c.rotation = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(1.0, 0.2, -0.3)));
    c.translation = {0.25, 1.5, 7.75};
    writeCameraFile(dir.path() / "camera.yaml", c, "made by a test");
    const CalibratedCamera read = readCameraFile(dir.path() / "camera.yaml");
    EXPECT_EQ(read.intrinsics.imageSize, c.intrinsics.imageSize);
    EXPECT_DOUBLE_EQ(read.intrinsics.fx, 1001.25);
    EXPECT_DOUBLE_EQ(read.intrinsics.cy, 355.125);
    EXPECT_NEAR(read.intrinsics.distortion[0], -0.21, 1e-7);
    EXPECT_NEAR(read.intrinsics.distortion[3], -0.0005, 1e-9);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(read.translation[i], c.translation[i], 1e-6);
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(read.rotation[i][j], c.rotation[i][j], 1e-6);
    }
}

TEST(CameraFile, intrinsicsAloneStandTheCameraAtTheOrigin) {
    test::TempDir dir;
    const CalibratedCamera c =
        readCameraFile(dir.write("lens.yaml", "image_size: [640, 480]\nfx: 500\nfy: 500\ncx: 319.5\ncy: 239.5\n"));
    EXPECT_EQ(c.position(), glm::dvec3(0.0));
    EXPECT_FALSE(c.intrinsics.distorted());
}

TEST(CameraFile, aLensFileHoldsNoPoseAndReadsBackAsTheLens) {
    test::TempDir dir;
    const CameraIntrinsics lens{.imageSize = {640, 480},
                                .fx = 612.5,
                                .fy = 598.25,
                                .cx = 322.5,
                                .cy = 236.75,
                                .distortion = {-0.08, 0.01, 0.0, 0.0, 0.0}};
    writeLensFile(dir.path() / "lens.yaml", lens, "chessboard, 12 views");
    std::ifstream in(dir.path() / "lens.yaml");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("rotation"), std::string::npos) << text;
    EXPECT_EQ(text.find("translation"), std::string::npos) << text;
    EXPECT_NE(text.find("# chessboard, 12 views"), std::string::npos) << text;
    const CalibratedCamera read = readCameraFile(dir.path() / "lens.yaml");
    EXPECT_EQ(read.intrinsics.imageSize, lens.imageSize);
    EXPECT_DOUBLE_EQ(read.intrinsics.fx, 612.5);
    EXPECT_DOUBLE_EQ(read.intrinsics.fy, 598.25);
    EXPECT_DOUBLE_EQ(read.intrinsics.cx, 322.5);
    EXPECT_DOUBLE_EQ(read.intrinsics.cy, 236.75);
    EXPECT_NEAR(read.intrinsics.distortion[0], -0.08, 1e-7);
    EXPECT_EQ(read.position(), glm::dvec3(0.0));
}

TEST(CameraFile, aMatrixThatIsNoRotationOrAHalfPoseIsRefusedWithItsPlace) {
    test::TempDir dir;
    const std::string lens = "image_size: [640, 480]\nfx: 500\nfy: 500\ncx: 319.5\ncy: 239.5\n";
    const auto refused = [&](const std::string& yaml, const std::string& expected) {
        try {
            readCameraFile(dir.write("camera.yaml", yaml));
            ADD_FAILURE() << yaml << " was accepted";
        } catch (const ConfigError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("camera.yaml:"), std::string::npos) << e.what();
        }
    };
    refused(lens + "rotation: [1, 0.5, 0, 0, 1, 0, 0, 0, 1]\ntranslation: [0, 1, 0]\n",
            "not a rotation matrix");  // a shear
    refused(lens + "rotation: [-1, 0, 0, 0, 1, 0, 0, 0, 1]\ntranslation: [0, 1, 0]\n",
            "not a rotation matrix");  // a mirror
    refused(lens + "rotation: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n", "give both");
    refused("image_size: [640, 480]\nfy: 500\ncx: 319.5\ncy: 239.5\n", "fx");
}

}  // namespace arcomp
