#pragma once
/// \file
/// The procedure screen: the endoscope view, the scope-shape view (when the
/// task allows it), the heads-up display and the key legend. The loop runs
/// on a SimulationRunner's thread; the screen polls its newest snapshot at
/// kFrameRate and hands the keyboard and mouse to it through a
/// ManualOperator. The session row is inserted as running before the first
/// step (a crash leaves it to be marked aborted); at the end the session is
/// scored and stored through cli::completeStoredSession, the path of
/// `colonosim run --user`.

#include "curricula/Curriculum.h"
#include "db/Records.h"
#include "simcore/procedure/Operator.h"
#include "trainer_ui/app/AppContext.h"
#include "trainer_ui/app/KeyboardControls.h"
#include "trainer_ui/app/ProcedureScene.h"

#include <QWidget>

#include <chrono>
#include <limits>
#include <memory>
#include <optional>

class QLabel;
class QTimer;

namespace colonosim::app {

class EndoscopeViewWidget;
class HeadsUpDisplay;
class ManualOperator;
class ShapeViewWidget;
class SimulationRunner;

/// Who drives the scope.
enum class Driver { Keyboard, Gamepad, Haptic, Autopilot };

struct ProcedureOptions {
    Driver driver = Driver::Keyboard;
    int hapticPort = 18944;    ///< the colonosim-hdc connection's TCP port (loopback)
    double timeLimit = 600.0;  ///< s simulated: the run ends there
};

/// The operator for `options` and the device name stored with the session.
/// Throws devices::DeviceError (no gamepad, port in use) with a sentence.
[[nodiscard]] std::pair<std::unique_ptr<procedure::Operator>, std::string>
makeDriver(const ProcedureOptions& options);

class ProcedureScreen : public QWidget {
    Q_OBJECT
public:
    static constexpr int kFrameRate = 60;  ///< UI polls per second

    /// Inserts the session (running) and starts the loop. Throws db errors.
    ProcedureScreen(AppContext& context, const curricula::Task& task,
                    std::shared_ptr<const ProcedureScene> scene, std::optional<qint64> caseId,
                    const ProcedureOptions& options, QWidget* parent = nullptr);
    ~ProcedureScreen() override;

    [[nodiscard]] qint64 session() const { return m_session; }
    /// The insertion shown now, m (what the HUD shows).
    [[nodiscard]] double shownInsertion() const;
    /// The simulated time shown now, s.
    [[nodiscard]] double shownTime() const;
    /// Endoscope-view frames drawn so far.
    [[nodiscard]] long framesDrawn() const;
    [[nodiscard]] double graphicsRate() const;
    [[nodiscard]] double physicsRate() const;
    /// Input-to-display latency of the last insertion key press: from the key press to the end of
    /// the first endoscope frame drawn with the scope moved, ms (NaN until measured).
    [[nodiscard]] double inputLatency() const { return m_inputLatency; }
    /// Ends the procedure as Esc does.
    void endProcedure();
    /// Ends the procedure now and stores its session (emits completed or
    /// failed before it returns); nothing when it has already ended.
    void endAndStore();

Q_SIGNALS:
    /// The session was stored; `result` is what was stored.
    void completed(qint64 session, const colonosim::db::SessionResult& result);
    /// The procedure could not run or be stored; `message` says why.
    void failed(const QString& message);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void tick();
    void finish();
    void sendControls();

    AppContext& m_context;
    curricula::Task m_task;
    std::shared_ptr<const ProcedureScene> m_scene;
    ProcedureOptions m_options;
    qint64 m_session = 0;
    ManualOperator* m_manual = nullptr;  ///< owned by the runner; null unless the keyboard drives
    KeyboardControls m_keys;
    QPoint m_dragStart;
    std::unique_ptr<SimulationRunner> m_runner;
    EndoscopeViewWidget* m_view = nullptr;
    ShapeViewWidget* m_shape = nullptr;
    QLabel* m_shapeCaption = nullptr;
    HeadsUpDisplay* m_hud = nullptr;
    QLabel* m_status = nullptr;
    QTimer* m_timer = nullptr;
    bool m_done = false;
    struct LatencyProbe {
        std::chrono::steady_clock::time_point pressed;
        double insertion;  ///< m, shown when the key went down
    };
    std::optional<LatencyProbe> m_probe;
    double m_inputLatency = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace colonosim::app
