#include "graph/io/SilhouetteFile.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace arcomp;

namespace {

int runArcomp(const std::string& args) {
    const int status = std::system((std::string(ARCOMP_BINARY) + " " + args + " 2>/dev/null").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// An octahedron: small, closed, and every face visible from somewhere.
fs::path writeOctahedron(const fs::path& folder) {
    fs::create_directories(folder);
    const fs::path file = folder / "octahedron.obj";
    std::ofstream out(file);
    out << "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
           "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    return file;
}

}  // namespace

TEST(BakeSilhouette, writesAFileTheReaderAccepts) {
    const fs::path folder = fs::path(ARCOMP_TEST_OUTPUT) / "bake_silhouette";
    const fs::path model = writeOctahedron(folder), out = folder / "octahedron.sil";
    fs::remove(out);
    ASSERT_EQ(runArcomp("bake silhouette " + model.string() + " --regions '-0.5,-0.5,3,0.5,0.5,4;3,3,3,4,4,4' --out " +
                        out.string()),
              0);
    const SilhouetteMesh m = readSilhouetteFile(out);
    EXPECT_EQ(m.regions.size(), 2u);
    EXPECT_EQ(m.full.indexCount, 24u);
    EXPECT_LT(m.ranges[0].indexCount, m.full.indexCount);  // the back faces are gone
}

TEST(BakeSilhouette, badRegionsAreBadInput) {
    const fs::path folder = fs::path(ARCOMP_TEST_OUTPUT) / "bake_silhouette";
    const fs::path model = writeOctahedron(folder);
    EXPECT_EQ(runArcomp("bake silhouette " + model.string() + " --regions 1,2,3 --out " + (folder / "x.sil").string()),
              2);
    EXPECT_EQ(
        runArcomp("bake silhouette " + model.string() + " --regions around:0 --out " + (folder / "x.sil").string()), 2);
    EXPECT_EQ(
        runArcomp("bake silhouette " + (folder / "missing.obj").string() + " --out " + (folder / "x.sil").string()), 2);
}
