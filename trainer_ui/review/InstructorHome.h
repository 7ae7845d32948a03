#pragma once
/// \file
/// The instructor's home screen: the trainees and cohorts this instructor may
/// read; per-trainee learning curves per metric with the benchmark drawn, and
/// the CUSUM / LC-CUSUM charts of cecal intubation with their decision
/// limits; the session list (Replay asks the shell to open the replay
/// screen); the case library with the generator, assignments to trainees or
/// cohorts; and a side-by-side comparison of two sessions. Everything is read
/// and written through AppContext::records, which enforces authorization.

#include "trainer_ui/app/AppContext.h"

#include <QWidget>

#include <memory>

class QTabWidget;

namespace colonosim::app {

class TraineeSessions;
class TraineesPage;
class CurvesPage;
class SessionsPage;
class CaseLibraryPage;
class ComparisonPage;

class InstructorHome : public QWidget {
    Q_OBJECT
public:
    explicit InstructorHome(AppContext& context, QWidget* parent = nullptr);

    ~InstructorHome() override;

    /// Reads the records again (after sessions were added elsewhere): each
    /// page reloads when next shown.
    void refresh();

Q_SIGNALS:
    void replayRequested(qint64 session);

private:
    AppContext& m_context;
    std::unique_ptr<TraineeSessions> m_sessionCache;
    QTabWidget* m_tabs;
    TraineesPage* m_trainees;
    CurvesPage* m_curves;
    SessionsPage* m_sessions;
    CaseLibraryPage* m_library;
    ComparisonPage* m_comparison;
};

}  // namespace colonosim::app
