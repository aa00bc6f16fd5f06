#include "ui/paint/headless_renderer.hpp"

#include "ui/paint/edge_smoothing.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include <osg/GL>
#include <osgViewer/Viewer>
#include <GL/glext.h>

namespace ll::ui {
namespace {

template <class F>
F glFunction(const char* name) {
    auto f = reinterpret_cast<F>(eglGetProcAddress(name));
    if (!f) throw std::runtime_error(std::string("OpenGL: the driver lacks ") + name);
    return f;
}

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("headless OpenGL: " + what +
                             " (needs Mesa's EGL surfaceless platform: packages libegl-mesa0, libgl1-mesa-dri)");
}

}  // namespace

struct HeadlessRenderer::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    GLuint drawFbo = 0, resolveFbo = 0, colour = 0, depth = 0, resolveColour = 0;
    int samples = 0;
    bool smoothEdges = false;
    EdgeSmoothing edgeSmoothing;
    osg::ref_ptr<osgViewer::Viewer> viewer;
    std::vector<unsigned char> pixels;  // bottom row first, as GL reads them

    PFNGLGENFRAMEBUFFERSPROC genFramebuffers = nullptr;
    PFNGLBINDFRAMEBUFFERPROC bindFramebuffer = nullptr;
    PFNGLDELETEFRAMEBUFFERSPROC deleteFramebuffers = nullptr;
    PFNGLGENRENDERBUFFERSPROC genRenderbuffers = nullptr;
    PFNGLBINDRENDERBUFFERPROC bindRenderbuffer = nullptr;
    PFNGLDELETERENDERBUFFERSPROC deleteRenderbuffers = nullptr;
    PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC renderbufferStorageMultisample = nullptr;
    PFNGLFRAMEBUFFERRENDERBUFFERPROC framebufferRenderbuffer = nullptr;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC checkFramebufferStatus = nullptr;
    PFNGLBLITFRAMEBUFFERPROC blitFramebuffer = nullptr;

    void makeCurrent() {
        if (eglGetCurrentContext() != context) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
    }

    // A framebuffer with a colour (and optionally depth) renderbuffer of `samples`.
    GLuint framebuffer(int width, int height, int s, GLuint& colourBuffer, GLuint* depthBuffer) {
        GLuint fbo = 0;
        genFramebuffers(1, &fbo);
        bindFramebuffer(GL_FRAMEBUFFER, fbo);
        genRenderbuffers(1, &colourBuffer);
        bindRenderbuffer(GL_RENDERBUFFER, colourBuffer);
        renderbufferStorageMultisample(GL_RENDERBUFFER, s, GL_RGBA8, width, height);
        framebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colourBuffer);
        if (depthBuffer) {
            genRenderbuffers(1, depthBuffer);
            bindRenderbuffer(GL_RENDERBUFFER, *depthBuffer);
            renderbufferStorageMultisample(GL_RENDERBUFFER, s, GL_DEPTH24_STENCIL8, width, height);
            framebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, *depthBuffer);
        }
        if (checkFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            fail("framebuffer object incomplete (" + std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(s) +
                 " samples)");
        return fbo;
    }
};

