#pragma once
/// \file
/// The certification rule set of record, for the administrator: the active
/// set's name and version, importing a rule-set file as a new version
/// (checked completely first; problems listed as sentences with their line)
/// and activating a stored version. The data layer enforces that only
/// administrators may import or activate (db/CertificationRules.h).

#include "trainer_ui/app/AppContext.h"

#include <QGroupBox>

#include <string>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;

namespace colonosim::app {

class RuleSetBox : public QGroupBox {
    Q_OBJECT
public:
    explicit RuleSetBox(AppContext& context, QWidget* parent = nullptr);

    /// Reads the stored versions and the active one again.
    void reload();

Q_SIGNALS:
    /// The active rule set changed.
    void changed();

private:
    void import();
    void activate();
    void say(const QString& text, bool error);

    AppContext& m_context;
    QLabel* m_active;
    QComboBox* m_versions;
    QLineEdit* m_path;
    QLabel* m_status;
    QListWidget* m_problems;
};

}  // namespace colonosim::app
