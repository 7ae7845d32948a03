#pragma once
/// \file
/// The trainer's window: a top bar (who is logged in, their role, log out)
/// over a QStackedWidget of screens. The login screen is always first;
/// after login the role's home screen (student: the curriculum map;
/// instructor: InstructorHome; administrator: AdminHome) is the base of a
/// stack of screens that the person goes forward into and back out of
/// (task brief, procedure, results, replay), so closing a screen returns to
/// where they were. Leaving a running procedure (Home, Log out, closing the
/// window) ends it as Esc does: the session is scored and stored before the
/// screens go, never dropped.

#include "db/Database.h"
#include "db/Records.h"
#include "trainer_ui/app/AppContext.h"

#include <QMainWindow>

#include <filesystem>
#include <memory>
#include <vector>

class QLabel;
class QStackedWidget;

namespace colonosim::db {
struct SessionResult;
}

namespace colonosim::app {

class LoginScreen;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    MainWindow(db::Database& database, db::Records& records, std::filesystem::path exportDir,
               QWidget* parent = nullptr);
    ~MainWindow() override;

    /// The person logged in (null when nobody is).
    [[nodiscard]] const AppContext* context() const { return m_context.get(); }
    /// The screen shown now.
    [[nodiscard]] QWidget* currentScreen() const;

    void logOut();
    /// Goes back to the role's home screen.
    void backToHome();
    /// Opens the replay of `session` over the current screen.
    void openReplay(qint64 session);

private:
    void loggedIn(const db::Actor& actor);
    void push(QWidget* screen);
    void pop();
    /// Ends a procedure still running on the stack and stores its session
    /// (as Esc does), before the screens above the home screen go.
    void endRunningProcedure();
    void openBrief(const QString& task);
    void startProcedure();
    void procedureCompleted(qint64 session, const db::SessionResult& result);
    void showError(const QString& message);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    db::Database& m_database;
    db::Records& m_records;
    std::filesystem::path m_exportDir;
    std::unique_ptr<AppContext> m_context;
    QStackedWidget* m_stack = nullptr;
    LoginScreen* m_login = nullptr;
    QWidget* m_topBar = nullptr;
    QLabel* m_who = nullptr;
    std::vector<QWidget*> m_screens;  ///< above the login screen; the first is the home screen
    bool m_leaving = false;           ///< a procedure is being ended by navigation: no results screen
};

}  // namespace colonosim::app
