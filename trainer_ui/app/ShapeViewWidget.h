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

#include <memory>

namespace colonosim::app {

class ShapeViewWidget : public OffscreenGlWidget {
    Q_OBJECT
public:
    ShapeViewWidget(std::shared_ptr<const ProcedureScene> scene, QWidget* parent = nullptr);
    ~ShapeViewWidget() override;

    /// The snapshot to draw next (must stay valid until the next call); schedules a repaint.
    void showSnapshot(const Snapshot* snapshot);

protected:
    void initializeGL() override;
    bool paintGL() override;

private:
    std::shared_ptr<const ProcedureScene> m_scene;
    std::unique_ptr<render::GlFunctions> m_gl;
    std::unique_ptr<render::ShapeView> m_view;
    const Snapshot* m_snapshot = nullptr;
    QString m_failure;
};

}  // namespace colonosim::app
