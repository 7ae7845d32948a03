#pragma once
/// \file
/// The results of a session: every metric against its benchmark (the limit
/// of the task's benchmark set, pass or fail), what to improve in plain words
/// for each failed metric, the task's progression state, and Replay.

#include "curricula/Curriculum.h"
#include "db/Records.h"
#include "trainer_ui/app/AppContext.h"

#include <QWidget>

class QTableWidget;

namespace colonosim::app {

class ResultsScreen : public QWidget {
    Q_OBJECT
public:
    ResultsScreen(AppContext& context, qint64 session, const curricula::Task& task,
                  const db::SessionResult& result, QWidget* parent = nullptr);

    /// Rows of the metric table (for tests and reports): metric, value, limit, verdict.
    [[nodiscard]] QTableWidget* metricTable() const { return m_table; }

Q_SIGNALS:
    void replayRequested(qint64 session);
    void backRequested();

private:
    QTableWidget* m_table = nullptr;
};

/// A progression state ("locked", "unlocked", "proficient", "unavailable") in a sentence.
[[nodiscard]] QString progressionWords(const std::string& state);

}  // namespace colonosim::app
