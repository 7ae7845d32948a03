// The trainer driven as a person drives it, under Xvfb: the first start
// (choosing the administrator's password), the login (a wrong password is
// answered with a sentence), and a student taking the first task of the
// curriculum with the autopilot and with the keyboard, seeing the results,
// and replaying the session (seeking lands exactly on the recording); then
// the three roles in turn on one database: the student's session, seen and
// replayed by the instructor of the student's cohort and reported by the
// administrator, each logging in through the window; the haptic device and
// the gamepad chosen in the brief, and a replay at 1x and 4x. A screenshot
// of every screen goes to the screenshots folder of the build.
#include "db/Database.h"
#include "db/Records.h"
#include "scoring/Benchmarks.h"
#include "simcore/devices/HapticDevice.h"
#include "simcore/devices/HdcController.h"
#include "tests/db/TempDir.h"
#include "trainer_ui/app/CurriculumMap.h"
#include "trainer_ui/app/EndoscopeViewWidget.h"
#include "trainer_ui/app/FirstStartDialog.h"
#include "trainer_ui/app/HeadsUpDisplay.h"
#include "trainer_ui/app/MainWindow.h"
#include "trainer_ui/app/OffscreenGlWidget.h"
#include "trainer_ui/app/ProcedureScreen.h"
#include "trainer_ui/app/ReplayScreen.h"
#include "trainer_ui/app/ResultsScreen.h"
#include "trainer_ui/app/ShapeViewWidget.h"
#include "trainer_ui/app/SimulationRunner.h"
#include "trainer_ui/app/TaskBrief.h"
#include "trainer_ui/cli/RecordsAccess.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableView>
#include <QTableWidget>
#include <QTest>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace {

using namespace colonosim;

constexpr int kLongWait =
    180000;  ///< ms: a generous bound for work on a loaded machine (never a timing check)

/// Waits, processing events, until `condition()` holds or kLongWait has
/// passed; returns whether it holds.
template <class Condition>
bool waitUntil(Condition condition)
{
    QElapsedTimer waited;
    waited.start();
    while (!condition() && waited.elapsed() < kLongWait) {
        QTest::qWait(10);
    }
    return condition();
}

/// Waits until `condition` holds (at most kLongWait), then asserts it.
/// QtTest's QTRY_* macros report a failure to QtTest and return, which
/// GoogleTest counts as a pass; this fails the test.
#define ASSERT_SOON(condition)                                                                               \
    ASSERT_TRUE(waitUntil([&] { return static_cast<bool>(condition); })) << "still false: " #condition

void screenshot(QWidget& widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(COLONOSIM_SCREENSHOT_DIR));
    const QString path = QStringLiteral(COLONOSIM_SCREENSHOT_DIR "/%1.png").arg(name);
    EXPECT_TRUE(widget.grab().save(path)) << path.toStdString();
}

