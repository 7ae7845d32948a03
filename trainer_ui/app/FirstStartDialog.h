#pragma once
/// \file
/// First start of a database with no user: the person choosing the first
/// administrator's password (twice; refused with a sentence when the two
/// differ or the password is shorter than the records accept). On OK the
/// records are seeded as the command line seeds them (cli::seedFirstStart):
/// the administrator "admin" and the core curriculum. Never a fixed password.

#include "db/Records.h"

#include <QDialog>

#include <filesystem>

class QLabel;
class QLineEdit;

namespace colonosim::app {

class FirstStartDialog : public QDialog {
    Q_OBJECT
public:
    static constexpr const char* kAdministrator = "admin";

    FirstStartDialog(db::Records& records, const std::filesystem::path& database, QWidget* parent = nullptr);

    /// The message shown (empty when none).
    [[nodiscard]] QString message() const;

private:
    void create();

    db::Records& m_records;
    QLineEdit* m_password = nullptr;
    QLineEdit* m_repeat = nullptr;
    QLabel* m_message = nullptr;
};

}  // namespace colonosim::app
