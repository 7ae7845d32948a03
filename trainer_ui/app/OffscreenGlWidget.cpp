#include "trainer_ui/app/OffscreenGlWidget.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QSurfaceFormat>

#include <algorithm>
#include <chrono>
#include <cmath>

#ifndef GL_BGRA
#define GL_BGRA 0x80E1
#endif

namespace colonosim::app {

OffscreenGlWidget::OffscreenGlWidget(QWidget* parent) : QWidget(parent)
{
    // Every pixel is painted from the framebuffer: Qt need not clear behind it.
    setAttribute(Qt::WA_OpaquePaintEvent);
}

OffscreenGlWidget::~OffscreenGlWidget()
{
    if (m_context && m_context->makeCurrent(m_surface.get())) {
        m_fbo.reset();  // its framebuffer belongs to this context
        m_context->doneCurrent();
    }
}

bool OffscreenGlWidget::ensureContext()
{
    if (m_context) {
        return true;
    }
    if (!m_contextFailure.isEmpty()) {
        return false;
    }
    const QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    auto surface = std::make_unique<QOffscreenSurface>();
    surface->setFormat(format);
    surface->create();
    auto context = std::make_unique<QOpenGLContext>();
    context->setFormat(format);
    if (!surface->isValid() || !context->create() || !context->makeCurrent(surface.get())) {
        m_contextFailure = tr("No OpenGL %1.%2 context could be made for the view.")
                               .arg(format.majorVersion())
                               .arg(format.minorVersion());
        return false;
    }
    context->doneCurrent();
    m_surface = std::move(surface);
    m_context = std::move(context);
    return true;
}

unsigned OffscreenGlWidget::framebufferObject() const
{
    return m_fbo ? m_fbo->handle() : 0U;
}

QSize OffscreenGlWidget::framebufferSize() const
{
    const double scale = devicePixelRatioF() * m_renderScale;
    return {std::max(1, static_cast<int>(std::lround(width() * scale))),
            std::max(1, static_cast<int>(std::lround(height() * scale)))};
}

void OffscreenGlWidget::setRenderScale(double scale)
{
    m_renderScale = std::clamp(scale, 0.25, 1.0);
}

bool OffscreenGlWidget::makeCurrent()
{
    return m_context && m_context->makeCurrent(m_surface.get());
}

void OffscreenGlWidget::doneCurrent()
{
    if (m_context) {
        m_context->doneCurrent();
    }
}

void OffscreenGlWidget::paintEvent(QPaintEvent* /*event*/)
{
    using Clock = std::chrono::steady_clock;
    const Clock::time_point began = Clock::now();
    if (!ensureContext()) {
        QPainter painter(this);
        painter.fillRect(rect(), Qt::black);
        painter.setPen(QColor(230, 230, 230));
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, m_contextFailure);
        return;
    }
    const qreal ratio = devicePixelRatioF();
    const QSize size = framebufferSize();
    m_context->makeCurrent(m_surface.get());
    if (!m_fbo || m_fbo->size() != size) {
        m_fbo =
            std::make_unique<QOpenGLFramebufferObject>(size, QOpenGLFramebufferObject::CombinedDepthStencil);
        m_image = QImage(size, QImage::Format_RGB32);
    }
    if (!m_initialized) {
        initializeGL();
        m_initialized = true;
    }
    m_fbo->bind();
    const bool drew = paintGL();
    if (drew) {
        // BGRA bytes are Format_RGB32's own order on a little-endian machine:
        // no conversion; the rows come bottom first and are flipped below.
        m_fbo->bind();
        QOpenGLFunctions* gl = m_context->functions();
        gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->glReadPixels(0, 0, size.width(), size.height(), GL_BGRA, GL_UNSIGNED_BYTE, m_image.bits());
    }
    m_fbo->release();
    m_context->doneCurrent();
    if (drew) {
        QImage shown = m_image.mirrored(false, true);
        QPainter painter(this);
        if (m_renderScale < 1.0) {
            painter.setRenderHint(QPainter::SmoothPixmapTransform);
            painter.drawImage(QRectF(rect()), shown);
        } else {
            shown.setDevicePixelRatio(ratio);
            painter.drawImage(QPointF(0.0, 0.0), shown);
        }
        painter.end();
        const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
        frameShown(seconds(began.time_since_epoch()), seconds(Clock::now() - began));
    }
}

}  // namespace colonosim::app
