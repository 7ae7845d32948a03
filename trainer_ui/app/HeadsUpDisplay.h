#pragma once
/// \file
/// The procedure screen's heads-up display: insertion depth, the handle-force
/// gauge (its colour turns at the recorder's excessive-force level), the
/// comfort meter (0-10 and the Gloucester 5-point scale), the loop indicator
/// with the loop's type, the timer against the task's limit, and the
/// graphics and physics rates. The gauges and the loop indicator follow
/// every snapshot; the figures in words change at most kTextRate times a
/// second while the procedure runs, and at once when it starts, pauses or
/// ends. Figures changing faster cannot be read, and each change of a
/// label's text costs its layout and shaping on the window's thread: a fifth
/// of that thread's time at 60 changes a second.

#include "trainer_ui/app/SimulationRunner.h"

#include <QElapsedTimer>
#include <QWidget>

class QLabel;
class QProgressBar;

namespace colonosim::app {

class HeadsUpDisplay : public QWidget {
    Q_OBJECT
public:
    /// Changes a second, at most, of the figures in words while running.
    static constexpr int kTextRate = 10;

    explicit HeadsUpDisplay(double excessiveForce, QWidget* parent = nullptr);

    /// Shows `snapshot`; `graphicsRate` frames/s; `timeLimit` s; `viewScale`
    /// the endoscope view's drawing scale (said when under 1).
    void showSnapshot(const Snapshot& snapshot, double graphicsRate, double timeLimit,
                      double viewScale = 1.0);

    /// Plain words of the 5-point comfort scale (1..5).
    [[nodiscard]] static QString comfortWords(int scale);
    /// The physics rate in words: "physics 1001 Hz"; when the loop keeps
    /// less than kBehindShare of `targetRate` (steps/s that real time asks,
    /// times `speed`), also how much slower than asked the scope then
    /// follows the hands ("physics 612 Hz, 61% of real time"; at a replay's
    /// other speeds "..., 60% of 4x real time").
    [[nodiscard]] static QString physicsWords(double rate, double targetRate, double speed = 1.0);
    /// True when a measured `rate` (> 0) is under kBehindShare of `targetRate`.
    [[nodiscard]] static bool behindRealTime(double rate, double targetRate);
    /// Share of the asked rate under which the display says the loop is behind.
    static constexpr double kBehindShare = 0.95;
    /// A loop type as a person reads it ("alpha loop"); "no loop" for none.
    [[nodiscard]] static QString loopWords(procedure::LoopKind kind);

private:
    double m_excessiveForce;
    QLabel* m_depth;
    QProgressBar* m_force;
    QLabel* m_forceText;
    QProgressBar* m_comfort;
    QLabel* m_comfortText;
    QLabel* m_loop;
    QLabel* m_timer;
    QLabel* m_rates;
    QLabel* m_mucosa;                                       ///< the renderer's coverage so far
    QElapsedTimer m_textShown;                              ///< since the figures in words last changed
    Snapshot::State m_textState = Snapshot::State::Failed;  ///< the state they were shown for
};

}  // namespace colonosim::app
