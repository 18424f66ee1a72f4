#pragma once
// A line chart written to PNG, for the benchmarks that reproduce a paper's
// figure (frame time along a camera path, polygons drawn against Ωt). A few
// series, a legend, optional horizontal reference lines; axes start at the
// data's minimum x and at y = 0. Not a plotting library.
//
//   LinePlot plot("frame time along the path", "frame", "ms");
//   plot.addSeries("unmanaged", frames, unmanagedMs);
//   plot.addLevel("target", 16.7);
//   plot.writePng("out/budget/frame-time.png");   // throws on failure

#include <filesystem>
#include <string>
#include <vector>

namespace arcomp {

class LinePlot {
public:
    LinePlot(std::string title, std::string xLabel, std::string yLabel);

    // Colours are picked from a fixed palette in the order series are added.
    void addSeries(std::string name, std::vector<double> x, std::vector<double> y);
    void addLevel(std::string name, double y);

    // Creates the folder when missing; throws std::runtime_error on failure.
    void writePng(const std::filesystem::path& file, int width = 960, int height = 540) const;

private:
    struct Series {
        std::string name;
        std::vector<double> x, y;
    };
    struct Level {
        std::string name;
        double y;
    };
    std::string title_, xLabel_, yLabel_;
    std::vector<Series> series_;
    std::vector<Level> levels_;
};

}  // namespace arcomp
