#include "trainer_ui/app/FirstStartDialog.h"

#include "db/Password.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace colonosim::app {

FirstStartDialog::FirstStartDialog(db::Records& records, const std::filesystem::path& database,
                                   QWidget* parent)
    : QDialog(parent), m_records(records)
{
    setObjectName(QStringLiteral("firstStartDialog"));
    setWindowTitle(tr("colonosim — first start"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(
        tr("<h2>Welcome to colonosim</h2><p>The records are new (%1). Choose the password of the first "
           "administrator, <b>%2</b>. The administrator then adds instructors and students.</p><p>The "
           "password "
           "needs at least %3 characters. Keep it safe: there is no default password.</p>")
            .arg(QString::fromStdString(database.string()).toHtmlEscaped(),
                 QString::fromLatin1(kAdministrator))
            .arg(db::kMinPasswordLength));
    intro->setWordWrap(true);
    layout->addWidget(intro);
    auto* form = new QFormLayout;
    m_password = new QLineEdit;
    m_password->setObjectName(QStringLiteral("newPassword"));
    m_password->setEchoMode(QLineEdit::Password);
    m_repeat = new QLineEdit;
    m_repeat->setObjectName(QStringLiteral("repeatPassword"));
    m_repeat->setEchoMode(QLineEdit::Password);
    form->addRow(tr("Password"), m_password);
    form->addRow(tr("The same password again"), m_repeat);
    layout->addLayout(form);
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("firstStartMessage"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b3261e;"));
    layout->addWidget(m_message);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    QPushButton* ok = buttons->button(QDialogButtonBox::Ok);
    ok->setText(tr("Create the administrator"));
    ok->setObjectName(QStringLiteral("createAdministrator"));
    connect(buttons, &QDialogButtonBox::accepted, this, &FirstStartDialog::create);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    setMinimumWidth(520);
}

QString FirstStartDialog::message() const
{
    return m_message->text();
}

void FirstStartDialog::create()
{
    const std::string password = m_password->text().toStdString();
    if (password.size() < db::kMinPasswordLength) {
        m_message->setText(tr("The password has %1 characters; it needs at least %2.")
                               .arg(password.size())
                               .arg(db::kMinPasswordLength));
        return;
    }
    if (password.size() > db::kMaxPasswordLength) {
        m_message->setText(tr("The password has %1 characters; at most %2 are allowed.")
                               .arg(password.size())
                               .arg(db::kMaxPasswordLength));
        return;
    }
    if (m_repeat->text() != m_password->text()) {
        m_message->setText(tr("The two passwords differ. Type the same password in both fields."));
        m_repeat->clear();
        return;
    }
    try {
        (void)cli::seedFirstStart(m_records, kAdministrator, password);
    } catch (const std::exception& error) {
        m_message->setText(
            tr("The administrator could not be created: %1").arg(QString::fromStdString(error.what())));
        return;
    }
    accept();
}

}  // namespace colonosim::app
