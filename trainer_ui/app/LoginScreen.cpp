#include "trainer_ui/app/LoginScreen.h"

#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace colonosim::app {

LoginScreen::LoginScreen(db::Records& records, QWidget* parent) : QWidget(parent), m_records(records)
{
    setObjectName(QStringLiteral("loginScreen"));
    auto* outer = new QVBoxLayout(this);
    outer->addStretch();
    auto* box = new QWidget;
    box->setFixedWidth(480);
    auto* layout = new QVBoxLayout(box);
    layout->addWidget(new QLabel(tr("<h1>colonosim</h1>")));
    layout->addWidget(new QLabel(tr("Colonoscopy training. Log in with the name and password")));
    layout->addWidget(new QLabel(tr("your administrator gave you.")));
    auto* form = new QFormLayout;
    m_name = new QLineEdit;
    m_name->setObjectName(QStringLiteral("loginName"));
    m_password = new QLineEdit;
    m_password->setObjectName(QStringLiteral("loginPassword"));
    m_password->setEchoMode(QLineEdit::Password);
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Password"), m_password);
    layout->addLayout(form);
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("loginMessage"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b3261e;"));
    layout->addWidget(m_message);
    auto* button = new QPushButton(tr("Log in"));
    button->setObjectName(QStringLiteral("loginButton"));
    button->setDefault(true);
    connect(button, &QPushButton::clicked, this, &LoginScreen::logIn);
    connect(m_password, &QLineEdit::returnPressed, this, &LoginScreen::logIn);
    layout->addWidget(button);
    outer->addWidget(box, 0, Qt::AlignHCenter);
    outer->addStretch();
}

void LoginScreen::reset()
{
    m_name->clear();
    m_password->clear();
    m_message->clear();
    m_name->setFocus();
}

void LoginScreen::logIn()
{
    const std::string name = m_name->text().trimmed().toStdString();
    if (name.empty()) {
        m_message->setText(tr("Type your name first."));
        return;
    }
    try {
        const db::Actor actor = m_records.authenticate(name, m_password->text().toStdString());
        m_password->clear();
        m_message->clear();
        Q_EMIT loggedIn(actor);
    } catch (const db::AuthenticationFailed&) {
        m_password->clear();
        m_message->setText(tr("The name or the password is not right. Check both and try again."));
    } catch (const std::exception& error) {
        m_message->setText(tr("The records could not be read: %1").arg(QString::fromStdString(error.what())));
    }
}

}  // namespace colonosim::app
