#pragma once
/// \file
/// The procedure screen's heads-up display: insertion depth, the handle-force
/// gauge (its colour turns at the recorder's excessive-force level), the
/// comfort meter (0-10 and the Gloucester 5-point scale), the loop indicator
/// with the loop's type, the timer against the task's limit, and the
/// graphics and physics rates.

#include "trainer_ui/app/SimulationRunner.h"

#include <QWidget>

class QLabel;
class QProgressBar;

namespace colonosim::app {

class HeadsUpDisplay : public QWidget {
    Q_OBJECT
public:
    explicit HeadsUpDisplay(double excessiveForce, QWidget* parent = nullptr);

    /// Shows `snapshot`; `graphicsRate` frames/s; `timeLimit` s.
    void showSnapshot(const Snapshot& snapshot, double graphicsRate, double timeLimit);

    /// Plain words of the 5-point comfort scale (1..5).
    [[nodiscard]] static QString comfortWords(int scale);
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
    QLabel* m_mucosa;  ///< the renderer's coverage so far
};

}  // namespace colonosim::app
