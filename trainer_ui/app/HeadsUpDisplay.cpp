#include "trainer_ui/app/HeadsUpDisplay.h"

#include "simcore/procedure/Discomfort.h"

#include <QFormLayout>
#include <QLabel>
#include <QProgressBar>

#include <algorithm>
#include <cmath>

namespace colonosim::app {

namespace {
constexpr double kForceScale = 30.0;  ///< N at the gauge's full scale (twice the excessive level)

QString clock(double seconds)
{
    const int whole = static_cast<int>(seconds);
    return QStringLiteral("%1:%2.%3")
        .arg(whole / 60)
        .arg(whole % 60, 2, 10, QLatin1Char('0'))
        .arg(static_cast<int>((seconds - whole) * 10.0));
}

QProgressBar* gauge(const char* name, int maximum)
{
    auto* bar = new QProgressBar;
    bar->setObjectName(QString::fromLatin1(name));
    bar->setRange(0, maximum);
    bar->setTextVisible(false);
    bar->setMinimumWidth(180);
    bar->setMaximumWidth(320);
    return bar;
}

/// Sets the gauge's colour. A style sheet is parsed and the widget
/// re-polished on every call, equal or not, and the display updates up to
/// 60 times a second: only a change is set.
void colour(QProgressBar* bar, const char* chunk)
{
    const QString wanted = QString::fromLatin1(chunk);
    if (bar->property("chunkColour").toString() == wanted) {
        return;
    }
    bar->setProperty("chunkColour", wanted);
    bar->setStyleSheet(
        QStringLiteral("QProgressBar { border: 1px solid #777; border-radius: 3px; background: "
                       "#2b2b2b; height: 14px; } QProgressBar::chunk { background: %1; }")
            .arg(wanted));
}
}  // namespace

HeadsUpDisplay::HeadsUpDisplay(double excessiveForce, QWidget* parent)
    : QWidget(parent), m_excessiveForce(excessiveForce)
{
    setObjectName(QStringLiteral("headsUpDisplay"));
    auto* form = new QFormLayout(this);
    form->setLabelAlignment(Qt::AlignRight);
    m_depth = new QLabel(tr("0.0 cm"));
    m_depth->setObjectName(QStringLiteral("insertionDepth"));
    m_force = gauge("handleForceGauge", static_cast<int>(kForceScale * 10.0));
    m_forceText = new QLabel;
    m_comfort = gauge("comfortMeter", 100);
    m_comfortText = new QLabel;
    m_loop = new QLabel;
    m_loop->setObjectName(QStringLiteral("loopIndicator"));
    m_timer = new QLabel;
    m_timer->setObjectName(QStringLiteral("procedureTimer"));
    m_rates = new QLabel;
    m_rates->setObjectName(QStringLiteral("rates"));
    m_mucosa = new QLabel;
    m_mucosa->setObjectName(QStringLiteral("mucosaSeen"));
    form->addRow(tr("Insertion"), m_depth);
    form->addRow(tr("Handle force"), m_force);
    form->addRow(QString(), m_forceText);
    form->addRow(tr("Comfort"), m_comfort);
    form->addRow(QString(), m_comfortText);
    form->addRow(tr("Loop"), m_loop);
    form->addRow(tr("Mucosa seen"), m_mucosa);
    form->addRow(tr("Time"), m_timer);
    form->addRow(tr("Rates"), m_rates);
    showSnapshot(Snapshot{}, 0.0, 0.0);
}

QString HeadsUpDisplay::comfortWords(int scale)
{
    switch (scale) {
    case 1: return tr("1 comfortable");
    case 2: return tr("2 minimal discomfort");
    case 3: return tr("3 mild discomfort");
    case 4: return tr("4 moderate discomfort");
    default: return tr("5 severe discomfort");
    }
}

bool HeadsUpDisplay::behindRealTime(double rate, double targetRate)
{
    // A rate of 0 is none measured yet (the loop's first half second, or a
    // device that has not sent a frame): nothing is said of it.
    return targetRate > 0.0 && rate > 0.0 && rate < kBehindShare * targetRate;
}

QString HeadsUpDisplay::physicsWords(double rate, double targetRate, double speed)
{
    const QString words = tr("physics %1 Hz").arg(rate, 0, 'f', 0);
    if (!behindRealTime(rate, targetRate)) {
        return words;
    }
    // The share is floored, so that 94.6% does not read as the 95% that would not be said.
    const QString share = QString::number(std::floor(100.0 * rate / targetRate), 'f', 0);
    return speed == 1.0 ? tr("%1, %2% of real time").arg(words, share)
                        : tr("%1, %2% of %3x real time").arg(words, share).arg(speed, 0, 'g', 3);
}

QString HeadsUpDisplay::loopWords(procedure::LoopKind kind)
{
    switch (kind) {
    case procedure::LoopKind::None: return tr("no loop");
    case procedure::LoopKind::N: return tr("sigmoid N-loop");
    case procedure::LoopKind::Alpha: return tr("alpha loop");
    case procedure::LoopKind::ReverseAlpha: return tr("reverse alpha loop");
    case procedure::LoopKind::GammaDeepTransverse: return tr("gamma / deep transverse loop");
    case procedure::LoopKind::ReverseSplenic: return tr("reverse splenic loop");
    }
    return tr("no loop");
}

void HeadsUpDisplay::showSnapshot(const Snapshot& snapshot, double graphicsRate, double timeLimit,
                                  double viewScale)
{
    const procedure::ProcedureFrame& frame = snapshot.frame;
    // Below the display's resolution a force reads 0.0, never -0.0.
    const double force = std::abs(frame.handleForce) < 0.05 ? 0.0 : frame.handleForce;
    m_force->setValue(static_cast<int>(std::clamp(std::abs(force), 0.0, kForceScale) * 10.0));
    colour(m_force, std::abs(force) >= m_excessiveForce ? "#e0463c" : "#3fa34d");
    m_comfort->setValue(static_cast<int>(std::clamp(frame.discomfort, 0.0, 10.0) * 10.0));
    const int scale = procedure::comfortScale(frame.discomfort);
    colour(m_comfort, scale >= 4 ? "#e0463c" : (scale == 3 ? "#e0a43c" : "#3fa34d"));
    m_loop->setText(loopWords(frame.loop));
    const QString loopStyle =
        frame.loop == procedure::LoopKind::None
            ? QStringLiteral("color: #3fa34d; font-weight: bold;")
            : QStringLiteral("color: white; background: #c0392b; font-weight: bold; padding: 2px;");
    if (m_loop->styleSheet() != loopStyle) {  // re-polished on every set: only a change
        m_loop->setStyleSheet(loopStyle);
    }

    const bool running = snapshot.state == Snapshot::State::Running;
    if (running && m_textState == snapshot.state && m_textShown.elapsed() < 1000 / kTextRate) {
        return;
    }
    m_textShown.restart();
    m_textState = snapshot.state;
    m_depth->setText(tr("%1 cm").arg(frame.input.insertion * 100.0, 0, 'f', 1));
    // The gauge shows the magnitude; the words say which way it acts (+ resists insertion).
    const QString direction = force > 0.0   ? tr(", resisting insertion")
                              : force < 0.0 ? tr(", resisting withdrawal")
                                            : QString();
    m_forceText->setText(tr("%1 N%2 (excessive at %3 N)")
                             .arg(std::abs(force), 0, 'f', 1)
                             .arg(direction)
                             .arg(m_excessiveForce, 0, 'f', 0));
    m_comfortText->setText(tr("%1 / 10 — %2").arg(frame.discomfort, 0, 'f', 1).arg(comfortWords(scale)));
    m_mucosa->setText(snapshot.mucosaSeen < 0.0
                          ? tr("not measured")
                          : tr("%1% of the wall").arg(100.0 * snapshot.mucosaSeen, 0, 'f', 1));
    m_timer->setText(tr("%1 of %2").arg(clock(frame.time), clock(timeLimit)));
    const QString graphics = viewScale < 1.0 ? tr("graphics %1 frames/s (view drawn at %2%)")
                                                   .arg(graphicsRate, 0, 'f', 0)
                                                   .arg(100.0 * viewScale, 0, 'f', 0)
                                             : tr("graphics %1 frames/s").arg(graphicsRate, 0, 'f', 0);
    // Behind real time the rates turn amber: the scope then follows the hands more slowly than they move.
    const bool behind = running && behindRealTime(snapshot.physicsRate, snapshot.targetRate);
    const QString ratesStyle = behind ? QStringLiteral("color: #b86e00; font-weight: bold;") : QString();
    if (m_rates->styleSheet() != ratesStyle) {
        m_rates->setStyleSheet(ratesStyle);
    }
    m_rates->setText(running ? tr("%1 · %2").arg(graphics, physicsWords(snapshot.physicsRate,
                                                                        snapshot.targetRate, snapshot.speed))
                             : tr("%1 · physics %2")
                                   .arg(graphics, snapshot.state == Snapshot::State::Paused ? tr("paused")
                                                                                            : tr("stopped")));
}

}  // namespace colonosim::app
