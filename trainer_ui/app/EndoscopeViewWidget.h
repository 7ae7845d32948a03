#pragma once
/// \file
/// The endoscope view in a window: an OffscreenGlWidget (OpenGL 3.3 core)
/// hosting render::EndoscopeView, drawing the latest snapshot of the loop
/// (the wall mapped from the physics nodes, seen from the tip pose) into the
/// widget's framebuffer. Counts the frames it draws (the graphics rate of
/// the HUD), and holds that rate by the resolution it draws at
/// (RenderScaleGovernor).

#include "simcore/render/EndoscopeView.h"
#include "trainer_ui/app/OffscreenGlWidget.h"
#include "trainer_ui/app/ProcedureScene.h"
#include "trainer_ui/app/RenderScaleGovernor.h"
#include "trainer_ui/app/SimulationRunner.h"

#include <QElapsedTimer>

#include <chrono>
#include <memory>

namespace colonosim::app {

class EndoscopeViewWidget : public OffscreenGlWidget {
    Q_OBJECT
public:
    /// The view's size in pixels: the video of a standard-definition endoscope (4:3).
    static constexpr int kWidth = 640;
    static constexpr int kHeight = 480;

    EndoscopeViewWidget(std::shared_ptr<const ProcedureScene> scene, QWidget* parent = nullptr);
    ~EndoscopeViewWidget() override;

    /// The snapshot to draw next (must stay valid until the next call); schedules a repaint.
    void showSnapshot(const Snapshot* snapshot);
    /// Frames drawn per wall-clock second, over the last half second or more.
    [[nodiscard]] double framesPerSecond() const { return m_fps; }
    /// Frames drawn since the widget was made.
    [[nodiscard]] long framesDrawn() const { return m_frames; }
    /// The last frame drawn: when it was finished (steady clock) and the insertion it shows (m).
    [[nodiscard]] std::chrono::steady_clock::time_point lastFrameAt() const { return m_lastFrameAt; }
    [[nodiscard]] double lastFrameInsertion() const { return m_lastFrameInsertion; }
    /// When the view failed to start (no OpenGL 3.3): the reason, as a sentence.
    [[nodiscard]] const QString& failure() const { return m_failure; }

protected:
    void initializeGL() override;
    bool paintGL() override;
    void frameShown(double start, double drawTime) override;

private:
    std::shared_ptr<const ProcedureScene> m_scene;
    std::unique_ptr<render::GlFunctions> m_gl;
    std::unique_ptr<render::EndoscopeView> m_view;
    const Snapshot* m_snapshot = nullptr;
    Eigen::Matrix3Xd m_visual;
    QString m_failure;
    RenderScaleGovernor m_governor;
    QElapsedTimer m_clock;
    long m_frames = 0;
    long m_windowFrames = 0;
    double m_fps = 0.0;
    std::chrono::steady_clock::time_point m_lastFrameAt;
    double m_lastFrameInsertion = 0.0;
    double m_drawnInsertion = 0.0;  ///< insertion of the frame being drawn, m
};

}  // namespace colonosim::app
