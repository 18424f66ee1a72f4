// arcomp calibrate floor <image|video> (--points "u,v=x,z;..." | --marker ID --marker-size M)
//     (--intrinsics F | --fovy-deg D) --out F:
// where the camera stands over the floor. Image points of at least four
// marks on the floor, each with its floor coordinates in metres (x, z; the
// floor is y = 0, +y up), give the camera's pose by cv::solvePnP. The marks
// are either given by hand (--points) or are the corners of an ArUco marker
// lying on the floor, found in the image (--marker, FloorMarker.hpp), which
// then is the floor's origin. Prints the reprojection error, the camera's
// height and tilt, and writes the camera file a station's
// `camera.calibration` names (runtime/config/CameraFile.hpp).
// With --preview it also draws the points, their reprojections and a 1 m
// floor grid over the image, to be looked at before it is trusted.

#include "runtime/config/CameraFile.hpp"
#include "tools/arcomp/FloorMarker.hpp"
#include "tools/cli/Command.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace arcomp {
namespace {

struct FloorCalibrationOptions {
    std::string image;
    std::string points;
    int marker = -1;
    double markerSize = 0.0;
    std::string dictionary;  // DICT_4X4_50 when not given
    std::string intrinsics;
    double fovyDegrees = 0.0;
    std::string out;
    std::string preview;
};

// "u,v=x,z;u,v=x,z;...": each item's place in the message when it is malformed.
std::vector<FloorPoint> parseFloorPoints(const std::string& text) {
    std::vector<FloorPoint> points;
    std::stringstream items(text);
    std::string item;
    for (int n = 1; std::getline(items, item, ';'); ++n) {
        if (item.find_first_not_of(" \t") == std::string::npos) continue;
        double u, v, x, z;
        char comma1, equals, comma2;
        std::istringstream in(item);
        if (!(in >> u >> comma1 >> v >> equals >> x >> comma2 >> z) || comma1 != ',' || equals != '=' ||
            comma2 != ',' || !(in >> std::ws).eof() || !std::isfinite(u) || !std::isfinite(v) || !std::isfinite(x) ||
            !std::isfinite(z))
            throw InputError("--points: item " + std::to_string(n) + " (\"" + item +
                             "\") is not u,v=x,z (pixels = floor metres)");
        points.push_back({{u, v}, {x, 0.0, z}});
    }
    return points;
}

cv::Mat firstImage(const std::string& file) {
    if (!std::filesystem::is_regular_file(file)) throw BadInput(file, "", "no such file");
    cv::Mat image = cv::imread(file, cv::IMREAD_COLOR);
    if (image.empty()) {
        cv::VideoCapture video(file);
        if (video.isOpened()) video.read(image);
    }
    if (image.empty()) throw BadInput(file, "", "neither an image nor a video with a first frame");
    return image;
}

// The floor points span an area: on one line they leave the pose's roll
// about that line undetermined.
void requireSpread(const std::vector<FloorPoint>& points) {
    cv::Mat xz(static_cast<int>(points.size()), 2, CV_64F);
    for (int i = 0; i < xz.rows; ++i) {
        xz.at<double>(i, 0) = points[static_cast<std::size_t>(i)].floor.x;
        xz.at<double>(i, 1) = points[static_cast<std::size_t>(i)].floor.z;
    }
    cv::PCA pca(xz, cv::noArray(), cv::PCA::DATA_AS_ROW);
    const double along = std::sqrt(std::max(pca.eigenvalues.at<double>(0), 0.0));
    const double across = pca.eigenvalues.rows > 1 ? std::sqrt(std::max(pca.eigenvalues.at<double>(1), 0.0)) : 0.0;
    if (along <= 0.0 || across < 0.02 * along)
        throw InputError("--points: the floor points lie (almost) on one line; give at least 4 that span an area, not "
                         "all on one line");
}

// The marks as given by hand.
std::vector<FloorPoint> givenPoints(const std::string& text, glm::ivec2 size) {
    const std::vector<FloorPoint> points = parseFloorPoints(text);
    if (points.size() < 4)
        throw InputError("--points: " + std::to_string(points.size()) +
                         " given; the floor needs at least 4 (u,v=x,z;...)");
    for (const FloorPoint& p : points)
        if (p.pixel.x < 0 || p.pixel.y < 0 || p.pixel.x > size.x - 1 || p.pixel.y > size.y - 1) {
            char where[64];
            std::snprintf(where, sizeof where, "%g,%g", p.pixel.x, p.pixel.y);
            throw InputError(std::string("--points: pixel ") + where + " is outside the " + std::to_string(size.x) +
                             "x" + std::to_string(size.y) + " image");
        }
    requireSpread(points);
    return points;
}

int calibrateFloor(const FloorCalibrationOptions& o) {
    const bool byPoints = !o.points.empty(), byMarker = o.marker >= 0;
    if (byPoints && byMarker) throw InputError("give the floor marks by --points or by --marker, not both");
    if (!byPoints && !byMarker)
        throw InputError(
            "give the floor marks: --points \"u,v=x,z;...\" (at least 4 marks) or --marker ID --marker-size M "
            "(an ArUco marker lying on the floor)");
    if (byMarker && !(o.markerSize > 0.0))
        throw InputError("--marker " + std::to_string(o.marker) +
                         ": give its --marker-size, the black square's edge in metres (border included)");
    if (!byMarker && (o.markerSize != 0.0 || !o.dictionary.empty()))
        throw InputError("--marker-size and --dictionary describe the --marker; with --points there is none");
    const std::string dictionary = o.dictionary.empty() ? "DICT_4X4_50" : o.dictionary;
    // How the marks were given, for the messages.
    const std::string marks = byPoints ? "--points" : "--marker " + std::to_string(o.marker);

    const cv::Mat image = firstImage(o.image);
    const glm::ivec2 size{image.cols, image.rows};
    const std::vector<FloorPoint> points =
        byPoints ? givenPoints(o.points, size) : findFloorMarker(image, dictionary, o.marker, o.markerSize);
    if (byMarker) {
        // Four corners a few pixels apart fit tilted poses nearly as well as
        // the true one. Seen from 3 m up, 40 degrees down, in a 640x480
        // picture: a 0.2 m marker (16 px, the root of its area in pixels)
        // gave 2.6 m and 34 degrees, a 0.5 m one 2.99 m and 39.8 degrees.
        std::vector<cv::Point2f> corners;
        for (const FloorPoint& p : points) corners.emplace_back(p.pixel);
        const double across = std::sqrt(cv::contourArea(corners));
        if (across < 30.0)
            std::fprintf(
                stderr,
                "arcomp calibrate floor: warning: marker %d spans only %.0f px in the image; a marker this small "
                "places the camera loosely (height and tilt off by a tenth): use a bigger one, or check the "
                "--preview\n",
                o.marker, across);
    }

    CalibratedCamera camera;
    if (!o.intrinsics.empty()) {
        camera.intrinsics = readCameraFile(o.intrinsics).intrinsics.scaledTo(size);
    } else if (o.fovyDegrees > 0.0) {
        // A guessed lens: square pixels, the principal point in the middle, no distortion.
        CameraIntrinsics& k = camera.intrinsics;
        k.imageSize = size;
        k.fy = k.fx = 0.5 * size.y / std::tan(glm::radians(o.fovyDegrees) / 2.0);
        k.cx = (size.x - 1) / 2.0;
        k.cy = (size.y - 1) / 2.0;
    } else {
        throw InputError("give the lens: --intrinsics <camera file> (from `arcomp calibrate intrinsics`) or --fovy-deg "
                         "<vertical field of view>");
    }
    const CameraIntrinsics& k = camera.intrinsics;
    const cv::Matx33d cameraMatrix(k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
    const cv::Vec<double, 5> distortion(k.distortion[0], k.distortion[1], k.distortion[2], k.distortion[3],
                                        k.distortion[4]);

    std::vector<cv::Point3d> floor;
    std::vector<cv::Point2d> pixels;
    for (const FloorPoint& p : points) {
        floor.push_back(p.floor);
        pixels.push_back(p.pixel);
    }
    cv::Vec3d rvec, tvec;
    if (!cv::solvePnP(floor, pixels, cameraMatrix, distortion, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE))
        throw InputError(marks + ": no camera pose fits these points");
    std::vector<cv::Point2d> reprojected;
    cv::projectPoints(floor, rvec, tvec, cameraMatrix, distortion, reprojected);
    double squares = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const double e = cv::norm(reprojected[i] - pixels[i]);
        squares += e * e;
        worst = std::max(worst, e);
    }
    const double rms = std::sqrt(squares / static_cast<double>(pixels.size()));

    cv::Matx33d r;
    cv::Rodrigues(rvec, r);
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) camera.rotation[column][row] = r(row, column);
    camera.translation = glm::dvec3(tvec[0], tvec[1], tvec[2]);
    if (camera.heightMetres() <= 0.0)
        throw InputError(
            marks + ": the best fit puts the camera " + std::to_string(-camera.heightMetres()) +
            " m below the floor; " +
            (byPoints ? "check that each u,v is the image point of its x,z" : "is the marker on the floor?"));

