#pragma once
// OpenSceneGraph rendering with no X server: an EGL context on Mesa's surfaceless
// platform (compatibility profile: Debian's OSG uses the fixed-function pipeline),
// drawing into our own framebuffer object (multisampled, resolved by a blit) and read
// back with glReadPixels. Works the same with DISPLAY set or unset.
//
// Anti-aliasing: 2, 4 or 8 samples per pixel (MSAA), kEdgeSmoothing (a plain frame
// smoothed on the CPU, ui/paint/edge_smoothing.hpp), 0 (none), or kAutoAntialiasing: 4x MSAA
// on a graphics card, edge smoothing on a software renderer (Mesa's llvmpipe draws a
// multisampled frame about 3x slower than a plain one).
//
//   HeadlessRenderer gl(1280, 720, 4);      // throws std::runtime_error saying what is missing
//   gl.setScene(osgScene.root());
//   applyCameraView(*gl.camera(), view, gl.aspect());
//   gl.render(image);                        // RGBX, top row first
#include <memory>
#include <string>
#include <vector>

#include <QImage>
#include <osg/Camera>
#include <osg/Node>

namespace ll::ui {

inline constexpr int kAutoAntialiasing = -1;
inline constexpr int kEdgeSmoothing = -2;

class HeadlessRenderer {
public:
    // width × height pixels; `antialiasing`: samples per pixel (4: 4× MSAA; 0 or 1:
    // none), kEdgeSmoothing or kAutoAntialiasing.
    HeadlessRenderer(int width, int height, int antialiasing = kAutoAntialiasing);
    ~HeadlessRenderer();
    HeadlessRenderer(const HeadlessRenderer&) = delete;
    HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    double aspect() const { return double(width_) / height_; }
    osg::Camera* camera();
    void setScene(osg::Node* root);
    void setBackground(float r, float g, float b);

    // Draws one frame into the framebuffer object and waits for it (glFinish).
    void draw();
    // Reads the last frame into `image` (Format_RGBX8888: R, G, B, 255 bytes; width ×
    // height, top row first; reallocated only when its size or format differ).
    void readBack(QImage& image);
    void render(QImage& image) {
        draw();
        readBack(image);
    }
    // The GL renderer string (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
    std::string rendererName() const;
    // What anti-aliasing is in use: "4x MSAA", "edge smoothing" or "none".
    std::string antialiasing() const;
    // Whether the renderer is a software rasteriser (llvmpipe, softpipe, swrast).
    bool softwareRenderer() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    int width_, height_;
};

}  // namespace ll::ui