template <class T>
T* child(QWidget& parent, const char* name)
{
    T* found = parent.findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

void click(QWidget& parent, const char* button)
{
    auto* found = child<QPushButton>(parent, button);
    ASSERT_NE(found, nullptr);
    ASSERT_TRUE(found->isEnabled()) << button;
    QTest::mouseClick(found, Qt::LeftButton);
}

void logIn(app::MainWindow& window, const QString& name, const QString& password)
{
    auto* nameField = child<QLineEdit>(window, "loginName");
    auto* passwordField = child<QLineEdit>(window, "loginPassword");
    nameField->clear();
    QTest::keyClicks(nameField, name);
    QTest::keyClicks(passwordField, password);
    click(window, "loginButton");
}

QString screenName(const app::MainWindow& window)
{
    return window.currentScreen() != nullptr ? window.currentScreen()->objectName() : QString();
}

TEST(Trainer, FirstStartChoosesTheAdministratorsPasswordAndLogsIn)
{
    test::TempDir dir;
    db::Database database(dir / "records.sqlite");
    db::Records records(database);
    ASSERT_TRUE(records.empty());

    app::FirstStartDialog dialog(records, dir / "records.sqlite");
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    auto* password = child<QLineEdit>(dialog, "newPassword");
    auto* repeat = child<QLineEdit>(dialog, "repeatPassword");
    QTest::keyClicks(password, "short");
    QTest::keyClicks(repeat, "short");
    click(dialog, "createAdministrator");
    EXPECT_TRUE(dialog.message().contains("at least 8")) << dialog.message().toStdString();
    EXPECT_TRUE(records.empty());

    password->clear();
    repeat->clear();
    QTest::keyClicks(password, "kestrel-harbour-41");
    QTest::keyClicks(repeat, "kestrel-harbour-14");
    click(dialog, "createAdministrator");
    EXPECT_TRUE(dialog.message().contains("differ")) << dialog.message().toStdString();
    EXPECT_TRUE(records.empty());
    screenshot(dialog, "first-start");

    QTest::keyClicks(repeat, "kestrel-harbour-41");
    click(dialog, "createAdministrator");
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    ASSERT_FALSE(records.empty());
    const db::Actor admin = records.authenticate("admin", "kestrel-harbour-41");
    EXPECT_EQ(admin.role, db::Role::Administrator);
    // Seeded as the command line seeds: the core curriculum is stored.
    EXPECT_TRUE(records.curriculum(admin, cli::kCoreCurriculum).has_value());

    app::MainWindow window(database, records, dir.path());
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    logIn(window, "admin", "not-the-password");
    auto* message = child<QLabel>(window, "loginMessage");
    EXPECT_TRUE(message->text().contains("not right")) << message->text().toStdString();
    EXPECT_EQ(window.context(), nullptr);
    screenshot(window, "login");

    logIn(window, "admin", "kestrel-harbour-41");
    ASSERT_NE(window.context(), nullptr);
    EXPECT_EQ(window.context()->actor.role, db::Role::Administrator);
    EXPECT_EQ(screenName(window), "adminHome");
    EXPECT_TRUE(child<QLabel>(window, "whoIsLoggedIn")->text().contains("administrator"));
    click(window, "logOut");
    EXPECT_EQ(window.context(), nullptr);
    EXPECT_EQ(screenName(window), "loginScreen");
}

/// Records with an administrator, the core curriculum, the student ada and a
/// benchmark set for the first task, so results show pass and fail.
struct StudentRecords {
    test::TempDir dir;
    db::Database database{dir / "records.sqlite"};
    db::Records records{database};

    StudentRecords()
    {
        const db::Actor admin = cli::seedFirstStart(records, "admin", "admin-password-1");
        records.addUser(admin, "ada", db::Role::Student, "ada-password-1");
        scoring::BenchmarkSet set;
        set.name = "core-navigation";
        set.metrics["max_handle_force"] = {5.0, 1.0, 5};
        set.metrics["clear_view"] = {0.9, 0.05, 5};
        set.metrics["cecal_intubation"] = {1.0, 0.0, 5};
        set.metrics["discomfort_peak"] = {2.0, 1.0, 5};
        records.storeBenchmarkSet(admin, set.name, 1, set.toJson());
    }
};

app::ProcedureScreen* startProcedure(app::MainWindow& window, app::Driver driver, double timeLimit)
{
    click(window, "openBrief");
    EXPECT_EQ(screenName(window), "taskBrief");
    QWidget& brief = *window.currentScreen();
    auto* choice = child<QComboBox>(brief, "driverChoice");
    const int index = choice->findData(static_cast<int>(driver));
    EXPECT_GE(index, 0);
    choice->setCurrentIndex(index);
    child<QDoubleSpinBox>(brief, "timeLimit")->setValue(timeLimit);
    click(brief, "startProcedure");
    return qobject_cast<app::ProcedureScreen*>(window.currentScreen());
}

TEST(Trainer, AStudentTakesTheFirstTaskSeesTheResultsAndReplaysIt)
{
    StudentRecords fixture;
    app::MainWindow window(fixture.database, fixture.records, fixture.dir.path());
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    logIn(window, "ada", "ada-password-1");
    ASSERT_EQ(screenName(window), "studentHome");

    // The curriculum map: the first task is open and marked next, the rest locked.
    auto* map = qobject_cast<app::CurriculumMap*>(window.currentScreen());
    ASSERT_NE(map, nullptr);
    EXPECT_EQ(map->nextTask().value_or(""), "navigation-straight");
    EXPECT_EQ(map->stateOf("navigation-flexures"), "locked");
    auto* tree = child<QTreeWidget>(window, "curriculumMap");
    ASSERT_NE(tree->currentItem(), nullptr);
    EXPECT_TRUE(tree->currentItem()->text(0).contains("Navigate an easy colon"));
    screenshot(window, "student-home");

    // The brief: a generated patient with indication, preparation and medication.
    click(window, "openBrief");
    ASSERT_EQ(screenName(window), "taskBrief");
    const QString history = child<QLabel>(window, "caseHistory")->text();
    for (const char* part : {"Indication", "Preparation", "Medication", "seed"}) {
        EXPECT_TRUE(history.contains(part)) << part << " missing from " << history.toStdString();
    }
    screenshot(window, "task-brief");
    click(window, "backToCurriculum");
    ASSERT_EQ(screenName(window), "studentHome");

    // The autopilot drives a short procedure through the procedure screen.
    constexpr double kRunLength = 4.0;  // s simulated
    app::ProcedureScreen* procedure = startProcedure(window, app::Driver::Autopilot, kRunLength);
    ASSERT_NE(procedure, nullptr);
    const qint64 session = procedure->session();
    auto* view = child<app::EndoscopeViewWidget>(window, "endoscopeView");
    // The first frame; on a timeout, say what the screen shows instead.
    if (!waitUntil([&] { return view->framesDrawn() > 0; })) {
        screenshot(window, "procedure-without-a-frame");
    }
    ASSERT_GT(view->framesDrawn(), 0)
        << "status: " << child<QLabel>(window, "procedureStatus")->text().toStdString()
        << "; view: " << view->failure().toStdString();
    EXPECT_TRUE(view->failure().isEmpty()) << view->failure().toStdString();
    // The figures (printed, never asserted): frames drawn and loop steps per wall-clock second
    // from the first frame until 3.5 s simulated.
    QElapsedTimer wall;
    wall.start();
    const long frames0 = procedure->framesDrawn();
    const double time0 = procedure->shownTime();
    auto* shape = child<app::ShapeViewWidget>(window, "shapeView");
    const long redraws0 = shape->redraws();
    ASSERT_SOON(procedure->shownTime() >= 3.5);
    const double seconds = static_cast<double>(wall.elapsed()) / 1000.0;
    const double shapeRate = static_cast<double>(shape->redraws() - redraws0) / seconds;
    std::cout << "scope-shape view: " << shapeRate << " redraws/s\n";
    EXPECT_GT(shapeRate, 1.0) << "the shape view follows the procedure";
    EXPECT_LE(shapeRate, app::ShapeViewWidget::kRedrawRate + 1.0)
        << "and leaves the frame budget to the camera";
    std::cout << "procedure screen over " << seconds << " s: graphics "
              << static_cast<double>(procedure->framesDrawn() - frames0) / seconds << " frames/s, physics "
              << 1000.0 * (procedure->shownTime() - time0) / seconds
              << " steps/s (HUD: " << procedure->graphicsRate() << " frames/s, " << procedure->physicsRate()
              << " steps/s)\n";
    EXPECT_GT(procedure->shownInsertion(), 0.03);
    screenshot(window, "procedure");
    ASSERT_SOON(screenName(window) == QStringLiteral("resultsScreen"));

    // Results: every metric with its benchmark, stored as completed.
    auto* table = child<QTableWidget>(window, "metricTable");
    EXPECT_GE(table->rowCount(), 10);
    int judged = 0;
    for (int row = 0; row < table->rowCount(); ++row) {
        const QString verdict = table->item(row, 3)->text();
        judged += verdict == "pass" || verdict == "fail" ? 1 : 0;
    }
    EXPECT_EQ(judged, 4);  // the four benchmarked metrics
    EXPECT_FALSE(child<QLabel>(window, "progressionStatus")->text().isEmpty());
    screenshot(window, "results");
    const db::Actor ada = fixture.records.authenticate("ada", "ada-password-1");
    const std::vector<db::SessionRow> stored = fixture.records.sessions(ada, "ada");
    ASSERT_EQ(stored.size(), 1u);
    EXPECT_EQ(stored[0].id, session);
    EXPECT_EQ(stored[0].status, "completed");
    EXPECT_EQ(stored[0].task, "navigation-straight");
    EXPECT_EQ(stored[0].device, "scripted:expert");
    EXPECT_NEAR(stored[0].duration, kRunLength, 1e-6);

    // Replay: play, pause, then seek to a recorded sample; the tip lands exactly where it was recorded.
    click(window, "replayButton");
    auto* replay = qobject_cast<app::ReplayScreen*>(window.currentScreen());
    ASSERT_NE(replay, nullptr);
    ASSERT_TRUE(replay->failure().isEmpty()) << replay->failure().toStdString();
    ASSERT_SOON(replay->shown()->state == app::Snapshot::State::Paused);
    click(window, "replayPlay");
    ASSERT_SOON(replay->shown()->frame.time > 0.5);
    click(window, "replayPause");
    ASSERT_SOON(replay->shown()->state == app::Snapshot::State::Paused);
    QTest::qWait(200);  // let both views draw the paused frame
    screenshot(window, "replay");

    const procedure::Recording& recording = replay->recording();
    ASSERT_GT(recording.samples.size(), 300u);
    const procedure::RecordedSample& target = recording.samples[250];  // 2.5 s at 100 Hz
    child<QDoubleSpinBox>(window, "seekTime")->setValue(target.time);
    click(window, "seekButton");
    EXPECT_TRUE(replay->seeking());
    EXPECT_TRUE(child<QProgressBar>(window, "seekProgress")->isVisible());
    ASSERT_SOON(!replay->seeking());
    const app::Snapshot* landed = replay->shown();
    EXPECT_EQ(landed->state, app::Snapshot::State::Paused);
    EXPECT_EQ(landed->frame.time, target.time);
    // Deterministic replay: bit-identical to the recording, so exact equality
    // (the recording holds the frame rounded to the recording resolution).
    const procedure::ProcedureFrame& f = landed->frame;
    const procedure::RecordedSample replayed =
        procedure::quantizeSample({f.time, f.input.insertion, f.tipPosition, f.tipSegment, f.handleForce,
                                   f.handleTorque, f.maxWallForce, f.mesenteryStrain, f.discomfort, f.loop});
    EXPECT_EQ(replayed.tip, target.tip);
    EXPECT_EQ(replayed.handleForce, target.handleForce);
    EXPECT_EQ(replayed.discomfort, target.discomfort);

    // A cancelled seek leaves the replay where it was.
    child<QDoubleSpinBox>(window, "seekTime")->setValue(3.9);
    click(window, "seekButton");
    ASSERT_TRUE(replay->seeking());
    click(window, "cancelSeek");
    EXPECT_FALSE(replay->seeking());
    EXPECT_FALSE(child<QProgressBar>(window, "seekProgress")->isVisible());
    QTest::qWait(300);
    EXPECT_EQ(replay->shown()->frame.time, target.time);
    click(window, "closeReplay");
    ASSERT_SOON(screenName(window) == QStringLiteral("resultsScreen"));

    // The keyboard path: holding Up inserts the scope; Esc ends and stores the session.
    click(window, "backToCurriculum");
    ASSERT_EQ(screenName(window), "studentHome");
    procedure = startProcedure(window, app::Driver::Keyboard, 600.0);
    ASSERT_NE(procedure, nullptr);
    ASSERT_SOON(child<QLabel>(window, "procedureStatus")->text().contains("running"));
    EXPECT_EQ(procedure->shownInsertion(), 0.0);
    QTest::keyPress(procedure, Qt::Key_Up);
    ASSERT_SOON(procedure->shownInsertion() > 0.01);
    ASSERT_SOON(!std::isnan(procedure->inputLatency()));
    std::cout << "input to display (Up key to the first frame drawn with the scope moved): "
              << procedure->inputLatency() << " ms\n";
    QTest::keyRelease(procedure, Qt::Key_Up);

    // The mouse path: dragging up on the endoscope view inserts further; a
    // release stops the feed.
    QWidget* dragged = child<QWidget>(window, "endoscopeView");
    ASSERT_NE(dragged, nullptr);
    const QPoint grab = dragged->rect().center();
    ASSERT_SOON(procedure->shownInsertion() > 0.0);
    const double beforeDrag = procedure->shownInsertion();
    QTest::mousePress(dragged, Qt::LeftButton, {}, grab);
    QTest::mouseMove(dragged, grab - QPoint(0, 150));  // full deflection: kDragPixels up
    ASSERT_SOON(procedure->shownInsertion() > beforeDrag + 0.01);
    QTest::mouseRelease(dragged, Qt::LeftButton, {}, grab - QPoint(0, 150));
    QTest::qWait(300);  // let the release reach the loop and the display
    const double released = procedure->shownInsertion();
    QTest::qWait(500);
    EXPECT_NEAR(procedure->shownInsertion(), released, 1e-3);  // no feed without a drag

    QTest::keyClick(procedure, Qt::Key_Escape);
    ASSERT_SOON(screenName(window) == QStringLiteral("resultsScreen"));
    const std::vector<db::SessionRow> after = fixture.records.sessions(ada, "ada");
    ASSERT_EQ(after.size(), 2u);
    EXPECT_EQ(after[1].device, "keyboard");
    EXPECT_GT(after[1].metrics.at("max_insertion"), 0.02);  // keys, then the mouse
}

/// StudentRecords with an instructor, ian, teaching ada's cohort.
struct ThreeRoles : StudentRecords {
    ThreeRoles()
    {
        const db::Actor admin = records.authenticate("admin", "admin-password-1");
        records.addUser(admin, "ian", db::Role::Instructor, "ian-password-1");
        records.addCohort(admin, "A");
        records.addMember(admin, "A", "ada");
        records.assignInstructor(admin, "A", "ian");
    }
};

void chooseText(QComboBox* box, const QString& text)
{
    ASSERT_NE(box, nullptr);
    const int k = box->findText(text, Qt::MatchStartsWith);
    ASSERT_GE(k, 0) << text.toStdString();
    box->setCurrentIndex(k);
}

std::string readFile(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

TEST(Trainer, TheInstructorReplaysTheStudentsSessionAndTheAdministratorReportsIt)
{
    ThreeRoles fixture;
    app::MainWindow window(fixture.database, fixture.records, fixture.dir.path());
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    const db::Actor ada = fixture.records.authenticate("ada", "ada-password-1");

    // The student: a short run with the autopilot; the heads-up display follows it.
    logIn(window, "ada", "ada-password-1");
    ASSERT_EQ(screenName(window), "studentHome");
    app::ProcedureScreen* procedure = startProcedure(window, app::Driver::Autopilot, 3.0);
    ASSERT_NE(procedure, nullptr);
    const qint64 session = procedure->session();
    EXPECT_NE(window.findChild<QWidget*>(QStringLiteral("shapeView")), nullptr)
        << "the first task shows the scope-shape view";
    ASSERT_SOON(procedure->shownTime() >= 2.0);
    EXPECT_TRUE(child<QLabel>(window, "insertionDepth")->text().endsWith(QStringLiteral(" cm")));
    EXPECT_NE(child<QLabel>(window, "insertionDepth")->text(), QStringLiteral("0.0 cm"));
    EXPECT_EQ(child<QLabel>(window, "loopIndicator")->text(), QStringLiteral("no loop"));
    // The figures in words follow within a tenth of a second (HeadsUpDisplay::kTextRate).
    ASSERT_SOON(child<QLabel>(window, "procedureTimer")->text().startsWith(QStringLiteral("0:02")));
    EXPECT_TRUE(child<QLabel>(window, "rates")->text().contains(QStringLiteral("frames/s")));
    ASSERT_SOON(child<QLabel>(window, "mucosaSeen")->text().endsWith(QStringLiteral("% of the wall")) &&
                !child<QLabel>(window, "mucosaSeen")->text().startsWith(QStringLiteral("0.0%")));
    ASSERT_SOON(screenName(window) == QStringLiteral("resultsScreen"));

    // Leaving a running procedure (Home) ends it as Esc does: stored, not lost.
    click(window, "backToCurriculum");
    procedure = startProcedure(window, app::Driver::Keyboard, 600.0);
    ASSERT_NE(procedure, nullptr);
    const qint64 left = procedure->session();
    ASSERT_SOON(child<QLabel>(window, "procedureStatus")->text().contains("running"));
    QTest::keyPress(procedure, Qt::Key_Up);
    ASSERT_SOON(procedure->shownInsertion() > 0.01);
    QTest::keyRelease(procedure, Qt::Key_Up);
    click(window, "homeButton");
    ASSERT_EQ(screenName(window), "studentHome");
    std::vector<db::SessionRow> stored = fixture.records.sessions(ada, "ada");
    ASSERT_EQ(stored.size(), 2u);
    // % mucosa visualised came from the renderer's coverage of the session.
    EXPECT_EQ(stored[0].metrics.at("mucosa_from_renderer"), 1.0);
    EXPECT_GT(stored[0].metrics.at("mucosa_visualised"), 0.0);
    EXPECT_LT(stored[0].metrics.at("mucosa_visualised"), 0.5);
    EXPECT_EQ(stored[1].id, left);
    EXPECT_EQ(stored[1].status, "completed");
    EXPECT_GT(stored[1].metrics.at("max_insertion"), 0.01);
    click(window, "logOut");
    ASSERT_EQ(screenName(window), "loginScreen");

    // The instructor: the cohort's sessions, and a replay of the student's first one.
    logIn(window, "ian", "ian-password-1");
    ASSERT_EQ(screenName(window), "instructorHome");
    EXPECT_TRUE(child<QLabel>(window, "whoIsLoggedIn")->text().contains("instructor"));
    child<QTabWidget>(window, "instructorTabs")->setCurrentIndex(2);
    chooseText(child<QComboBox>(window, "sessionTrainee"), QStringLiteral("ada"));
    auto* table = child<QTableView>(window, "sessionTable");
    ASSERT_SOON(table->model()->rowCount() == 2);
    int row = -1;
    for (int r = 0; r < table->model()->rowCount(); ++r) {
        row = table->model()->index(r, 0).data().toLongLong() == session ? r : row;
    }
    ASSERT_GE(row, 0) << "the student's session is listed";
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {},
                      table->visualRect(table->model()->index(row, 0)).center());
    screenshot(window, "instructor-sessions-in-window");
    click(window, "replayButton");
    ASSERT_EQ(screenName(window), "replayScreen");
    auto* replay = qobject_cast<app::ReplayScreen*>(window.currentScreen());
    ASSERT_NE(replay, nullptr);
    ASSERT_TRUE(replay->failure().isEmpty()) << replay->failure().toStdString();
    EXPECT_NEAR(replay->duration(), 3.0, 1e-6);
    EXPECT_NE(window.findChild<QWidget*>(QStringLiteral("replayShapeView")), nullptr)
        << "the instructor's replay always shows the scope-shape view";
    ASSERT_SOON(replay->shown()->state == app::Snapshot::State::Paused);
    // A quarter of the speed: the replay never runs ahead of a quarter of the wall clock.
    chooseText(child<QComboBox>(window, "replaySpeed"), QStringLiteral("0.25"));
    click(window, "replayPlay");
    ASSERT_SOON(replay->shown()->frame.time > 0.0);
    const double startedAt = replay->shown()->frame.time;
    QElapsedTimer wall;
    wall.start();
    QTest::qWait(1200);
    const double advanced = replay->shown()->frame.time - startedAt;
    const double seconds = static_cast<double>(wall.elapsed()) / 1000.0;
    EXPECT_GT(advanced, 0.0);
    EXPECT_LE(advanced, 0.25 * seconds + 0.05) << "simulated " << advanced << " s in " << seconds << " s";
    chooseText(child<QComboBox>(window, "replaySpeed"), QStringLiteral("1"));
    ASSERT_SOON(replay->shown()->frame.time > 1.0);
    click(window, "replayPause");
    ASSERT_SOON(replay->shown()->state == app::Snapshot::State::Paused);
    QTest::qWait(200);  // let both views draw the paused frame
    screenshot(window, "instructor-replay");
    click(window, "closeReplay");
    ASSERT_EQ(screenName(window), "instructorHome");
    click(window, "logOut");

    // The administrator: the student's signed PDF report and xAPI statements.
    logIn(window, "admin", "admin-password-1");
    ASSERT_EQ(screenName(window), "adminHome");
    child<QTabWidget>(window, "adminTabs")->setCurrentIndex(2);
    chooseText(child<QComboBox>(window, "certTrainee"), QStringLiteral("ada"));
    // A rule over the last 10 sessions says how many of them there are yet.
    auto* rules = child<QTableView>(window, "ruleTable");
    ASSERT_SOON(rules->model()->rowCount() > 0);
    QString perforation;
    for (int r = 0; r < rules->model()->rowCount(); ++r) {
        if (rules->model()->index(r, 1).data().toString().contains(QStringLiteral("perforation"))) {
            perforation = rules->model()->index(r, 3).data().toString();
        }
    }
    EXPECT_EQ(perforation, QStringLiteral("2 of the 10 it needs"));
    chooseText(child<QComboBox>(window, "exportScope"), QStringLiteral("trainee ada"));
    const auto exportAs = [&](const QString& format, const std::filesystem::path& file) {
        chooseText(child<QComboBox>(window, "exportFormat"), format);
        auto* path = child<QLineEdit>(window, "exportPath");
        path->clear();
        QTest::keyClicks(path, QString::fromStdString(file.string()));
        auto* button = child<QPushButton>(window, "exportButton");
        QTest::mouseClick(button, Qt::LeftButton);
        EXPECT_TRUE(waitUntil([&] { return button->isEnabled(); }));
        return child<QLabel>(window, "exportStatus")->text();
    };
    const std::filesystem::path pdf = fixture.dir / "ada-report.pdf";
    const QString pdfStatus = exportAs(QStringLiteral("PDF"), pdf);
    EXPECT_TRUE(pdfStatus.startsWith(QStringLiteral("Written:"))) << pdfStatus.toStdString();
    EXPECT_EQ(readFile(pdf).substr(0, 5), "%PDF-");
    screenshot(window, "admin-export-in-window");
    const std::filesystem::path xapi = fixture.dir / "ada-statements.json";
    const QString xapiStatus = exportAs(QStringLiteral("xAPI"), xapi);
    EXPECT_TRUE(xapiStatus.startsWith(QStringLiteral("Written:"))) << xapiStatus.toStdString();
    const std::string statements = readFile(xapi);
    EXPECT_NE(statements.find("\"actor\""), std::string::npos);
    EXPECT_NE(statements.find(std::to_string(session)), std::string::npos)
        << "the student's session is reported";
    click(window, "logOut");
    EXPECT_EQ(screenName(window), "loginScreen");
}

// The brief's other input devices, chosen as a person chooses them. The
// haptic device: the procedure waits on the port the brief names, and a
// Haptic Device Controller with the simulated device (a hand pushing in at
// 2 cm/s) connects to it and drives the session; the stored session names
// the device. The gamepad, where none is connected (as under Xvfb): a
// sentence saying so, and no session begun. Then the session's replay at 1x
// and at 4x: four times the simulated time per wall second, give or take a
// loaded machine.
TEST(Trainer, TheHapticDeviceDrivesASessionChosenInTheBriefAndItsReplayRunsFourTimesFaster)
{
    StudentRecords fixture;
    app::MainWindow window(fixture.database, fixture.records, fixture.dir.path());
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    logIn(window, "ada", "ada-password-1");
    ASSERT_EQ(screenName(window), "studentHome");
    const db::Actor ada = fixture.records.authenticate("ada", "ada-password-1");

    // The gamepad.
    click(window, "openBrief");
    ASSERT_EQ(screenName(window), "taskBrief");
    {
        QWidget& brief = *window.currentScreen();
        auto* choice = child<QComboBox>(brief, "driverChoice");
        choice->setCurrentIndex(choice->findData(static_cast<int>(app::Driver::Gamepad)));
        EXPECT_FALSE(child<QSpinBox>(brief, "hapticPort")->isEnabled()) << "the port is the haptic device's";
        click(brief, "startProcedure");
    }
    if (auto* procedure = qobject_cast<app::ProcedureScreen*>(window.currentScreen())) {
        // A gamepad is connected to this machine: it drives the session.
        procedure->endAndStore();
        ASSERT_SOON(screenName(window) == QStringLiteral("resultsScreen"));
        EXPECT_TRUE(fixture.records.sessions(ada, "ada").back().device.starts_with("gamepad:"));
        click(window, "backToCurriculum");
    } else {
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("errorMessage"));
        ASSERT_NE(box, nullptr) << "the missing gamepad is said";
        EXPECT_TRUE(box->text().contains(QStringLiteral("no game controller is connected")))
            << box->text().toStdString();
        screenshot(*box, "gamepad-missing");
        box->accept();
        EXPECT_EQ(screenName(window), "taskBrief") << "the brief stays, with its choices";
        EXPECT_TRUE(fixture.records.sessions(ada, "ada").empty());
        click(window, "backToCurriculum");
    }

    // The haptic device.
    ASSERT_EQ(screenName(window), "studentHome");
    click(window, "openBrief");
    ASSERT_EQ(screenName(window), "taskBrief");
    const int port = 20000 + static_cast<int>(::getpid() % 20000);
    QWidget& brief = *window.currentScreen();
    auto* choice = child<QComboBox>(brief, "driverChoice");
    choice->setCurrentIndex(choice->findData(static_cast<int>(app::Driver::Haptic)));
    EXPECT_TRUE(child<QSpinBox>(brief, "hapticPort")->isEnabled());
    child<QSpinBox>(brief, "hapticPort")->setValue(port);
    constexpr double kRunLength = 4.0;  // s simulated
    child<QDoubleSpinBox>(brief, "timeLimit")->setValue(kRunLength);
    click(brief, "startProcedure");
    auto* procedure = qobject_cast<app::ProcedureScreen*>(window.currentScreen());
    ASSERT_NE(procedure, nullptr);
    devices::SimulatedDevice device([](double t) {
        procedure::InputSample s;
        s.insertion = 0.02 * t;
        return s;
    });
    devices::HdcController hdc(device, devices::HapticParameters{}, "127.0.0.1", port);
    std::jthread servo([&](std::stop_token stop) { hdc.run(stop, 120.0); });
    ASSERT_SOON(hdc.everConnected());
    ASSERT_SOON(procedure->shownInsertion() > 0.01);
    screenshot(window, "procedure-haptic");
    ASSERT_SOON(screenName(window) == QStringLiteral("resultsScreen"));
    servo.request_stop();
    servo.join();
    EXPECT_GT(hdc.statistics().loadsReceived, 1000) << "the handle force came back to the device";
    const std::vector<db::SessionRow> stored = fixture.records.sessions(ada, "ada");
    ASSERT_FALSE(stored.empty());
    EXPECT_EQ(stored.back().device, "hdc:" + std::to_string(port));
    EXPECT_GT(stored.back().metrics.at("max_insertion"), 0.03) << "the hand pushed the scope in";

    // Its replay at 1x, then at 4x.
    click(window, "replayButton");
    auto* replay = qobject_cast<app::ReplayScreen*>(window.currentScreen());
    ASSERT_NE(replay, nullptr);
    ASSERT_SOON(replay->shown()->state == app::Snapshot::State::Paused);
    bool connected = false;
    for (const auto& e : replay->recording().events) {
        connected = connected || (e.kind == procedure::EventKind::DeviceConnected && e.detail == "simulated");
    }
    EXPECT_TRUE(connected) << "the recording says which device drove the session";
    auto played = [&](double speed) {
        auto* box = child<QComboBox>(window, "replaySpeed");
        box->setCurrentIndex(box->findData(speed));
        const double from = replay->shown()->frame.time;
        QElapsedTimer wall;
        wall.start();
        click(window, "replayPlay");
        QTest::qWait(600);
        click(window, "replayPause");
        const double seconds = static_cast<double>(wall.elapsed()) / 1000.0;
        EXPECT_TRUE(waitUntil([&] { return replay->shown()->state == app::Snapshot::State::Paused; }));
        return (replay->shown()->frame.time - from) / seconds;
    };
    const double normal = played(1.0);
    const double fast = played(4.0);
    std::cout << "replay: " << normal << " s simulated per wall second at 1x, " << fast << " at 4x\n";
    EXPECT_GT(normal, 0.3);
    EXPECT_LT(normal, 1.2) << "1x never runs ahead of the wall clock";
    EXPECT_GT(fast, 2.0 * normal) << "4x: several times faster than 1x";
    EXPECT_LT(replay->shown()->frame.time, kRunLength);
}

