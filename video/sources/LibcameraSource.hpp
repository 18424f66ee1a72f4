#pragma once
// A camera through libcamera 0.0.3 (Debian 12's; newer documentation
// differs). One Request per allocated buffer; libcamera's requestCompleted
// callback only hands the request to grab() on the capture thread, which
// converts, reuses and requeues it. Stop, free and release also happen on
// that thread, never inside a libcamera callback.
//
//   LibcameraSource cam({.cameraId = "", .width = 1280, .height = 720});   // "" = first camera
//   GrabResult r = cam.grab();   // Disconnected while libcamera lists no camera
//
// With no camera (cameraRemoved, or none at start) the source reports
// Disconnected and looks again with backoff.

#include "video/pixels/YuvConversion.hpp"
#include "video/sources/FrameGrabber.hpp"

#include <chrono>
#include <memory>
#include <vector>

namespace arcomp {

struct LibcameraOptions {
    std::string cameraId;  // empty: the first camera libcamera lists
    int width = 1280;
    int height = 720;
    double fps = 30.0;
    std::vector<PixelFormat> preference{PixelFormat::Yuyv, PixelFormat::Nv12, PixelFormat::Mjpeg};
    std::optional<YuvEncoding> encoding;
    std::chrono::milliseconds backoffInitial{250};
    std::chrono::milliseconds backoffMax{2000};
};

class LibcameraSource : public FrameGrabber {
public:
    explicit LibcameraSource(LibcameraOptions options);
    ~LibcameraSource() override;

    GrabResult grab() override;
    std::string name() const override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Ids of the cameras libcamera lists now (empty here: no camera).
std::vector<std::string> listLibcameraCameras();

}  // namespace arcomp
