#include "trainer_ui/app/ReplayScreen.h"

#include "db/RecordingCodec.h"
#include "db/StoredTrace.h"
#include "simcore/procedure/Operator.h"
#include "trainer_ui/app/EndoscopeViewWidget.h"
#include "trainer_ui/app/HeadsUpDisplay.h"
#include "trainer_ui/app/ShapeViewWidget.h"
#include "trainer_ui/app/SimulationRunner.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace colonosim::app {

namespace {
constexpr int kSliderSteps = 1000;  ///< slider units per simulated second (1 ms)

std::vector<char> bytesOf(const QByteArray& data)
{
    return std::vector<char>(data.begin(), data.end());
}
}  // namespace

ReplayScreen::ReplayScreen(AppContext& context, qint64 session, QWidget* parent)
    : QWidget(parent), m_session(session)
{
    setObjectName(QStringLiteral("replayScreen"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("<h2>Replay of session %1</h2>").arg(session)));
    try {
        const QByteArray trace = context.records.sessionTrace(context.actor, session);
        if (trace.isEmpty()) {
            throw std::runtime_error("it has no stored input trace (it did not complete)");
        }
        m_trace = db::decodeStoredTrace(bytesOf(trace));
        m_recording = db::decodeRecording(bytesOf(context.records.sessionRecording(context.actor, session)));
        m_scene = buildScene(context.records.sessionCase(context.actor, session));
    } catch (const std::exception& error) {
        m_failure =
            tr("Session %1 cannot be replayed: %2").arg(session).arg(QString::fromStdString(error.what()));
    }
    auto* back = new QPushButton(tr("Close the replay"));
    back->setObjectName(QStringLiteral("closeReplay"));
    connect(back, &QPushButton::clicked, this, &ReplayScreen::closeRequested);
    if (!m_failure.isEmpty()) {
        auto* message = new QLabel(m_failure);
        message->setObjectName(QStringLiteral("replayFailure"));
        message->setWordWrap(true);
        layout->addWidget(message);
        layout->addStretch();
        layout->addWidget(back);
        return;
    }

    auto* views = new QHBoxLayout;
    m_view = new EndoscopeViewWidget(m_scene);
    m_view->setObjectName(QStringLiteral("replayEndoscopeView"));
    views->addWidget(m_view, 0, Qt::AlignTop);
    auto* side = new QVBoxLayout;
    side->addWidget(new QLabel(tr("Scope shape — anterior | lateral (from the patient's left)")));
    m_shape = new ShapeViewWidget(m_scene);
    m_shape->setObjectName(QStringLiteral("replayShapeView"));
    side->addWidget(m_shape);
    m_hud = new HeadsUpDisplay(m_scene->settings.recorder.excessiveForce);
    side->addWidget(m_hud);
    side->addStretch(1);
    views->addLayout(side, 1);
    layout->addLayout(views);
    layout->addStretch(1);

    auto* controls = new QHBoxLayout;
    auto* playButton = new QPushButton(tr("Play"));
    playButton->setObjectName(QStringLiteral("replayPlay"));
    connect(playButton, &QPushButton::clicked, this, &ReplayScreen::play);
    auto* pauseButton = new QPushButton(tr("Pause"));
    pauseButton->setObjectName(QStringLiteral("replayPause"));
    connect(pauseButton, &QPushButton::clicked, this, &ReplayScreen::pause);
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName(QStringLiteral("replayPosition"));
    m_slider->setRange(0, static_cast<int>(duration() * kSliderSteps));
    connect(m_slider, &QSlider::sliderReleased, this,
            [this] { seek(static_cast<double>(m_slider->value()) / kSliderSteps); });
    m_time = new QLabel;
    m_time->setObjectName(QStringLiteral("replayTime"));
    m_time->setMinimumWidth(150);
    controls->addWidget(playButton);
    controls->addWidget(pauseButton);
    controls->addWidget(m_slider, 1);
    controls->addWidget(m_time);
    layout->addLayout(controls);

    auto* more = new QHBoxLayout;
    more->addWidget(new QLabel(tr("Go to")));
    m_seekTime = new QDoubleSpinBox;
    m_seekTime->setObjectName(QStringLiteral("seekTime"));
    m_seekTime->setRange(0.0, duration());
    m_seekTime->setDecimals(2);
    m_seekTime->setSuffix(tr(" s"));
    more->addWidget(m_seekTime);
    auto* seekButton = new QPushButton(tr("Seek"));
    seekButton->setObjectName(QStringLiteral("seekButton"));
    connect(seekButton, &QPushButton::clicked, this, [this] { seek(m_seekTime->value()); });
    more->addWidget(seekButton);
    m_seekProgress = new QProgressBar;
    m_seekProgress->setObjectName(QStringLiteral("seekProgress"));
    m_seekProgress->setRange(0, 100);
    m_seekProgress->setFormat(tr("re-simulating %p%"));
    more->addWidget(m_seekProgress, 1);
    m_cancel = new QPushButton(tr("Cancel seek"));
    m_cancel->setObjectName(QStringLiteral("cancelSeek"));
    connect(m_cancel, &QPushButton::clicked, this, &ReplayScreen::cancelSeek);
    more->addWidget(m_cancel);
    more->addStretch();
    more->addWidget(new QLabel(tr("Speed")));
    m_speedChoice = new QComboBox;
    m_speedChoice->setObjectName(QStringLiteral("replaySpeed"));
    for (const double speed : {0.25, 0.5, 1.0, 2.0, 4.0}) {
        m_speedChoice->addItem(QStringLiteral("%1×").arg(speed), speed);
    }
    m_speedChoice->setCurrentIndex(2);
    connect(m_speedChoice, &QComboBox::currentIndexChanged, this,
            [this](int index) { setSpeed(m_speedChoice->itemData(index).toDouble()); });
    more->addWidget(m_speedChoice);
    more->addWidget(back);
    layout->addLayout(more);
    showSeeking(false);

    m_runner = startRunner(true, 0.0);
    m_timer = new QTimer(this);
    connect(m_timer, &QTimer::timeout, this, &ReplayScreen::tick);
    m_timer->start(1000 / 60);
}