TEST(HeadsUpDisplay, TheGaugesFollowEverySnapshotAndTheWordsTenTimesASecond)
{
    app::HeadsUpDisplay hud(15.0);
    app::Snapshot snapshot;
    snapshot.state = app::Snapshot::State::Running;
    snapshot.frame.input.insertion = 0.10;
    snapshot.frame.handleForce = 2.0;
    hud.showSnapshot(snapshot, 30.0, 60.0);
    auto* depth = child<QLabel>(hud, "insertionDepth");
    auto* gauge = child<QProgressBar>(hud, "handleForceGauge");
    EXPECT_EQ(depth->text(), QStringLiteral("10.0 cm"));
    EXPECT_EQ(gauge->value(), 20);

    // The next snapshot at once: the gauge moves, the words wait.
    QElapsedTimer since;
    since.start();
    snapshot.frame.input.insertion = 0.11;
    snapshot.frame.handleForce = 4.0;
    hud.showSnapshot(snapshot, 30.0, 60.0);
    EXPECT_EQ(gauge->value(), 40);
    if (since.elapsed() < 1000 / app::HeadsUpDisplay::kTextRate) {
        EXPECT_EQ(depth->text(), QStringLiteral("10.0 cm"));
    }
    // A tenth of a second on, the words follow.
    QTest::qWait(1000 / app::HeadsUpDisplay::kTextRate + 10);
    hud.showSnapshot(snapshot, 30.0, 60.0);
    EXPECT_EQ(depth->text(), QStringLiteral("11.0 cm"));
    // A paused procedure shows its last figures at once.
    snapshot.state = app::Snapshot::State::Paused;
    snapshot.frame.input.insertion = 0.12;
    hud.showSnapshot(snapshot, 30.0, 60.0);
    EXPECT_EQ(depth->text(), QStringLiteral("12.0 cm"));
    EXPECT_TRUE(child<QLabel>(hud, "rates")->text().endsWith(QStringLiteral("paused")));
}

