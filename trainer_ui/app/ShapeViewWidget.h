#pragma once
/// \file
/// The scope-shape view in a window (as on magnetic endoscope imaging): a
/// OffscreenGlWidget hosting render::ShapeView, the anterior and lateral panels
/// of the colon's outline and the shaft from the latest snapshot, the
/// segment holding a loop highlighted. Its caption is a label of the host.

#include "simcore/render/ShapeView.h"
#include "trainer_ui/app/OffscreenGlWidget.h"
#include "trainer_ui/app/ProcedureScene.h"
#include "trainer_ui/app/SimulationRunner.h"

#include <chrono>
#include <memory>

namespace colonosim::app {

class ShapeViewWidget : public OffscreenGlWidget {
    Q_OBJECT
public:
    ShapeViewWidget(std::shared_ptr<const ProcedureScene> scene, QWidget* parent = nullptr);
    ~ShapeViewWidget() override;

    /// The snapshot to draw next (must stay valid until the next call);
    /// schedules a repaint at most kRedrawRate times a second while the
    /// procedure runs (a paused, finished or failed state is drawn at once).
    void showSnapshot(const Snapshot* snapshot);

    /// Hz: redraws a second at most while running. The shaft's shape changes
    /// slowly beside the camera view (magnetic endoscope imaging refreshes a
    /// few to about 20 times a second); each redraw costs 3.5-4.5 ms of the
    /// GUI thread on the software rasteriser, which goes to the endoscope
    /// view's frame rate instead. Model choice.
    static constexpr double kRedrawRate = 15.0;
    [[nodiscard]] long redraws() const { return m_redraws; }

protected:
    void initializeGL() override;
    bool paintGL() override;

private:
    std::shared_ptr<const ProcedureScene> m_scene;
    std::unique_ptr<render::GlFunctions> m_gl;
    std::unique_ptr<render::ShapeView> m_view;
    const Snapshot* m_snapshot = nullptr;
    QString m_failure;
    std::chrono::steady_clock::time_point m_lastRedraw{};
    long m_redraws = 0;
};

}  // namespace colonosim::app
