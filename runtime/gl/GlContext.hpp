#pragma once
// An OpenGL context that is current on this thread, with its entry points
// loaded (see GlApi.hpp). Two kinds: HeadlessContext (EGL, no window; draws
// into RenderTargets) and WindowContext (GLFW; presents with swap()).
//
//   auto ctx = HeadlessContext::create(GlRequest::Auto);  // gl33, else es3
//   ctx->api();   // what we got

#include "runtime/gl/GlApi.hpp"

#include <memory>
#include <string>

namespace arcomp {

// Which API to ask for; Auto tries desktop GL 3.3 core, then ES 3.0.
enum class GlRequest { Auto, Gl33, Es3 };
GlRequest parseGlRequest(const std::string& text);  // throws InputError-like std::invalid_argument

class GlContext {
public:
    virtual ~GlContext() = default;
    GlApiKind api() const { return api_; }
    virtual void makeCurrent() = 0;

protected:
    GlApiKind api_ = GlApiKind::Gl33;
};

class HeadlessContext final : public GlContext {
public:
    // Throws std::runtime_error saying what was tried when no context can be made.
    static std::unique_ptr<HeadlessContext> create(GlRequest request);
    ~HeadlessContext() override;
    void makeCurrent() override;

private:
    HeadlessContext() = default;
    bool tryCreate(GlApiKind kind, std::string& why);
    void* display_ = nullptr;
    void* context_ = nullptr;
};

}  // namespace arcomp
