#include "video/sources/LibcameraSource.hpp"
#include "graph/core/JoinText.hpp"

#include "video/pixels/VideoError.hpp"

#include <libcamera/libcamera.h>
#include <opencv2/imgcodecs.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <thread>

#include <sys/mman.h>

namespace arcomp {

namespace {

// libcamera allows one CameraManager per process; sources share it.
std::shared_ptr<libcamera::CameraManager> sharedManager() {
    static std::mutex mutex;
    static std::weak_ptr<libcamera::CameraManager> weak;
    std::lock_guard lock(mutex);
    if (auto m = weak.lock()) return m;
    auto m = std::shared_ptr<libcamera::CameraManager>(new libcamera::CameraManager, [](libcamera::CameraManager* p) {
        p->stop();
        delete p;
    });
    if (m->start() != 0) throw VideoError("libcamera", "CameraManager::start", "failed");
    weak = m;
    return m;
}

libcamera::PixelFormat toLibcamera(PixelFormat f) {
    switch (f) {
    case PixelFormat::Yuyv: return libcamera::formats::YUYV;
    case PixelFormat::Nv12: return libcamera::formats::NV12;
    case PixelFormat::Mjpeg: return libcamera::formats::MJPEG;
    default: return {};
    }
}

}  // namespace

struct LibcameraSource::Impl {
    LibcameraOptions options;
    std::shared_ptr<libcamera::CameraManager> manager;
    std::shared_ptr<libcamera::Camera> camera;
    std::unique_ptr<libcamera::CameraConfiguration> config;
    std::unique_ptr<libcamera::FrameBufferAllocator> allocator;
    std::vector<std::unique_ptr<libcamera::Request>> requests;
    std::map<const libcamera::FrameBuffer*, std::pair<void*, std::size_t>> mapped;
    libcamera::Stream* stream = nullptr;
    PixelFormat format = PixelFormat::Yuyv;
    YuvEncoding encoding;
    int width = 0, height = 0, stride = 0;
    bool acquired = false, started = false;

    // Filled by libcamera's thread, drained by grab().
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<libcamera::Request*> completed;
    bool removed = false;

    std::uint64_t sequence = 0;
    std::chrono::milliseconds backoff{0};
    bool waitBeforeConnect = false;

    void onRequestCompleted(libcamera::Request* request) {
        if (request->status() == libcamera::Request::RequestCancelled) return;
        {
            std::lock_guard lock(mutex);
            completed.push_back(request);
        }
        ready.notify_one();
    }

    void onCameraRemoved(std::shared_ptr<libcamera::Camera> gone) {
        if (gone != camera) return;
        {
            std::lock_guard lock(mutex);
            removed = true;
        }
        ready.notify_one();
    }

