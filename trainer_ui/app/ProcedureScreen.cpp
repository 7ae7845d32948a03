#include "trainer_ui/app/ProcedureScreen.h"

#include "scoring/SessionMetrics.h"
#include "simcore/devices/Gamepad.h"
#include "simcore/devices/HdcOperator.h"
#include "trainer_ui/app/EndoscopeViewWidget.h"
#include "trainer_ui/app/HeadsUpDisplay.h"
#include "trainer_ui/app/ManualOperator.h"
#include "trainer_ui/app/ShapeViewWidget.h"
#include "trainer_ui/app/SimulationRunner.h"
#include "trainer_ui/cli/SessionStore.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

#include <thread>

namespace colonosim::app {

namespace {
constexpr double kDragPixels = 150.0;  ///< mouse travel for full deflection
}  // namespace

std::pair<std::unique_ptr<procedure::Operator>, std::string> makeDriver(const ProcedureOptions& options)
{
    switch (options.driver) {
    case Driver::Keyboard: return {std::make_unique<ManualOperator>(), "keyboard"};
    case Driver::Autopilot: return {procedure::makeOperator("expert"), "scripted:expert"};
    case Driver::Gamepad: {
        auto pad = std::make_unique<devices::GamepadOperator>(0);
        std::string name = "gamepad:" + pad->name();
        return {std::move(pad), name};
    }
    case Driver::Haptic:
        return {std::make_unique<devices::HdcOperator>(options.hapticPort, devices::HapticParameters{}),
                "hdc:" + std::to_string(options.hapticPort)};
    }
    return {std::make_unique<ManualOperator>(), "keyboard"};
}

ProcedureScreen::ProcedureScreen(AppContext& context, const curricula::Task& task,
                                 std::shared_ptr<const ProcedureScene> scene, std::optional<qint64> caseId,
                                 const ProcedureOptions& options, QWidget* parent)
    : QWidget(parent), m_context(context), m_task(task), m_scene(std::move(scene)), m_options(options)
{
    setObjectName(QStringLiteral("procedureScreen"));
    setFocusPolicy(Qt::StrongFocus);
    auto [driver, device] = makeDriver(options);
    m_manual = dynamic_cast<ManualOperator*>(driver.get());
    m_session = m_context.records.beginSession(m_context.actor, caseId, task.id, device);

    auto* layout = new QVBoxLayout(this);
    auto* title = new QLabel(tr("<h2>%1</h2>").arg(QString::fromStdString(task.title).toHtmlEscaped()));
    layout->addWidget(title);
    auto* row = new QHBoxLayout;
    m_view = new EndoscopeViewWidget(m_scene);
    m_view->setObjectName(QStringLiteral("endoscopeView"));
    m_view->setFocusPolicy(Qt::NoFocus);
    m_view->installEventFilter(this);
    row->addWidget(m_view, 0, Qt::AlignTop);
    auto* side = new QVBoxLayout;
    if (task.shapeView) {
        m_shapeCaption = new QLabel(tr("Scope shape — anterior | lateral (from the patient's left)"));
        m_shapeCaption->setWordWrap(true);
        side->addWidget(m_shapeCaption);
        m_shape = new ShapeViewWidget(m_scene);
        m_shape->setObjectName(QStringLiteral("shapeView"));
        m_shape->setFocusPolicy(Qt::NoFocus);
        side->addWidget(m_shape);
    }
    m_hud = new HeadsUpDisplay(m_scene->settings.recorder.excessiveForce);
    side->addWidget(m_hud);
    auto* end = new QPushButton(tr("End procedure (Esc)"));
    end->setObjectName(QStringLiteral("endProcedure"));
    end->setFocusPolicy(Qt::NoFocus);
    connect(end, &QPushButton::clicked, this, &ProcedureScreen::endProcedure);
    side->addWidget(end);
    side->addStretch();
    row->addLayout(side, 1);
    layout->addLayout(row);
    layout->addStretch(1);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("procedureStatus"));
    layout->addWidget(m_status);
    auto* legend =
        new QLabel(options.driver == Driver::Keyboard
                       ? KeyboardControls::legend()
                       : tr("<b>Input</b>: %1. Esc ends the procedure.").arg(QString::fromStdString(device)));
    legend->setObjectName(QStringLiteral("keyLegend"));
    legend->setWordWrap(true);
    layout->addWidget(legend);

    RunnerOptions runnerOptions;
    runnerOptions.maxTime = options.timeLimit;
    runnerOptions.coverage = true;  // % mucosa visualised, for the display and the score
    m_runner = std::make_unique<SimulationRunner>(m_scene, std::move(driver), runnerOptions);
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &ProcedureScreen::tick);
    m_timer->start(1000 / kFrameRate);
    setFocus();
}

ProcedureScreen::~ProcedureScreen() = default;