    char what[96];
    if (byPoints)
        std::snprintf(what, sizeof what, "%zu points", points.size());
    else
        std::snprintf(what, sizeof what, "the corners of %s marker %d (%g m)", dictionary.c_str(), o.marker,
                      o.markerSize);
    char note[256];
    std::snprintf(note, sizeof note, "floor from %s in %s: %.2f px RMS, %.2f px worst", what,
                  std::filesystem::path(o.image).filename().c_str(), rms, worst);
    writeCameraFile(o.out, camera, note);
    if (!o.preview.empty()) {
        cv::Mat shown = image.clone();
        // A 1 m grid over the floor around the points, as the camera sees it.
        double minX = 1e9, maxX = -1e9, minZ = 1e9, maxZ = -1e9;
        for (const cv::Point3d& f : floor) {
            minX = std::min(minX, f.x), maxX = std::max(maxX, f.x), minZ = std::min(minZ, f.z),
            maxZ = std::max(maxZ, f.z);
        }
        std::vector<cv::Point3d> ends;
        for (double x = std::floor(minX) - 2; x <= std::ceil(maxX) + 2; x += 1.0)
            ends.insert(ends.end(), {{x, 0, std::floor(minZ) - 2}, {x, 0, std::ceil(maxZ) + 2}});
        for (double z = std::floor(minZ) - 2; z <= std::ceil(maxZ) + 2; z += 1.0)
            ends.insert(ends.end(), {{std::floor(minX) - 2, 0, z}, {std::ceil(maxX) + 2, 0, z}});
        for (std::size_t i = 0; i + 1 < ends.size(); i += 2) {
            const cv::Point3d a = ends[i], b = ends[i + 1];
            std::vector<cv::Point3d> line;
            for (int s = 0; s <= 20; ++s) line.push_back(a + (b - a) * (s / 20.0));
            // Only the stretch in front of the camera: points behind it project nowhere sensible.
            std::vector<cv::Point3d> ahead;
            for (const cv::Point3d& p : line)
                if ((camera.rotation * glm::dvec3(p.x, p.y, p.z) + camera.translation).z > 0.1) ahead.push_back(p);
            if (ahead.size() < 2) continue;
            std::vector<cv::Point2d> drawn;
            cv::projectPoints(ahead, rvec, tvec, cameraMatrix, distortion, drawn);
            for (std::size_t s = 0; s + 1 < drawn.size(); ++s)
                cv::line(shown, drawn[s], drawn[s + 1], cv::Scalar(0, 200, 255), 1, cv::LINE_AA);
        }
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            cv::circle(shown, pixels[i], 6, cv::Scalar(0, 255, 0), 2, cv::LINE_AA);
            cv::drawMarker(shown, reprojected[i], cv::Scalar(0, 0, 255), cv::MARKER_CROSS, 10, 2);
        }
        if (!cv::imwrite(o.preview, shown)) throw std::runtime_error(o.preview + ": cannot be written");
    }
    const glm::dvec3 at = camera.position();
    std::printf("floor: %s, reprojection %.2f px RMS (%.2f px worst)\n", what, rms, worst);
    std::printf("camera: %.2f m above the floor at x %.2f, z %.2f, tilted %.1f degrees down\n", camera.heightMetres(),
                at.x, at.z, camera.tiltDegrees());
    std::printf("wrote %s\n", o.out.c_str());
    return kExitOk;
}

