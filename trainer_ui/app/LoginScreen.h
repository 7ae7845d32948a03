#pragma once
/// \file
/// Login: name and password, checked by the records; a wrong name or
/// password is answered with a sentence, never with a crash.

#include "db/Records.h"

#include <QWidget>

class QLabel;
class QLineEdit;

namespace colonosim::app {

class LoginScreen : public QWidget {
    Q_OBJECT
public:
    explicit LoginScreen(db::Records& records, QWidget* parent = nullptr);
    /// Clears the fields and the message (after a log-out).
    void reset();

Q_SIGNALS:
    void loggedIn(const colonosim::db::Actor& actor);

private:
    void logIn();

    db::Records& m_records;
    QLineEdit* m_name = nullptr;
    QLineEdit* m_password = nullptr;
    QLabel* m_message = nullptr;
};

}  // namespace colonosim::app
