#pragma once
/// \file
/// A trainee's completed sessions; Replay asks for the chosen session to be
/// replayed from its stored trace (the shell opens the replay screen).

#include "trainer_ui/app/AppContext.h"

#include "trainer_ui/review/LazyPage.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableView;

namespace colonosim::app {

class TraineeSessions;

class SessionTableModel;

class SessionsPage : public LazyPage {
    Q_OBJECT
public:
    SessionsPage(AppContext& context, TraineeSessions& sessions, QWidget* parent = nullptr);

Q_SIGNALS:
    void replayRequested(qint64 session);

protected:
    void reload() override;

private:
    void load();
    [[nodiscard]] qint64 chosenSession() const;

    AppContext& m_context;
    TraineeSessions& m_cache;
    QComboBox* m_trainee;
    SessionTableModel* m_model;
    QTableView* m_table;
    QPushButton* m_replay;
    QLabel* m_status;
};

}  // namespace colonosim::app
