#include "tools/arcomp/FloorMarker.hpp"

#include "tools/arcomp/ArucoDictionary.hpp"
#include "tools/cli/Command.hpp"

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace arcomp {

std::vector<FloorPoint> findFloorMarker(const cv::Mat& image, const std::string& dictionaryName, int id,
                                        double sizeMetres) {
    const cv::Ptr<cv::aruco::Dictionary> dictionary = arucoDictionary(dictionaryName);
    const int count = dictionary->bytesList.rows;
    if (id < 0 || id >= count)
        throw InputError("--marker " + std::to_string(id) + ": " + dictionaryName + " has IDs 0 to " +
                         std::to_string(count - 1));
    cv::Mat grey = image;
    if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    // Subpixel corners: the four corners are all the pose is made of.
    const cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
    parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<int> ids;
    cv::aruco::detectMarkers(grey, dictionary, corners, ids, parameters);

    const auto copies = std::count(ids.begin(), ids.end(), id);
    if (copies == 0) {
        std::vector<int> seen = ids;
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        std::string found;
        for (int s : seen) found += (found.empty() ? "" : ", ") + std::to_string(s);
        throw InputError("--marker " + std::to_string(id) + ": not in the image; " +
                         (seen.empty()
                              ? "it shows no " + dictionaryName + " markers at all"
                              : "it shows " + dictionaryName + " marker" + (seen.size() > 1 ? "s " : " ") + found) +
                         " (a marker must lie in full view, its white border around it)");
    }
    if (copies > 1)
        throw InputError("--marker " + std::to_string(id) + ": in the image " + std::to_string(copies) +
                         " times; the floor's origin has to be one marker");
    const std::vector<cv::Point2f>& c =
        corners[static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin())];
    const double h = sizeMetres / 2.0;
    const cv::Point3d floor[4] = {{-h, 0.0, -h}, {h, 0.0, -h}, {h, 0.0, h}, {-h, 0.0, h}};
    std::vector<FloorPoint> points;
    for (int i = 0; i < 4; ++i) points.push_back({cv::Point2d(c[static_cast<std::size_t>(i)]), floor[i]});
    return points;
}

}  // namespace arcomp
