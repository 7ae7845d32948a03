#include "trainer_ui/review/InstructorHome.h"

#include "trainer_ui/review/CaseLibraryPage.h"
#include "trainer_ui/review/ComparisonPage.h"
#include "trainer_ui/review/CurvesPage.h"
#include "trainer_ui/review/SessionsPage.h"
#include "trainer_ui/review/TraineeSessions.h"
#include "trainer_ui/review/TraineesPage.h"

#include <QTabWidget>
#include <QVBoxLayout>

namespace colonosim::app {

InstructorHome::InstructorHome(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context),
      m_sessionCache(std::make_unique<TraineeSessions>(context.records, context.actor)),
      m_tabs(new QTabWidget), m_trainees(new TraineesPage(context, *m_sessionCache)),
      m_curves(new CurvesPage(context, *m_sessionCache)),
      m_sessions(new SessionsPage(context, *m_sessionCache)), m_library(new CaseLibraryPage(context)),
      m_comparison(new ComparisonPage(context, *m_sessionCache))
{
    setObjectName(QStringLiteral("instructorHome"));
    m_tabs->setObjectName(QStringLiteral("instructorTabs"));
    m_tabs->addTab(m_trainees, QStringLiteral("Trainees and cohorts"));
    m_tabs->addTab(m_curves, QStringLiteral("Learning curves"));
    m_tabs->addTab(m_sessions, QStringLiteral("Sessions"));
    m_tabs->addTab(m_library, QStringLiteral("Case library"));
    m_tabs->addTab(m_comparison, QStringLiteral("Compare sessions"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    connect(m_sessions, &SessionsPage::replayRequested, this, &InstructorHome::replayRequested);
    connect(m_trainees, &TraineesPage::traineeChosen, this, [this](const QString& trainee) {
        m_curves->showTrainee(trainee);
        m_tabs->setCurrentWidget(m_curves);
    });
}

InstructorHome::~InstructorHome() = default;

void InstructorHome::refresh()
{
    m_sessionCache->clear();
    m_trainees->refresh();
    m_curves->refresh();
    m_sessions->refresh();
    m_library->refresh();
    m_comparison->refresh();
}

}  // namespace colonosim::app