/// Half red, half blue (left | right), cleared with OpenGL into whatever
/// framebuffer the widget gives it.
class HalvesWidget final : public app::OffscreenGlWidget {
public:
    HalvesWidget() { setFixedSize(200, 100); }
    void drawAt(double scale) { setRenderScale(scale); }
    QSize drawnSize;

protected:
    void initializeGL() override {}
    bool paintGL() override
    {
        drawnSize = framebufferSize();
        QOpenGLFunctions* gl = QOpenGLContext::currentContext()->functions();
        const int w = drawnSize.width();
        const int h = drawnSize.height();
        gl->glViewport(0, 0, w, h);
        gl->glEnable(GL_SCISSOR_TEST);
        gl->glScissor(0, 0, w / 2, h);
        gl->glClearColor(1.0F, 0.0F, 0.0F, 1.0F);
        gl->glClear(GL_COLOR_BUFFER_BIT);
        gl->glScissor(w / 2, 0, w - w / 2, h);
        gl->glClearColor(0.0F, 0.0F, 1.0F, 1.0F);
        gl->glClear(GL_COLOR_BUFFER_BIT);
        gl->glDisable(GL_SCISSOR_TEST);
        return true;
    }
};

TEST(OffscreenView, AViewDrawnAtASmallerScaleStillFillsItsWidget)
{
    HalvesWidget widget;
    for (const double scale : {1.0, 0.5}) {
        widget.drawAt(scale);
        const QImage shown = widget.grab().toImage();
        EXPECT_EQ(widget.drawnSize, QSize(static_cast<int>(200 * scale), static_cast<int>(100 * scale)));
        ASSERT_EQ(shown.size(), QSize(200, 100));
        // Every corner of the widget, and the middle of each half, shows its half's colour.
        for (const int y : {2, 50, 97}) {
            for (const int x : {2, 50}) {
                EXPECT_EQ(shown.pixelColor(x, y), QColor(Qt::red)) << scale << " at " << x << ", " << y;
            }
            for (const int x : {150, 197}) {
                EXPECT_EQ(shown.pixelColor(x, y), QColor(Qt::blue)) << scale << " at " << x << ", " << y;
            }
        }
    }
}

TEST(Trainer, TheShapeViewIsShownOnlyWhenTheTaskAllowsIt)
{
    StudentRecords fixture;
    const db::Actor ada = fixture.records.authenticate("ada", "ada-password-1");
    app::AppContext context{fixture.database, fixture.records, ada, fixture.dir.path()};
    const curricula::Curriculum curriculum = app::loadCurriculum(context);
    const std::shared_ptr<const app::ProcedureScene> scene = app::buildScene(std::nullopt);
    app::ProcedureOptions options;
    options.driver = app::Driver::Autopilot;
    options.timeLimit = 0.5;
    for (const char* id : {"navigation-straight", "complex-anatomy"}) {
        const curricula::Task* task = curriculum.find(id);
        ASSERT_NE(task, nullptr) << id;
        app::ProcedureScreen screen(context, *task, scene, std::nullopt, options);
        const bool shown = screen.findChild<QWidget*>(QStringLiteral("shapeView")) != nullptr;
        EXPECT_EQ(shown, task->shapeView) << id;
        screen.endAndStore();
    }
    EXPECT_FALSE(curriculum.find("complex-anatomy")->shapeView)
        << "the assessment of difficult anatomy hides it";
}

}  // namespace
