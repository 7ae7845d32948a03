#include "trainer_ui/app/EndoscopeViewWidget.h"

#include "trainer_ui/app/GlLoader.h"

#include <QOpenGLContext>
#include <QPainter>

namespace colonosim::app {

EndoscopeViewWidget::EndoscopeViewWidget(std::shared_ptr<const ProcedureScene> scene, QWidget* parent)
    : OffscreenGlWidget(parent), m_scene(std::move(scene))
{
    setFixedSize(kWidth, kHeight);
    m_clock.start();
}

EndoscopeViewWidget::~EndoscopeViewWidget()
{
    if (makeCurrent()) {  // the view's OpenGL objects belong to the widget's context
        m_view.reset();
        doneCurrent();
    }
}

void EndoscopeViewWidget::showSnapshot(const Snapshot* snapshot)
{
    m_snapshot = snapshot;
    update();
}

void EndoscopeViewWidget::initializeGL()
{
    try {
        m_gl = loadQtGlFunctions();
        m_view = std::make_unique<render::EndoscopeView>(*m_gl, m_scene->surface, render::RenderParameters{});
    } catch (const std::exception& error) {
        m_failure = tr("The endoscope view cannot be drawn: %1").arg(QString::fromStdString(error.what()));
        m_view.reset();
    }
}

bool EndoscopeViewWidget::paintGL()
{
    const int width = framebufferSize().width();
    const int height = framebufferSize().height();
    if (!m_view || m_snapshot == nullptr || m_snapshot->wall.cols() == 0) {
        QPainter painter(this);
        painter.fillRect(rect(), Qt::black);
        painter.setPen(QColor(230, 230, 230));
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                         m_failure.isEmpty() ? tr("Preparing the colon…") : m_failure);
        return false;
    }
    m_scene->mapping.apply(m_snapshot->wall, m_visual);
    m_view->setWallPositions(m_visual);
    m_view->setBleedingMarks(m_snapshot->bleedingMarks);
    m_view->render({m_snapshot->tip.position, m_snapshot->tip.rotation},
                   {m_snapshot->lensSoiling, 0.0, m_snapshot->frame.lensWallDistance}, width, height,
                   framebufferObject());
    m_drawnInsertion = m_snapshot->frame.input.insertion;
    if (m_frames == 0) {
        m_clock.restart();  // the rate counts from the first frame drawn
    }
    ++m_frames;
    ++m_windowFrames;
    const double elapsed = static_cast<double>(m_clock.elapsed()) / 1000.0;
    if (elapsed >= 0.5) {
        m_fps = static_cast<double>(m_windowFrames) / elapsed;
        m_windowFrames = 0;
        m_clock.restart();
    }
    return true;
}

void EndoscopeViewWidget::frameShown(double start, double drawTime)
{
    setRenderScale(m_governor.frameDrawn(start, drawTime));
    m_lastFrameAt = std::chrono::steady_clock::now();
    m_lastFrameInsertion = m_drawnInsertion;
}

}  // namespace colonosim::app
