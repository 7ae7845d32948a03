#include "trainer_ui/app/MainWindow.h"

#include "simcore/devices/Gamepad.h"
#include "trainer_ui/app/CurriculumMap.h"
#include "trainer_ui/app/LoginScreen.h"
#include "trainer_ui/app/ProcedureScreen.h"
#include "trainer_ui/app/ReplayScreen.h"
#include "trainer_ui/app/ResultsScreen.h"
#include "trainer_ui/app/TaskBrief.h"
#include "trainer_ui/review/AdminHome.h"
#include "trainer_ui/review/InstructorHome.h"

#include <QApplication>
#include <QCloseEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace colonosim::app {

namespace {
QString roleWords(db::Role role)
{
    switch (role) {
    case db::Role::Student: return QObject::tr("student");
    case db::Role::Instructor: return QObject::tr("instructor");
    case db::Role::Administrator: return QObject::tr("administrator");
    }
    return {};
}
}  // namespace

MainWindow::MainWindow(db::Database& database, db::Records& records, std::filesystem::path exportDir,
                       QWidget* parent)
    : QMainWindow(parent), m_database(database), m_records(records), m_exportDir(std::move(exportDir))
{
    setObjectName(QStringLiteral("trainerWindow"));
    setWindowTitle(tr("colonosim — colonoscopy trainer"));
    auto* central = new QWidget;
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    m_topBar = new QWidget;
    m_topBar->setObjectName(QStringLiteral("topBar"));
    m_topBar->setStyleSheet(QStringLiteral(
        "#topBar { background: #1f3a5f; } #topBar QLabel { color: white; font-weight: bold; }"));
    auto* bar = new QHBoxLayout(m_topBar);
    auto* brand = new QLabel(tr("colonosim"));
    m_who = new QLabel;
    m_who->setObjectName(QStringLiteral("whoIsLoggedIn"));
    auto* home = new QPushButton(tr("Home"));
    home->setObjectName(QStringLiteral("homeButton"));
    connect(home, &QPushButton::clicked, this, &MainWindow::backToHome);
    auto* logOutButton = new QPushButton(tr("Log out"));
    logOutButton->setObjectName(QStringLiteral("logOut"));
    connect(logOutButton, &QPushButton::clicked, this, &MainWindow::logOut);
    bar->addWidget(brand);
    bar->addStretch();
    bar->addWidget(m_who);
    bar->addWidget(home);
    bar->addWidget(logOutButton);
    layout->addWidget(m_topBar);
    m_stack = new QStackedWidget;
    m_stack->setObjectName(QStringLiteral("screens"));
    layout->addWidget(m_stack, 1);
    setCentralWidget(central);
    m_login = new LoginScreen(m_records);
    connect(m_login, &LoginScreen::loggedIn, this, &MainWindow::loggedIn);
    m_stack->addWidget(m_login);
    m_topBar->hide();
    resize(1400, 900);
}

MainWindow::~MainWindow()
{
    // The screens refer to the context: they go first.
    for (QWidget* screen : m_screens) {
        delete screen;
    }
}

QWidget* MainWindow::currentScreen() const
{
    return m_stack->currentWidget();
}

void MainWindow::loggedIn(const db::Actor& actor)
{
    m_context = std::make_unique<AppContext>(AppContext{m_database, m_records, actor, m_exportDir});
    m_who->setText(tr("%1 (%2)").arg(QString::fromStdString(actor.name), roleWords(actor.role)));
    m_topBar->show();
    QWidget* home = nullptr;
    try {
        switch (actor.role) {
        case db::Role::Student: {
            auto* map = new CurriculumMap(*m_context);
            connect(map, &CurriculumMap::briefRequested, this, &MainWindow::openBrief);
            home = map;
            break;
        }
        case db::Role::Instructor: {
            auto* instructor = new InstructorHome(*m_context);
            connect(instructor, &InstructorHome::replayRequested, this, &MainWindow::openReplay);
            home = instructor;
            break;
        }
        case db::Role::Administrator: home = new AdminHome(*m_context); break;
        }
    } catch (const std::exception& error) {
        showError(tr("Your home screen could not be opened: %1").arg(QString::fromStdString(error.what())));
        logOut();
        return;
    }
    push(home);
}

void MainWindow::endRunningProcedure()
{
    for (QWidget* screen : m_screens) {
        if (auto* procedure = qobject_cast<ProcedureScreen*>(screen)) {
            m_leaving = true;
            procedure->endAndStore();
            m_leaving = false;
        }
    }
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    endRunningProcedure();
    QMainWindow::closeEvent(event);
}

