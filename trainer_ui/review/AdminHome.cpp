#include "trainer_ui/review/AdminHome.h"

#include "trainer_ui/review/BackupPage.h"
#include "trainer_ui/review/CertificationPage.h"
#include "trainer_ui/review/CurriculumPage.h"
#include "trainer_ui/review/UsersPage.h"

#include <QTabWidget>
#include <QVBoxLayout>

namespace colonosim::app {

AdminHome::AdminHome(AppContext& context, QWidget* parent)
    : QWidget(parent), m_context(context), m_tabs(new QTabWidget), m_users(new UsersPage(context)),
      m_curriculum(new CurriculumPage(context)), m_certification(new CertificationPage(context)),
      m_backup(new BackupPage(context))
{
    setObjectName(QStringLiteral("adminHome"));
    m_tabs->setObjectName(QStringLiteral("adminTabs"));
    m_tabs->addTab(m_users, QStringLiteral("Users and cohorts"));
    m_tabs->addTab(m_curriculum, QStringLiteral("Curricula"));
    m_tabs->addTab(m_certification, QStringLiteral("Certification"));
    m_tabs->addTab(m_backup, QStringLiteral("Backup"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    connect(m_users, &UsersPage::changed, m_certification, &CertificationPage::refresh);
}

}  // namespace colonosim::app
