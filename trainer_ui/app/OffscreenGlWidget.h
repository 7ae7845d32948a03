#pragma once
/// \file
/// A plain (raster) widget that draws its picture with OpenGL off screen: its
/// own OpenGL context, an offscreen surface and a framebuffer object of the
/// widget's size; each paint event renders into the framebuffer
/// (paintGL()), reads the pixels back and paints them as an image.
///
/// Why not QOpenGLWidget: one QOpenGLWidget turns its whole top-level window
/// into an OpenGL surface, which Qt composes on every frame (the window's
/// raster content and each widget's texture, then a swap of the whole
/// window). On the software rasteriser that composition of the trainer's
/// 1400x900 window cost 14-20 ms a frame, more than half of what the
/// endoscope view's own draw costs; the readback of a 640x480 view costs
/// about a millisecond, and the window stays raster (only what changed is
/// flushed). The widget also grabs like any other (screenshots).

#include <QImage>
#include <QWidget>

#include <memory>

class QOpenGLContext;
class QOffscreenSurface;
class QOpenGLFramebufferObject;

namespace colonosim::app {

class OffscreenGlWidget : public QWidget {
    Q_OBJECT
public:
    explicit OffscreenGlWidget(QWidget* parent = nullptr);
    ~OffscreenGlWidget() override;

    /// The scale the widget draws at, each side (see setRenderScale()).
    [[nodiscard]] double renderScale() const { return m_renderScale; }

protected:
    /// Called once, with the context current, before the first paintGL().
    virtual void initializeGL() = 0;
    /// Draws into framebufferObject(), with the context current and the
    /// framebuffer bound. Returns false when it drew nothing with OpenGL
    /// (it may then have painted the widget with a QPainter of its own).
    virtual bool paintGL() = 0;
    /// Called after a frame paintGL() drew has been painted on the widget:
    /// when its paint event began and how long it took, readback and
    /// painting included (s, steady clock).
    virtual void frameShown(double /*start*/, double /*drawTime*/) {}
    /// The framebuffer object to draw into (OpenGL name), during paintGL().
    [[nodiscard]] unsigned framebufferObject() const;
    /// The framebuffer's size in pixels: the widget's, times the device pixel
    /// ratio and the render scale.
    [[nodiscard]] QSize framebufferSize() const;
    /// Draws into a framebuffer `scale` (0.25-1) times the widget's size on
    /// each side and paints it stretched over the widget, smoothly filtered:
    /// fewer pixels to rasterise for a softer picture.
    void setRenderScale(double scale);
    /// Makes the widget's context current (e.g. to release its resources).
    /// False when the context could not be made (no OpenGL 3.3).
    bool makeCurrent();
    void doneCurrent();
    /// Why the context could not be made, as a sentence; empty when it was.
    [[nodiscard]] const QString& contextFailure() const { return m_contextFailure; }

    void paintEvent(QPaintEvent* event) override;

private:
    /// Creates the context and surface on first use; false when that failed.
    bool ensureContext();

    std::unique_ptr<QOpenGLContext> m_context;
    std::unique_ptr<QOffscreenSurface> m_surface;
    std::unique_ptr<QOpenGLFramebufferObject> m_fbo;
    QImage m_image;  ///< the last frame read back, bottom row first
    double m_renderScale = 1.0;
    bool m_initialized = false;
    QString m_contextFailure;
};

}  // namespace colonosim::app
