#pragma once
/// \file
/// Deterministic replay of a stored session: its stored input trace played
/// back through a ReplayOperator on the session's case, in the same
/// SimulationRunner as a live procedure, with both views (the shape view is
/// always shown here) and the heads-up display. Play, pause, speed
/// (0.25x-4x), and seek: a seek re-simulates from the start as fast as the
/// loop runs, on a second runner, with a progress bar and Cancel; the shown
/// replay stays as it was until the seek completes (and when it is cancelled).

#include "simcore/procedure/InputTrace.h"
#include "simcore/procedure/Recorder.h"
#include "trainer_ui/app/AppContext.h"
#include "trainer_ui/app/ProcedureScene.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;
class QTimer;

namespace colonosim::app {

class EndoscopeViewWidget;
class HeadsUpDisplay;
class ShapeViewWidget;
class SimulationRunner;
struct Snapshot;

class ReplayScreen : public QWidget {
    Q_OBJECT
public:
    /// Loads the session's trace, case and recording through the records
    /// (so the actor's read rights apply); a failure is shown as a sentence.
    ReplayScreen(AppContext& context, qint64 session, QWidget* parent = nullptr);
    ~ReplayScreen() override;

    void play();
    void pause();
    /// Re-simulates from the start up to `seconds` (clamped to the session), then pauses there.
    void seek(double seconds);
    void cancelSeek();
    /// 0.25-4.
    void setSpeed(double speed);

    [[nodiscard]] bool ready() const { return m_runner != nullptr; }
    [[nodiscard]] bool seeking() const { return m_seekRunner != nullptr; }
    /// The snapshot shown now (null before the first).
    [[nodiscard]] const Snapshot* shown() const;
    /// The stored recording of the session (what was recorded live).
    [[nodiscard]] const procedure::Recording& recording() const { return m_recording; }
    [[nodiscard]] double duration() const;
    /// When the session could not be loaded: why, as a sentence (else empty).
    [[nodiscard]] const QString& failure() const { return m_failure; }

Q_SIGNALS:
    void closeRequested();

private:
    void tick();
    std::unique_ptr<SimulationRunner> startRunner(bool paused, double seekTo) const;
    void showSeeking(bool on);

    qint64 m_session;
    QString m_failure;
    std::shared_ptr<const ProcedureScene> m_scene;
    procedure::InputTrace m_trace;
    procedure::Recording m_recording;
    double m_speed = 1.0;
    double m_seekTarget = 0.0;
    std::unique_ptr<SimulationRunner> m_runner;
    std::unique_ptr<SimulationRunner> m_seekRunner;
    EndoscopeViewWidget* m_view = nullptr;
    ShapeViewWidget* m_shape = nullptr;
    HeadsUpDisplay* m_hud = nullptr;
    QLabel* m_time = nullptr;
    QSlider* m_slider = nullptr;
    QDoubleSpinBox* m_seekTime = nullptr;
    QComboBox* m_speedChoice = nullptr;
    QProgressBar* m_seekProgress = nullptr;
    QPushButton* m_cancel = nullptr;
    QTimer* m_timer = nullptr;
};

}  // namespace colonosim::app
