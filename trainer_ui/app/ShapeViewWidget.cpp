#include "trainer_ui/app/ShapeViewWidget.h"

#include "trainer_ui/app/GlLoader.h"

#include <QPainter>

namespace colonosim::app {

ShapeViewWidget::ShapeViewWidget(std::shared_ptr<const ProcedureScene> scene, QWidget* parent)
    : OffscreenGlWidget(parent), m_scene(std::move(scene))
{
    setMinimumSize(320, 160);
    setMaximumSize(560, 280);
}

ShapeViewWidget::~ShapeViewWidget()
{
    if (makeCurrent()) {  // the view's OpenGL objects belong to the widget's context
        m_view.reset();
        doneCurrent();
    }
}

void ShapeViewWidget::showSnapshot(const Snapshot* snapshot)
{
    m_snapshot = snapshot;
    const auto now = std::chrono::steady_clock::now();
    const bool running = snapshot != nullptr && snapshot->state == Snapshot::State::Running;
    if (running && now - m_lastRedraw < std::chrono::duration<double>(1.0 / kRedrawRate)) {
        return;  // drawn by a later snapshot
    }
    m_lastRedraw = now;
    ++m_redraws;
    update();
}

void ShapeViewWidget::initializeGL()
{
    try {
        m_gl = loadQtGlFunctions();
        m_view = std::make_unique<render::ShapeView>(*m_gl);
    } catch (const std::exception& error) {
        m_failure = tr("The scope-shape view cannot be drawn: %1").arg(QString::fromStdString(error.what()));
        m_view.reset();
    }
}

bool ShapeViewWidget::paintGL()
{
    if (!m_view || m_snapshot == nullptr || m_snapshot->scopeNodes.empty()) {
        QPainter painter(this);
        painter.fillRect(rect(), Qt::black);
        painter.setPen(QColor(230, 230, 230));
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                         m_failure.isEmpty() ? tr("Preparing the scope…") : m_failure);
        return false;
    }
    const int width = static_cast<int>(this->width() * devicePixelRatioF());
    const int height = static_cast<int>(this->height() * devicePixelRatioF());
    m_view->render(m_scene->anatomy.centreline, m_snapshot->scopeNodes, m_snapshot->loopSegment,
                   m_scene->settings.scope.outerDiameter, width, height, framebufferObject());
    return true;
}

}  // namespace colonosim::app