HeadlessRenderer::HeadlessRenderer(int width, int height, int antialiasing)
    : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
    Impl& d = *impl_;
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) fail("EGL has no eglGetPlatformDisplayEXT");
    d.display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (d.display == EGL_NO_DISPLAY || !eglInitialize(d.display, &major, &minor)) fail("no surfaceless EGL display");
    if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL cannot bind desktop OpenGL");
    const EGLint configAttributes[] =
        {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglChooseConfig(d.display, configAttributes, &config, 1, &configs);
    // No version asked: Mesa gives its highest compatibility-profile context, which
    // the fixed-function OSG needs (a core profile draws nothing).
    const EGLint contextAttributes[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    d.context = eglCreateContext(d.display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
    if (d.context == EGL_NO_CONTEXT) fail("no compatibility-profile OpenGL context");
    if (!eglMakeCurrent(d.display, EGL_NO_SURFACE, EGL_NO_SURFACE, d.context)) fail("cannot make the context current without a surface");

    d.genFramebuffers = glFunction<PFNGLGENFRAMEBUFFERSPROC>("glGenFramebuffers");
    d.bindFramebuffer = glFunction<PFNGLBINDFRAMEBUFFERPROC>("glBindFramebuffer");
    d.deleteFramebuffers = glFunction<PFNGLDELETEFRAMEBUFFERSPROC>("glDeleteFramebuffers");
    d.genRenderbuffers = glFunction<PFNGLGENRENDERBUFFERSPROC>("glGenRenderbuffers");
    d.bindRenderbuffer = glFunction<PFNGLBINDRENDERBUFFERPROC>("glBindRenderbuffer");
    d.deleteRenderbuffers = glFunction<PFNGLDELETERENDERBUFFERSPROC>("glDeleteRenderbuffers");
    d.renderbufferStorageMultisample = glFunction<PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC>("glRenderbufferStorageMultisample");
    d.framebufferRenderbuffer = glFunction<PFNGLFRAMEBUFFERRENDERBUFFERPROC>("glFramebufferRenderbuffer");
    d.checkFramebufferStatus = glFunction<PFNGLCHECKFRAMEBUFFERSTATUSPROC>("glCheckFramebufferStatus");
    d.blitFramebuffer = glFunction<PFNGLBLITFRAMEBUFFERPROC>("glBlitFramebuffer");

    GLint maxSamples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    int samples = antialiasing;
    if (antialiasing == kAutoAntialiasing) samples = softwareRenderer() ? kEdgeSmoothing : 4;
    d.smoothEdges = samples == kEdgeSmoothing;
    d.samples = samples > 1 ? std::min(samples, int(maxSamples)) : 0;
    d.drawFbo = d.framebuffer(width, height, d.samples, d.colour, &d.depth);
    if (d.samples > 0) d.resolveFbo = d.framebuffer(width, height, 0, d.resolveColour, nullptr);
    d.bindFramebuffer(GL_FRAMEBUFFER, d.drawFbo);

    d.viewer = new osgViewer::Viewer;
    d.viewer->setThreadingModel(osgViewer::Viewer::SingleThreaded);
    osgViewer::GraphicsWindowEmbedded* window = d.viewer->setUpViewerAsEmbeddedInWindow(0, 0, width, height);
    window->setDefaultFboId(d.drawFbo);
    osg::Camera* camera = d.viewer->getCamera();
    camera->setDrawBuffer(GL_COLOR_ATTACHMENT0);
    camera->setReadBuffer(GL_COLOR_ATTACHMENT0);
    camera->setClearColor(osg::Vec4(0.93f, 0.94f, 0.96f, 1.0f));
    camera->setViewport(0, 0, width, height);
    d.viewer->setCameraManipulator(nullptr);
    d.viewer->setKeyEventSetsDone(0);
    d.viewer->realize();
}

HeadlessRenderer::~HeadlessRenderer() {
    Impl& d = *impl_;
    d.makeCurrent();
    d.viewer = nullptr;  // releases OSG's GL objects while the context is current
    d.deleteFramebuffers(1, &d.drawFbo);
    d.deleteRenderbuffers(1, &d.colour);
    d.deleteRenderbuffers(1, &d.depth);
    if (d.resolveFbo) {
        d.deleteFramebuffers(1, &d.resolveFbo);
        d.deleteRenderbuffers(1, &d.resolveColour);
    }
    eglMakeCurrent(d.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(d.display, d.context);
    eglTerminate(d.display);
}

osg::Camera* HeadlessRenderer::camera() { return impl_->viewer->getCamera(); }

void HeadlessRenderer::setScene(osg::Node* root) { impl_->viewer->setSceneData(root); }

void HeadlessRenderer::setBackground(float r, float g, float b) { camera()->setClearColor(osg::Vec4(r, g, b, 1)); }

std::string HeadlessRenderer::rendererName() const {
    impl_->makeCurrent();
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "?";
}

std::string HeadlessRenderer::antialiasing() const {
    if (impl_->smoothEdges) return "edge smoothing";
    return impl_->samples > 1 ? std::to_string(impl_->samples) + "x MSAA" : "none";
}

bool HeadlessRenderer::softwareRenderer() const {
    const std::string name = rendererName();
    for (const char* software : {"llvmpipe", "softpipe", "swrast"})
        if (name.find(software) != std::string::npos) return true;
    return false;
}

void HeadlessRenderer::draw() {
    Impl& d = *impl_;
    d.makeCurrent();
    d.bindFramebuffer(GL_FRAMEBUFFER, d.drawFbo);
    d.viewer->frame();
    glFinish();
}

void HeadlessRenderer::readBack(QImage& image) {
    Impl& d = *impl_;
    d.makeCurrent();
    if (d.samples > 0) {
        d.bindFramebuffer(GL_READ_FRAMEBUFFER, d.drawFbo);
        d.bindFramebuffer(GL_DRAW_FRAMEBUFFER, d.resolveFbo);
        d.blitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        d.bindFramebuffer(GL_READ_FRAMEBUFFER, d.resolveFbo);
    } else {
        d.bindFramebuffer(GL_READ_FRAMEBUFFER, d.drawFbo);
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    const std::size_t row = std::size_t(width_) * 4;
    d.pixels.resize(row * height_);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, d.pixels.data());
    d.bindFramebuffer(GL_FRAMEBUFFER, d.drawFbo);
    if (image.width() != width_ || image.height() != height_ || image.format() != QImage::Format_RGBX8888)
        image = QImage(width_, height_, QImage::Format_RGBX8888);
    // Flip (GL's rows are bottom-up) and make it opaque (blended trails and labels
    // leave alpha below 1 where they were drawn).
    for (int y = 0; y < height_; ++y) {
        unsigned char* line = image.scanLine(y);
        std::memcpy(line, d.pixels.data() + row * (height_ - 1 - y), row);
        for (std::size_t x = 3; x < row; x += 4) line[x] = 255;
    }
    if (d.smoothEdges) d.edgeSmoothing.apply(image);
}

}  // namespace ll::ui
