// The glTF writer the feature models and the tests' files share: what it
// writes loads through arcomp's own loader, with the buffer laid out as the
// spec asks.

#include "graph/io/GltfWriter.hpp"
#include "graph/io/ModelLoader.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <cstdint>

using namespace arcomp;
using arcomp::test::TempDir;
using Json = GltfWriter::Json;

namespace {

GltfWriter triangle() {
    GltfWriter w;
    const float corners[9] = {0, 0, 0, 2, 0, 0, 0, 3, -1};
    const std::uint8_t pad[1] = {7};  // one byte, so that the next view must be realigned
    const std::uint16_t indices[3] = {0, 1, 2};
    const int position = w.accessor(corners, 3, "VEC3", GltfWriter::kFloat, {.bounds = true});
    w.accessor(pad, 1, "SCALAR", GltfWriter::kUnsignedByte);
    const int index =
        w.accessor(indices, 3, "SCALAR", GltfWriter::kUnsignedShort, {.target = GltfWriter::kElementArrayBuffer});
    GltfWriter::add(w.meshes, R"({"primitives": [{"attributes": {"POSITION": )" + std::to_string(position) +
                                  R"(}, "indices": )" + std::to_string(index) + "}]}");
    w.sceneNodes.push_back(GltfWriter::add(w.nodes, R"({"name": "tri", "mesh": 0})"));
    return w;
}

}  // namespace

TEST(GltfWriter, aTriangleLoadsWithItsBoundsAndAlignedViews) {
    const GltfWriter w = triangle();
    const Json doc = Json::parse(w.text());
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_EQ(doc["accessors"][0]["min"], Json::parse("[0, 0, -1]"));
    EXPECT_EQ(doc["accessors"][0]["max"], Json::parse("[2, 3, 0]"));
    EXPECT_FALSE(doc["accessors"][1].contains("min"));
    EXPECT_EQ(doc["bufferViews"][1]["byteOffset"], 36);
    EXPECT_EQ(doc["bufferViews"][2]["byteOffset"], 40);  // 37 rounded up to 4
    EXPECT_EQ(doc["bufferViews"][2]["target"], GltfWriter::kElementArrayBuffer);
    EXPECT_EQ(doc["buffers"][0]["byteLength"], 46);
    // glTF arrays, when present, are not empty: none was added, none is written.
    EXPECT_FALSE(doc.contains("animations"));
    EXPECT_FALSE(doc.contains("materials"));

    TempDir dir;
    const auto file = dir.write("tri.gltf", w.text());
    Scene scene;
    const std::size_t before = scene.nodeCount();
    const LoadedModel m = loadModel(file, scene, scene.root());  // throws a ModelError on what it cannot take
    EXPECT_NE(m.root, kNoNode);
    EXPECT_GT(scene.nodeCount(), before);
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
}

TEST(GltfWriter, aHandWrittenPartThatIsNotJsonIsRefusedWhereItIsAdded) {
    GltfWriter w;
    EXPECT_THROW(GltfWriter::add(w.materials, R"({"name": "unfinished")"), Json::parse_error);
    EXPECT_TRUE(w.materials.empty());
    const float one = 1.0f;
    EXPECT_THROW(w.accessor(&one, 1, "VEC5", GltfWriter::kFloat), std::invalid_argument);
    EXPECT_THROW(w.accessor(&one, 1, "SCALAR", GltfWriter::kUnsignedByte, {.bounds = true}), std::invalid_argument);
}

TEST(GltfWriter, theGlbHoldsTheSameModelWithTheBufferInItsBinChunk) {
    const GltfWriter w = triangle();
    TempDir dir;
    const std::string glb = w.glb();
    ASSERT_EQ(glb.substr(0, 4), "glTF");
    EXPECT_EQ(glb.size() % 4, 0u);
    EXPECT_EQ(glb.find("base64"), std::string::npos);
    Scene fromText, fromGlb;
    loadModel(dir.write("tri.gltf", w.text()), fromText, fromText.root());
    loadModel(dir.write("tri.glb", glb), fromGlb, fromGlb.root());
    ASSERT_EQ(fromGlb.geometries().size(), 1u);
    EXPECT_EQ(fromGlb.geometry(0).positions, fromText.geometry(0).positions);
    EXPECT_EQ(fromGlb.geometry(0).indices, fromText.geometry(0).indices);
}