    std::string connect();
    void teardown();
    std::optional<cv::Mat> convert(libcamera::FrameBuffer* buffer);
};

std::string LibcameraSource::Impl::connect() {
    if (!manager) {
        manager = sharedManager();
        manager->cameraRemoved.connect(this, &Impl::onCameraRemoved);
    }
    const auto cams = manager->cameras();
    if (cams.empty()) return "libcamera lists no camera";
    camera = options.cameraId.empty() ? cams.front() : manager->get(options.cameraId);
    if (!camera) return joinText("libcamera has no camera '", options.cameraId, "'");
    if (camera->acquire() != 0) return joinText("camera '", camera->id(), "' is in use");
    acquired = true;
    removed = false;

    config = camera->generateConfiguration({libcamera::StreamRole::Viewfinder});
    if (!config || config->empty()) return "camera gives no viewfinder configuration";
    libcamera::StreamConfiguration& sc = config->at(0);
    sc.size = libcamera::Size(static_cast<unsigned>(options.width), static_cast<unsigned>(options.height));
    for (PixelFormat want : options.preference) {
        const auto formats = sc.formats().pixelformats();
        if (std::find(formats.begin(), formats.end(), toLibcamera(want)) != formats.end()) {
            sc.pixelFormat = toLibcamera(want);
            break;
        }
    }
    if (config->validate() == libcamera::CameraConfiguration::Invalid) return "camera rejects every configuration";
    if (camera->configure(config.get()) != 0) return "Camera::configure failed";
    if (sc.pixelFormat == libcamera::formats::YUYV)
        format = PixelFormat::Yuyv;
    else if (sc.pixelFormat == libcamera::formats::NV12)
        format = PixelFormat::Nv12;
    else if (sc.pixelFormat == libcamera::formats::MJPEG)
        format = PixelFormat::Mjpeg;
    else
        return joinText("camera settled on ", sc.pixelFormat.toString(), ", which arcomp cannot convert");
    width = static_cast<int>(sc.size.width);
    height = static_cast<int>(sc.size.height);
    stride = static_cast<int>(sc.stride);
    encoding = options.encoding.value_or(defaultYuvEncoding(format, height));
    stream = sc.stream();

    allocator = std::make_unique<libcamera::FrameBufferAllocator>(camera);
    if (allocator->allocate(stream) < 0) return "FrameBufferAllocator::allocate failed";
    for (const auto& buffer : allocator->buffers(stream)) {
        // All planes of a buffer share one dmabuf here; map it once, whole.
        const auto& planes = buffer->planes();
        std::size_t length = 0;
        for (const auto& p : planes) length = std::max<std::size_t>(length, p.offset + p.length);
        void* mem = ::mmap(nullptr, length, PROT_READ, MAP_SHARED, planes[0].fd.get(), 0);
        if (mem == MAP_FAILED) return "mmap of a camera buffer failed";
        mapped[buffer.get()] = {mem, length};
        std::unique_ptr<libcamera::Request> request = camera->createRequest();
        if (!request || request->addBuffer(stream, buffer.get()) != 0) return "cannot build a capture request";
        requests.push_back(std::move(request));
    }
    camera->requestCompleted.connect(this, &Impl::onRequestCompleted);
    if (camera->start() != 0) return "Camera::start failed";
    started = true;
    for (auto& r : requests)
        if (camera->queueRequest(r.get()) != 0) return "Camera::queueRequest failed";
    spdlog::info(
        joinText("libcamera ", camera->id(), ": streaming ", pixelFormatName(format), " ", width, "x", height));
    return {};
}

void LibcameraSource::Impl::teardown() {
    if (camera) {
        if (started) camera->stop();
        camera->requestCompleted.disconnect(this);
    }
    started = false;
    {
        std::lock_guard lock(mutex);
        completed.clear();
    }
    requests.clear();
    for (auto& [buffer, m] : mapped) ::munmap(m.first, m.second);
    mapped.clear();
    if (allocator && stream) allocator->free(stream);
    allocator.reset();
    config.reset();
    if (camera && acquired) camera->release();
    acquired = false;
    camera.reset();
    stream = nullptr;
}

std::optional<cv::Mat> LibcameraSource::Impl::convert(libcamera::FrameBuffer* buffer) {
    const auto it = mapped.find(buffer);
    if (it == mapped.end() || buffer->metadata().status != libcamera::FrameMetadata::FrameSuccess) return std::nullopt;
    const auto* base = static_cast<const std::uint8_t*>(it->second.first);
    const auto& planes = buffer->planes();
    switch (format) {
    case PixelFormat::Yuyv: return yuyvToBgr(base + planes[0].offset, width, height, stride, encoding);
    case PixelFormat::Nv12: {
        const std::uint8_t* uv = planes.size() > 1
                                     ? base + planes[1].offset
                                     : base + planes[0].offset + static_cast<std::size_t>(stride) * height;
        return nv12ToBgr(base + planes[0].offset, stride, uv, stride, width, height, encoding);
    }
    case PixelFormat::Mjpeg: {
        const unsigned used = buffer->metadata().planes()[0].bytesused;
        cv::Mat img = cv::imdecode(
            cv::Mat(1, static_cast<int>(used), CV_8UC1, const_cast<std::uint8_t*>(base + planes[0].offset)),
            cv::IMREAD_COLOR);
        if (img.empty()) return std::nullopt;
        return img;
    }
    default: return std::nullopt;
    }
}

LibcameraSource::LibcameraSource(LibcameraOptions options) : impl_(std::make_unique<Impl>()) {
    impl_->options = std::move(options);
}

LibcameraSource::~LibcameraSource() {
    impl_->teardown();
    if (impl_->manager) impl_->manager->cameraRemoved.disconnect(impl_.get());
}

std::string LibcameraSource::name() const {
    return "libcamera " + (impl_->options.cameraId.empty() ? std::string("(first camera)") : impl_->options.cameraId);
}

GrabResult LibcameraSource::grab() {
    Impl& s = *impl_;
    if (!s.started) {
        if (s.waitBeforeConnect) {
            std::this_thread::sleep_for(s.backoff);
            s.backoff = std::clamp(s.backoff * 2, s.options.backoffInitial, s.options.backoffMax);
        }
        std::string why;
        try {
            why = s.connect();
        } catch (const VideoError& e) {
            why = e.what();
        }
        if (!why.empty()) {
            s.teardown();
            s.waitBeforeConnect = true;
            return {std::nullopt, {SourceStatus::Disconnected, why}};
        }
        s.waitBeforeConnect = false;
        s.backoff = std::chrono::milliseconds(0);
    }
    const auto timeout = std::chrono::milliseconds(std::max(50, static_cast<int>(3000.0 / s.options.fps)));
    libcamera::Request* request = nullptr;
    {
        std::unique_lock lock(s.mutex);
        s.ready.wait_for(lock, timeout, [&] { return s.removed || !s.completed.empty(); });
        if (s.removed) {
            lock.unlock();
            const std::string id = s.camera ? s.camera->id() : std::string("camera");
            s.teardown();
            s.waitBeforeConnect = true;
            return {std::nullopt, {SourceStatus::Disconnected, joinText("libcamera removed ", id)}};
        }
        if (s.completed.empty())
            return {std::nullopt, {SourceStatus::Stalled, joinText("no frame for ", timeout.count(), " ms")}};
        request = s.completed.front();
        s.completed.pop_front();
    }
    libcamera::FrameBuffer* buffer = request->buffers().begin()->second;
    std::optional<cv::Mat> img = s.convert(buffer);
    Frame f;
    f.timestamp = std::chrono::nanoseconds(buffer->metadata().timestamp);
    // libcamera timestamps are CLOCK_BOOTTIME-or-MONOTONIC from the sensor;
    // the moment we took it is the honest bound for latency.
    f.captured = std::chrono::steady_clock::now();
    request->reuse(libcamera::Request::ReuseBuffers);
    s.camera->queueRequest(request);
    if (!img) return {std::nullopt, {SourceStatus::Streaming, {}}};
    f.image = std::move(*img);
    f.sequence = s.sequence++;
    f.format = s.format;
    return {std::move(f), {SourceStatus::Streaming, {}}};
}

std::vector<std::string> listLibcameraCameras() {
    std::vector<std::string> ids;
    for (const auto& c : sharedManager()->cameras()) ids.push_back(c->id());
    return ids;
}

}  // namespace arcomp