double ProcedureScreen::shownInsertion() const
{
    return m_runner->snapshot().frame.input.insertion;
}

double ProcedureScreen::shownTime() const
{
    return m_runner->snapshot().frame.time;
}

long ProcedureScreen::framesDrawn() const
{
    return m_view->framesDrawn();
}

double ProcedureScreen::graphicsRate() const
{
    return m_view->framesPerSecond();
}

double ProcedureScreen::physicsRate() const
{
    return m_runner->snapshot().physicsRate;
}

void ProcedureScreen::endProcedure()
{
    m_runner->requestEnd();
}

void ProcedureScreen::endAndStore()
{
    if (m_done) {
        return;
    }
    m_runner->requestEnd();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    // The loop stops at its next step (or once it is built, if it was still
    // being prepared).
    while (!m_runner->finished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    QApplication::restoreOverrideCursor();
    finish();
}

void ProcedureScreen::sendControls()
{
    if (m_manual != nullptr) {
        m_manual->setControls(m_keys.controls());
    }
}

void ProcedureScreen::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Escape) {
        endProcedure();
        return;
    }
    if (m_manual == nullptr || event->isAutoRepeat()) {
        QWidget::keyPressEvent(event);
        return;
    }
    if (const std::uint8_t buttons = KeyboardControls::pressButtons(event->key()); buttons != 0) {
        m_manual->press(buttons);
        return;
    }
    if (event->key() == Qt::Key_Up && !m_probe) {
        m_probe = LatencyProbe{std::chrono::steady_clock::now(), m_view->lastFrameInsertion()};
    }
    if (m_keys.keyDown(event->key())) {
        sendControls();
        return;
    }
    QWidget::keyPressEvent(event);
}

void ProcedureScreen::keyReleaseEvent(QKeyEvent* event)
{
    if (m_manual == nullptr || event->isAutoRepeat() || !m_keys.keyUp(event->key())) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    sendControls();
}

bool ProcedureScreen::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_view && m_manual != nullptr) {
        if (event->type() == QEvent::MouseButtonPress) {
            m_dragStart = static_cast<QMouseEvent*>(event)->position().toPoint();
            setFocus();
            return true;
        }
        if (event->type() == QEvent::MouseMove) {
            const QPoint now = static_cast<QMouseEvent*>(event)->position().toPoint();
            m_keys.setMouse((m_dragStart.y() - now.y()) / kDragPixels,
                            (m_dragStart.x() - now.x()) / kDragPixels);
            sendControls();
            return true;
        }
        if (event->type() == QEvent::MouseButtonRelease) {
            m_keys.setMouse(0.0, 0.0);
            sendControls();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ProcedureScreen::tick()
{
    if (m_runner->poll()) {
        const Snapshot& now = m_runner->snapshot();
        m_view->showSnapshot(&now);
        if (m_shape != nullptr) {
            m_shape->showSnapshot(&now);
            m_shapeCaption->setText(tr("Scope shape — anterior | lateral (from the patient's left) — %1")
                                        .arg(HeadsUpDisplay::loopWords(now.frame.loop)));
        }
        m_hud->showSnapshot(now, m_view->framesPerSecond(), m_options.timeLimit, m_view->renderScale());
        m_status->setText(now.state == Snapshot::State::Preparing ? tr("Preparing the colon…")
                                                                  : tr("Procedure running."));
    }
    if (m_probe && m_view->lastFrameAt() > m_probe->pressed &&
        m_view->lastFrameInsertion() > m_probe->insertion) {
        m_inputLatency =
            std::chrono::duration<double, std::milli>(m_view->lastFrameAt() - m_probe->pressed).count();
        m_probe.reset();
    }
    if (m_runner->finished() && !m_done) {
        finish();
    }
}

void ProcedureScreen::finish()
{
    m_done = true;
    m_timer->stop();
    const procedure::ProcedureLoop* loop = m_runner->loop();
    if (loop == nullptr) {
        m_runner->poll();
        const QString why = QString::fromStdString(m_runner->snapshot().failure);
        m_status->setText(why);
        Q_EMIT failed(why);
        return;
    }
    m_status->setText(tr("Scoring and storing the session…"));
    try {
        scoring::ScoringContext scoringContext;
        scoringContext.colonLength = loop->colonLength();
        scoringContext.lesionsPresent = m_scene->lesionsPresent;
        scoringContext.mucosaSeen = m_runner->mucosaSeen();
        const db::SessionResult result =
            cli::completeStoredSession(m_context.records, m_context.actor, m_session, m_task.id, *loop,
                                       m_runner->recording(), scoringContext);
        Q_EMIT completed(m_session, result);
    } catch (const std::exception& error) {
        const QString why =
            tr("The session could not be stored: %1").arg(QString::fromStdString(error.what()));
        m_status->setText(why);
        Q_EMIT failed(why);
    }
}

}  // namespace colonosim::app
