#pragma once
// GStreamer as arcomp uses it: initialised once per process, and asked
// which elements this machine has (plugins are packages: x264enc is in
// gstreamer1.0-plugins-ugly, srtsink in -bad), so that a missing one is
// named before a pipeline is built.
//
//   if (!hasGstElement("x264enc")) report("install gstreamer1.0-plugins-ugly");

#include <string>

namespace arcomp {

// Idempotent and thread-safe.
void initGstreamer();
bool hasGstElement(const std::string& factory);
// The Debian package that holds an element arcomp uses, for messages;
// "a GStreamer plugin package" for one it does not know.
std::string packageOfGstElement(const std::string& factory);

}  // namespace arcomp
