#include "tools/arcomp/ArucoDictionary.hpp"

#include "tools/cli/Command.hpp"

#include <utility>

namespace arcomp {

cv::Ptr<cv::aruco::Dictionary> arucoDictionary(const std::string& name) {
    using namespace cv::aruco;
    static const std::pair<const char*, PREDEFINED_DICTIONARY_NAME> kNames[] = {
        {"DICT_4X4_50", DICT_4X4_50},
        {"DICT_4X4_100", DICT_4X4_100},
        {"DICT_4X4_250", DICT_4X4_250},
        {"DICT_4X4_1000", DICT_4X4_1000},
        {"DICT_5X5_50", DICT_5X5_50},
        {"DICT_5X5_100", DICT_5X5_100},
        {"DICT_5X5_250", DICT_5X5_250},
        {"DICT_5X5_1000", DICT_5X5_1000},
        {"DICT_6X6_50", DICT_6X6_50},
        {"DICT_6X6_100", DICT_6X6_100},
        {"DICT_6X6_250", DICT_6X6_250},
        {"DICT_6X6_1000", DICT_6X6_1000},
        {"DICT_7X7_50", DICT_7X7_50},
        {"DICT_7X7_100", DICT_7X7_100},
        {"DICT_7X7_250", DICT_7X7_250},
        {"DICT_7X7_1000", DICT_7X7_1000},
        {"DICT_ARUCO_ORIGINAL", DICT_ARUCO_ORIGINAL},
        {"DICT_APRILTAG_16h5", DICT_APRILTAG_16h5},
        {"DICT_APRILTAG_25h9", DICT_APRILTAG_25h9},
        {"DICT_APRILTAG_36h10", DICT_APRILTAG_36h10},
        {"DICT_APRILTAG_36h11", DICT_APRILTAG_36h11},
    };
    std::string known;
    for (const auto& [n, id] : kNames) {
        if (name == n) return getPredefinedDictionary(id);
        known += std::string(known.empty() ? "" : ", ") + n;
    }
    throw InputError("--dictionary " + name + ": not an OpenCV ArUco dictionary; one of " + known);
}

}  // namespace arcomp