void MainWindow::logOut()
{
    endRunningProcedure();
    for (QWidget* screen : m_screens) {
        m_stack->removeWidget(screen);
        delete screen;
    }
    m_screens.clear();
    m_context.reset();
    m_topBar->hide();
    m_login->reset();
    m_stack->setCurrentWidget(m_login);
}

void MainWindow::push(QWidget* screen)
{
    m_screens.push_back(screen);
    m_stack->addWidget(screen);
    m_stack->setCurrentWidget(screen);
    screen->setFocus();
}

void MainWindow::pop()
{
    if (m_screens.size() <= 1) {
        return;
    }
    QWidget* top = m_screens.back();
    m_screens.pop_back();
    m_stack->setCurrentWidget(m_screens.back());
    m_stack->removeWidget(top);
    top->hide();
    top->setParent(nullptr);  // out of the window's children at once; deleted when control returns
    top->deleteLater();
}

void MainWindow::backToHome()
{
    endRunningProcedure();
    while (m_screens.size() > 1) {
        pop();
    }
    if (auto* map = m_screens.empty() ? nullptr : qobject_cast<CurriculumMap*>(m_screens.front())) {
        map->refresh();
    }
}

void MainWindow::openBrief(const QString& task)
{
    try {
        const curricula::Curriculum curriculum = loadCurriculum(*m_context);
        const curricula::Task* entry = curriculum.find(task.toStdString());
        if (entry == nullptr) {
            showError(tr("The task \"%1\" is not in the curriculum.").arg(task));
            return;
        }
        auto* brief = new TaskBrief(*m_context, *entry);
        connect(brief, &TaskBrief::backRequested, this, &MainWindow::pop);
        connect(brief, &TaskBrief::startRequested, this, &MainWindow::startProcedure);
        push(brief);
    } catch (const std::exception& error) {
        showError(tr("The task brief could not be opened: %1").arg(QString::fromStdString(error.what())));
    }
}

void MainWindow::startProcedure()
{
    auto* brief = qobject_cast<TaskBrief*>(m_screens.back());
    if (brief == nullptr) {
        return;
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    try {
        const qint64 caseId = brief->storeCase();
        const auto scene = buildScene(brief->caseXml());
        auto* screen = new ProcedureScreen(*m_context, brief->task(), scene, caseId, brief->options());
        connect(screen, &ProcedureScreen::completed, this, &MainWindow::procedureCompleted);
        connect(screen, &ProcedureScreen::failed, this, [this](const QString& message) {
            if (!m_leaving) {
                pop();
            }
            showError(message);
        });
        push(screen);
    } catch (const devices::DeviceError& error) {
        showError(tr("The input device cannot be used: %1").arg(QString::fromStdString(error.what())));
    } catch (const std::exception& error) {
        showError(tr("The procedure could not start: %1").arg(QString::fromStdString(error.what())));
    }
    QApplication::restoreOverrideCursor();
}

void MainWindow::procedureCompleted(qint64 session, const db::SessionResult& result)
{
    if (m_leaving) {
        return;  // stored; the navigation that ended it takes the screens down
    }
    auto* procedure = qobject_cast<ProcedureScreen*>(m_screens.back());
    TaskBrief* brief =
        m_screens.size() >= 2 ? qobject_cast<TaskBrief*>(m_screens[m_screens.size() - 2]) : nullptr;
    if (procedure == nullptr || brief == nullptr) {
        return;
    }
    const curricula::Task task = brief->task();
    pop();
    pop();
    if (auto* map = qobject_cast<CurriculumMap*>(m_screens.front())) {
        map->refresh();
    }
    auto* results = new ResultsScreen(*m_context, session, task, result);
    connect(results, &ResultsScreen::replayRequested, this, &MainWindow::openReplay);
    connect(results, &ResultsScreen::backRequested, this, &MainWindow::backToHome);
    push(results);
}

void MainWindow::openReplay(qint64 session)
{
    if (!m_context) {
        return;
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto* replay = new ReplayScreen(*m_context, session);
    connect(replay, &ReplayScreen::closeRequested, this, &MainWindow::pop);
    push(replay);
    QApplication::restoreOverrideCursor();
}

void MainWindow::showError(const QString& message)
{
    auto* box = new QMessageBox(QMessageBox::Warning, tr("colonosim"), message, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("errorMessage"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

}  // namespace colonosim::app