ReplayScreen::~ReplayScreen() = default;

double ReplayScreen::duration() const
{
    return static_cast<double>(m_trace.samples.size()) * m_trace.loopStep;
}

const Snapshot* ReplayScreen::shown() const
{
    return m_runner ? &m_runner->snapshot() : nullptr;
}

std::unique_ptr<SimulationRunner> ReplayScreen::startRunner(bool paused, double seekTo) const
{
    RunnerOptions options;
    options.maxTime = duration() + 1.0;
    options.speed = m_speed;
    options.startPaused = paused;
    options.seekTo = seekTo;
    return std::make_unique<SimulationRunner>(m_scene, std::make_unique<procedure::ReplayOperator>(m_trace),
                                              options);
}

void ReplayScreen::play()
{
    if (!m_runner || seeking()) {
        return;
    }
    if (m_runner->finished()) {
        m_runner = startRunner(false, 0.0);
        return;
    }
    m_runner->setPaused(false);
}

void ReplayScreen::pause()
{
    if (m_runner) {
        m_runner->setPaused(true);
    }
}

void ReplayScreen::seek(double seconds)
{
    if (!m_runner) {
        return;
    }
    m_seekTarget = std::clamp(seconds, 0.0, duration());
    m_seekRunner = startRunner(true, m_seekTarget);
    showSeeking(true);
}

void ReplayScreen::cancelSeek()
{
    m_seekRunner.reset();
    showSeeking(false);
}

void ReplayScreen::setSpeed(double speed)
{
    m_speed = std::clamp(speed, 0.25, 4.0);
    if (m_runner) {
        m_runner->setSpeed(m_speed);
    }
}

void ReplayScreen::showSeeking(bool on)
{
    m_seekProgress->setVisible(on);
    m_cancel->setVisible(on);
    m_seekProgress->setValue(0);
}

void ReplayScreen::tick()
{
    if (m_seekRunner) {
        m_seekRunner->poll();
        const Snapshot& seek = m_seekRunner->snapshot();
        const double done = m_seekTarget > 0.0 ? seek.frame.time / m_seekTarget : 1.0;
        m_seekProgress->setValue(static_cast<int>(std::clamp(done, 0.0, 1.0) * 100.0));
        const bool arrived = seek.state == Snapshot::State::Finished ||
                             seek.state == Snapshot::State::Failed ||
                             (seek.state == Snapshot::State::Paused &&
                              seek.frame.time + 0.5 * m_trace.loopStep >= m_seekTarget);
        if (arrived) {
            m_runner = std::move(m_seekRunner);
            showSeeking(false);
        }
    }
    m_runner->poll();
    const Snapshot& now = m_runner->snapshot();
    m_view->showSnapshot(&now);
    m_shape->showSnapshot(&now);
    m_hud->showSnapshot(now, m_view->framesPerSecond(), duration(), m_view->renderScale());
    if (!m_slider->isSliderDown()) {
        m_slider->setValue(static_cast<int>(now.frame.time * kSliderSteps));
    }
    const char* state = now.state == Snapshot::State::Running    ? "playing"
                        : now.state == Snapshot::State::Paused   ? "paused"
                        : now.state == Snapshot::State::Finished ? "ended"
                                                                 : "preparing";
    m_time->setText(
        tr("%1 s of %2 s, %3").arg(now.frame.time, 0, 'f', 2).arg(duration(), 0, 'f', 1).arg(tr(state)));
}

}  // namespace colonosim::app