const bool registered = registerCalibration(
    {"floor", "The camera's pose over the floor from image points of known floor marks", [](CommandLine& line) {
         auto o = std::make_shared<FloorCalibrationOptions>();
         line.option("image", o->image, "An image, or a video whose first frame is used").required();
         line.option("--points", o->points, "At least 4 marks: \"u,v=x,z;...\" (pixels = floor metres)");
         line.option("--marker", o->marker,
                     "Instead of --points: the ID of an ArUco marker on the floor, the floor's origin")
             .range(0, 99999);
         line.option("--marker-size", o->markerSize, "The marker's black square's edge in metres").range(1e-3, 100.0);
         line.option("--dictionary", o->dictionary, "The marker's ArUco dictionary (DICT_4X4_50)");
         line.option("--intrinsics", o->intrinsics,
                     "A camera file with the measured lens (arcomp calibrate intrinsics)");
         line.option("--fovy-deg", o->fovyDegrees, "Without --intrinsics: the lens's vertical field of view")
             .range(1.0, 179.0);
         line.option("--out", o->out, "The camera file to write").required();
         line.option("--preview", o->preview,
                     "Also draw the points, their reprojections and a 1 m floor grid into this image");
         return [o] { return calibrateFloor(*o); };
     }});

}  // namespace
}  // namespace arcomp
